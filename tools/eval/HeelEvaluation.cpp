#include "tools/eval/HeelEvaluation.h"

#include "core/io/CsvReader.h"
#include "core/model/Project.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/events/GaitParametersProcessor.h"
#include "plugins/events/GaitSummary.h"
#include "plugins/events/GaitSummaryProcessor.h"

#include <QTemporaryDir>
#include <algorithm>
#include <cmath>

namespace athlos::events {

Expected<HeelTrack> readGaitmapHeel(const QString& path, double rate) {
    MappedFile file;
    if (Status opened = file.open(path); !opened) return opened.error();
    CsvReader reader(file.begin(), file.end());
    QStringList markers, axes;
    if (!reader.readHeader(markers) || !reader.readHeader(axes))
        return makeError(QStringLiteral("%1: expected two header rows (marker, axis)").arg(path));
    const auto column = [&](const char* marker, const char* axis) {
        for (int i = 0; i < markers.size() && i < axes.size(); ++i)
            if (markers[i] == QLatin1String(marker) && axes[i] == QLatin1String(axis)) return i;
        return -1;
    };
    const int cols[4] = {column("L_FCC", "x"), column("L_FCC", "y"), column("R_FCC", "x"), column("R_FCC", "y")};
    if (*std::min_element(cols, cols + 4) < 0)
        return makeError(QStringLiteral("%1:1-2: expected the heel markers L_FCC and R_FCC with x and y").arg(path));
    const int last = *std::max_element(cols, cols + 4);
    HeelTrack track;
    track.rate = rate;
    std::string rest;
    while (reader.nextRecord()) {
        // A marker the cameras lost is an empty cell (NaN): the strides it touches are not scored.
        double v[4];
        for (int i = 0; i <= last; ++i) {
            double x = 0.0;
            const CsvReader::Field f = reader.number(x);
            if (f == CsvReader::Field::Missing)
                return makeError(QStringLiteral("%1:%2: %3 fields, the heel markers need %4")
                                     .arg(path)
                                     .arg(reader.line())
                                     .arg(reader.fieldsOnLine())
                                     .arg(last + 1));
            if (f == CsvReader::Field::Invalid)
                return makeError(
                    QStringLiteral("%1:%2:%3: '%4' is not a number")
                        .arg(path)
                        .arg(reader.line())
                        .arg(i + 1)
                        .arg(QString::fromUtf8(reader.lastField().data(), qsizetype(reader.lastField().size()))));
            for (int j = 0; j < 4; ++j)
                if (cols[j] == i) v[j] = x / 1000.0;  // mm → m
        }
        while (reader.text(rest)) {}
        reader.finishRecord();
        track.left.emplace_back(v[0], v[1]);
        track.right.emplace_back(v[2], v[3]);
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
// gait-summary on walk/left-foot-strides and walk/right-foot-strides; then the same summary (summariseGait,
// default parameters, so the same steady strides) of the heel's displacement between each stride's own
// start and end, with NaN where the marker was lost.
Expected<std::vector<SteadyLength>> steadyAgainstHeel(Project& walk, const HeelTrack& heel) {
    const GaitSummaryProcessor summary;
    const QStringList tables{QStringLiteral("walk/left-foot-strides"), QStringLiteral("walk/right-foot-strides")};
    auto run = runProcessor(walk, summary, RunRequest{summary.id(), tables, QStringLiteral("walk/summary"), {}});
    if (!run) return run.error();
    std::vector<FootStrides> heels;
    for (int f = 0; f < 2; ++f) {
        const Table* t = walk.table(tables[f]);
        FootStrides h;
        h.foot = f == 0 ? QStringLiteral("left") : QStringLiteral("right");
        h.start = t->column(QStringLiteral("start"))->numbers;
        h.end = t->column(QStringLiteral("end"))->numbers;
        h.turn = t->column(QStringLiteral("turning_angle"))->numbers;
        h.names = {QStringLiteral("stride_length")};
        h.units = {QStringLiteral("m")};
        const std::vector<Eigen::Vector2d>& track = heel.of(h.foot);
        const auto at = [&](double time) {
            return track[std::size_t(std::clamp(std::lround(time * heel.rate), 0L, long(track.size()) - 1))];
        };
        h.parameters.emplace_back();
        for (std::size_t i = 0; i < h.start.size(); ++i)
            h.parameters[0].push_back((at(h.end[i]) - at(h.start[i])).norm());
        heels.push_back(std::move(h));
    }
    const GaitSummary truth = summariseGait(GaitSummaryParams{}, heels);
    const Table* s = walk.table(QStringLiteral("walk/summary"));
    const TableColumn *mean = s->column(QStringLiteral("stride_length_mean")),
                      *cv = s->column(QStringLiteral("stride_length_cv")),
                      *si = s->column(QStringLiteral("stride_length_si")), *used = s->column(QStringLiteral("used"));
    std::vector<SteadyLength> out(3);
    for (std::size_t r = 0; r < 3; ++r) {
        const FootSummary& h = r < 2 ? truth.feet[r] : truth.pooled;
        SteadyLength& row = out[r];
        row.foot = s->column(QStringLiteral("foot"))->texts[qsizetype(r)];
        row.used = int(used->numbers[r]);
        row.estimatedMean = mean->numbers[r];
        row.estimatedCv = cv->numbers[r];
        row.heelMean = h.stats[0].mean;
        row.heelCv = h.stats[0].cv;
    }
    out[2].estimatedSi = si->numbers[2];
    out[2].heelSi = truth.symmetry[0];
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
