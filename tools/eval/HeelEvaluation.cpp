#include "tools/eval/HeelEvaluation.h"

#include "core/model/Project.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/events/GaitParametersProcessor.h"
#include "plugins/events/GaitSummary.h"
#include "plugins/events/GaitSummaryProcessor.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <tuple>

namespace athlos::events {

Expected<HeelTrack> readGaitmapHeel(const QString& path, double rate) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        return makeError(QStringLiteral("%1: %2").arg(path, file.errorString()));
    QTextStream in(&file);
    const QStringList markers = in.readLine().trimmed().split(QLatin1Char(','));
    const QStringList axes = in.readLine().trimmed().split(QLatin1Char(','));
    const auto column = [&](const char* marker, const char* axis) {
        for (int i = 0; i < markers.size() && i < axes.size(); ++i)
            if (markers[i] == QLatin1String(marker) && axes[i] == QLatin1String(axis)) return i;
        return -1;
    };
    const int lx = column("L_FCC", "x"), ly = column("L_FCC", "y"), rx = column("R_FCC", "x"),
              ry = column("R_FCC", "y");
    if (lx < 0 || ly < 0 || rx < 0 || ry < 0)
        return makeError(QStringLiteral("%1:1-2: expected the heel markers L_FCC and R_FCC with x and y").arg(path));
    HeelTrack track;
    track.rate = rate;
    for (int line = 3; !in.atEnd(); ++line) {
        const QString text = in.readLine().trimmed();
        if (text.isEmpty()) continue;
        const QStringList f = text.split(QLatin1Char(','));
        double v[4];
        const int cols[4] = {lx, ly, rx, ry};
        for (int j = 0; j < 4; ++j) {
            bool ok = cols[j] < f.size();
            v[j] = ok ? f[cols[j]].toDouble(&ok) : 0.0;
            if (!ok)
                return makeError(QStringLiteral("%1:%2:%3: '%4' is not a number")
                                     .arg(path)
                                     .arg(line)
                                     .arg(cols[j] + 1)
                                     .arg(cols[j] < f.size() ? f[cols[j]] : QString()));
        }
        track.left.emplace_back(v[0] / 1000.0, v[1] / 1000.0);
        track.right.emplace_back(v[2] / 1000.0, v[3] / 1000.0);
    }
    return track;
}

void scoreAgainstHeel(const std::vector<ReferenceStride>& reference, const std::vector<Eigen::Vector2d>& heel,
                      double heelRate, const std::vector<EstimatedStride>& strides, HeelScore& score, double maxTurn,
                      double minOwnLength) {
    // Horizontal heel displacement between two times, NaN outside the track.
    const auto heelLength = [&](double t0, double t1) {
        const long a = std::lround(t0 * heelRate), b = std::lround(t1 * heelRate), n = long(heel.size());
        if (a < 0 || b < 0 || a >= n || b >= n) return std::nan("");
        return (heel[std::size_t(b)] - heel[std::size_t(a)]).norm();
    };
    for (const ReferenceStride& ref : reference) {
        ++score.reference;
        const double truth = heelLength(ref.tStart, ref.tEnd);
        int hits = 0;
        const EstimatedStride* hit = nullptr;
        for (const EstimatedStride& s : strides)
            if (const double mid = 0.5 * (s.tStart + s.tEnd); mid >= ref.tStart && mid <= ref.tEnd) {
                ++hits;
                hit = &s;
            }
        if (hits != 1) continue;
        ++score.matchedOnce;
        if (!(truth > 0.0)) continue;
        const double e = hit->length / truth - 1.0;
        score.error.push_back(e);
        if (std::abs(hit->turningAngle) < maxTurn) score.straightError.push_back(e);
    }
    for (const EstimatedStride& s : strides)
        if (const double truth = heelLength(s.tStart, s.tEnd); truth > minOwnLength)
            score.ownError.push_back(s.length / truth - 1.0);
}

namespace {
// Mean and coefficient of variation (sample SD / mean, %) of the values where use is true.
std::pair<double, double> meanCv(const std::vector<double>& v, const std::vector<bool>& use) {
    double sum = 0.0, ss = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (use[i]) sum += v[i], ++n;
    const double mean = sum / n;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (use[i]) ss += (v[i] - mean) * (v[i] - mean);
    return {mean, 100.0 * std::sqrt(ss / (n - 1)) / mean};
}

// gait-summary on walk/left-foot-strides and walk/right-foot-strides, and the heel over the same strides.
Expected<std::vector<SteadyLength>> steadyAgainstHeel(Project& walk, const HeelTrack& heel) {
    const GaitSummaryProcessor summary;
    const QStringList tables{QStringLiteral("walk/left-foot-strides"), QStringLiteral("walk/right-foot-strides")};
    auto run = runProcessor(walk, summary, RunRequest{summary.id(), tables, QStringLiteral("walk/summary"), {}});
    if (!run) return run.error();
    const Table* s = walk.table(QStringLiteral("walk/summary"));
    const TableColumn *mean = s->column(QStringLiteral("stride_length_mean")),
                      *cv = s->column(QStringLiteral("stride_length_cv")),
                      *si = s->column(QStringLiteral("stride_length_si")), *used = s->column(QStringLiteral("used"));
    std::vector<SteadyLength> out(3);
    std::vector<double> allHeel;
    std::vector<bool> allUse;
    for (int f = 0; f < 2; ++f) {
        const Table* t = walk.table(tables[f]);
        FootStrides strides;
        strides.start = t->column(QStringLiteral("start"))->numbers;
        strides.end = t->column(QStringLiteral("end"))->numbers;
        strides.turn = t->column(QStringLiteral("turning_angle"))->numbers;
        const std::vector<bool> use = steadyStrides(GaitSummaryParams{}, strides);
        const std::vector<Eigen::Vector2d>& track = heel.of(f == 0 ? QStringLiteral("left") : QStringLiteral("right"));
        std::vector<double> lengths;
        for (std::size_t i = 0; i < strides.start.size(); ++i) {
            const auto at = [&](double time) {
                return track[std::size_t(std::clamp(std::lround(time * heel.rate), 0L, long(track.size()) - 1))];
            };
            lengths.push_back((at(strides.end[i]) - at(strides.start[i])).norm());
        }
        allHeel.insert(allHeel.end(), lengths.begin(), lengths.end());
        allUse.insert(allUse.end(), use.begin(), use.end());
        SteadyLength& r = out[std::size_t(f)];
        r.foot = s->column(QStringLiteral("foot"))->texts[f];
        r.used = int(used->numbers[std::size_t(f)]);
        r.estimatedMean = mean->numbers[std::size_t(f)];
        r.estimatedCv = cv->numbers[std::size_t(f)];
        std::tie(r.heelMean, r.heelCv) = meanCv(lengths, use);
    }
    SteadyLength& both = out[2];
    both.foot = QStringLiteral("both");
    both.used = int(used->numbers[2]);
    both.estimatedMean = mean->numbers[2];
    both.estimatedCv = cv->numbers[2];
    both.estimatedSi = si->numbers[2];
    std::tie(both.heelMean, both.heelCv) = meanCv(allHeel, allUse);
    both.heelSi = 200.0 * std::abs(out[0].heelMean - out[1].heelMean) / (out[0].heelMean + out[1].heelMean);
    return out;
}
}  // namespace

Expected<HeelScore> evaluateGaitParametersAgainstHeel(const QString& imuCsv, const QString& mocapCsv,
                                                      const QString& bordersCsv, const QVariantMap& parameters) {
    auto heel = readGaitmapHeel(mocapCsv);
    if (!heel) return heel.error();
    QTemporaryDir dir;
    if (!dir.isValid()) return makeError(QStringLiteral("cannot create a temporary folder"));
    auto project = importGaitmapWalk(dir.path(), imuCsv);
    if (!project) return project.error();
    Project& walk = **project;
    const GaitParametersProcessor gait;
    HeelScore score;
    for (const QString& foot : {QStringLiteral("left"), QStringLiteral("right")}) {
        const QString imu = QStringLiteral("walk/%1-foot").arg(foot), out = imu + QStringLiteral("-strides");
        auto run = runProcessor(walk, gait, RunRequest{gait.id(), {imu}, out, parameters});
        if (!run) return run.error();
        auto data = walk.stream(imu)->data();
        if (!data) return data.error();
        auto reference = readStrideBorders(bordersCsv, 1.0 / (*data)->medianInterval());
        if (!reference) return reference.error();
        std::vector<ReferenceStride> ofFoot;
        for (const ReferenceStride& r : *reference)
            if (r.foot == foot) ofFoot.push_back(r);
        const Table* table = walk.table(out);
        if (!table) return makeError(QStringLiteral("%1: no stride table").arg(imu));
        const auto& s0 = table->column(QStringLiteral("start"))->numbers;
        const auto& s1 = table->column(QStringLiteral("end"))->numbers;
        const auto& len = table->column(QStringLiteral("stride_length"))->numbers;
        const auto& turn = table->column(QStringLiteral("turning_angle"))->numbers;
        std::vector<EstimatedStride> strides;
        for (std::size_t i = 0; i < s0.size(); ++i) strides.push_back({s0[i], s1[i], len[i], turn[i]});
        scoreAgainstHeel(ofFoot, heel->of(foot), heel->rate, strides, score);
    }
    auto steady = steadyAgainstHeel(walk, *heel);
    if (!steady) return steady.error();
    score.steady = std::move(*steady);
    return score;
}

}  // namespace athlos::events
