#include "tools/eval/GaitEvaluation.h"

#include "core/io/CsvReader.h"
#include "core/io/Importer.h"
#include "core/model/Project.h"
#include "plugins/events/GaitEventsProcessor.h"
#include "plugins/events/MediolateralAxis.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace athlos::events {

Expected<std::unique_ptr<Project>> importGaitmapWalk(const QString& dir, const QString& imuCsv) {
    auto project = Project::create(dir + QStringLiteral("/p.athlos"));
    if (!project) return makeError(QStringLiteral("cannot create a project in %1").arg(dir));
    ImportOptions options;
    options.format = QStringLiteral("gaitmap");
    options.target = QStringLiteral("walk");
    auto imported = importFile(imuCsv, options);
    if (!imported) return imported.error();
    if (Status s = applyImport(*project, std::move(imported).value(), false); !s.ok()) return s.error();
    return project;
}

Expected<std::vector<ReferenceStride>> readStrideBorders(const QString& path, double rate) {
    if (!(rate > 0.0)) return makeError(QStringLiteral("%1: sampling rate %2 Hz must be positive").arg(path).arg(rate));
    MappedFile file;
    if (Status opened = file.open(path); !opened) return opened.error();
    CsvReader reader(file.begin(), file.end());
    QStringList header;
    if (!reader.readHeader(header)) return makeError(QStringLiteral("%1: empty file (no header row)").arg(path));
    const int foot = int(header.indexOf(QStringLiteral("foot"))), start = int(header.indexOf(QStringLiteral("start"))),
              end = int(header.indexOf(QStringLiteral("end")));
    if (foot < 0 || start < 0 || end < 0)
        return makeError(QStringLiteral("%1:1: expected columns foot, start, end (found: %2)")
                             .arg(path, header.join(QStringLiteral(", "))));
    std::vector<ReferenceStride> out;
    std::string cell;
    while (reader.nextRecord()) {
        QString footName;
        double s = 0.0, e = 0.0;
        for (int i = 0; i < int(header.size()); ++i) {
            const auto missing = [&] {
                return makeError(QStringLiteral("%1:%2: %3 fields, the header has %4")
                                     .arg(path)
                                     .arg(reader.line())
                                     .arg(reader.fieldsOnLine())
                                     .arg(header.size()));
            };
            if (i != start && i != end) {
                if (!reader.text(cell)) return missing();
                if (i == foot) footName = QString::fromStdString(cell);
                continue;
            }
            double x = 0.0;
            const CsvReader::Field f = reader.number(x);
            if (f == CsvReader::Field::Missing) return missing();
            if (f != CsvReader::Field::Number) {
                const auto raw = reader.lastField();
                return makeError(
                    QStringLiteral("%1:%2:%3: %4 '%5' is not a number")
                        .arg(path)
                        .arg(reader.line())
                        .arg(i + 1)
                        .arg(i == start ? u"start" : u"end", QString::fromUtf8(raw.data(), qsizetype(raw.size()))));
            }
            (i == start ? s : e) = x;
        }
        while (reader.text(cell)) {}
        const long long line = reader.line();
        reader.finishRecord();
        if (e <= s)
            return makeError(QStringLiteral("%1:%2:%3: end %4 is not after start %5")
                                 .arg(path)
                                 .arg(line)
                                 .arg(end + 1)
                                 .arg(e)
                                 .arg(s));
        out.push_back({footName, s / rate, e / rate});
    }
    return out;
}

void IcScore::add(const IcScore& o) {
    referenceIcs += o.referenceIcs;
    matchedIcs += o.matchedIcs;
    falseIcs += o.falseIcs;
    referenceStrides += o.referenceStrides;
    matchedStrides += o.matchedStrides;
    errorsMs.insert(errorsMs.end(), o.errorsMs.begin(), o.errorsMs.end());
    const double n = double(errorsMs.size());
    meanErrorMs = n > 0 ? std::accumulate(errorsMs.begin(), errorsMs.end(), 0.0) / n : 0.0;
    double ss = 0.0;
    for (double e : errorsMs) ss += (e - meanErrorMs) * (e - meanErrorMs);
    sdErrorMs = n > 1 ? std::sqrt(ss / (n - 1.0)) : 0.0;
}

IcScore scoreInitialContacts(const std::vector<ReferenceStride>& reference, const std::vector<double>& detectedIcs,
                             const std::vector<std::pair<double, double>>& detectedStrides, double tol) {
    IcScore score;
    // Distinct reference ICs and the bouts (chains of strides sharing borders).
    std::vector<double> ics;
    std::vector<std::pair<double, double>> bouts;
    auto strides = reference;
    std::sort(strides.begin(), strides.end(), [](const auto& a, const auto& b) { return a.tStart < b.tStart; });
    for (const auto& s : strides) {
        ics.push_back(s.tStart);
        ics.push_back(s.tEnd);
        if (!bouts.empty() && std::abs(bouts.back().second - s.tStart) < 1e-9)
            bouts.back().second = s.tEnd;
        else
            bouts.push_back({s.tStart, s.tEnd});
    }
    std::sort(ics.begin(), ics.end());
    ics.erase(std::unique(ics.begin(), ics.end(), [](double a, double b) { return std::abs(a - b) < 1e-9; }),
              ics.end());
    score.referenceIcs = int(ics.size());

    // Greedy one-to-one matching, nearest first (the tolerance is far below half a stride, so at
    // most one reference IC is in reach of a detection anyway).
    struct Pair {
        double d;
        std::size_t r, k;
    };
    std::vector<Pair> pairs;
    for (std::size_t r = 0; r < ics.size(); ++r)
        for (std::size_t k = 0; k < detectedIcs.size(); ++k)
            if (std::abs(detectedIcs[k] - ics[r]) <= tol) pairs.push_back({std::abs(detectedIcs[k] - ics[r]), r, k});
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.d < b.d; });
    std::vector<bool> refUsed(ics.size()), detUsed(detectedIcs.size());
    for (const auto& p : pairs) {
        if (refUsed[p.r] || detUsed[p.k]) continue;
        refUsed[p.r] = detUsed[p.k] = true;
        score.errorsMs.push_back(1000.0 * (detectedIcs[p.k] - ics[p.r]));
    }
    score.matchedIcs = int(score.errorsMs.size());
    for (std::size_t k = 0; k < detectedIcs.size(); ++k) {
        if (detUsed[k]) continue;
        for (const auto& b : bouts)
            if (detectedIcs[k] >= b.first - tol && detectedIcs[k] <= b.second + tol) {
                ++score.falseIcs;
                break;
            }
    }
    score.referenceStrides = int(strides.size());
    for (const auto& s : strides)
        for (const auto& d : detectedStrides)
            if (std::abs(d.first - s.tStart) <= tol && std::abs(d.second - s.tEnd) <= tol) {
                ++score.matchedStrides;
                break;
            }
    IcScore pooled;
    pooled.add(score);  // fills mean and SD
    return pooled;
}

Expected<std::vector<FootDetection>> detectGaitmapFile(const QString& imuCsv, const GaitEventDetector::Params& params) {
    ImportOptions options;
    options.format = QStringLiteral("gaitmap");
    options.target = QStringLiteral("walk");
    auto imported = importFile(imuCsv, options);
    if (!imported) return imported.error();
    std::vector<FootDetection> out;
    for (const auto& item : imported->items) {
        const Stream* s = std::get_if<Stream>(&item.item);
        if (!s) continue;
        const int gyr = s->info().columnIndex(QStringLiteral("gyr_x"));
        auto data = s->data();
        if (!data) return data.error();
        if (gyr < 0) return makeError(QStringLiteral("%1: stream '%2' has no gyr_x").arg(imuCsv, s->name()));
        const StreamData& d = **data;
        FootDetection f;
        f.foot = GaitEventsProcessor::footOf(s->info());
        f.rate = 1.0 / d.medianInterval();
        const double* g = d.values.data() + gyr;
        // As the processor's default ml_axis = auto: the principal axis of the angular velocity.
        const Eigen::Vector3d axis =
            mediolateralAxis(QStringLiteral("auto"), g, d.rows(), std::size_t(d.columns))->axis;
        f.swingSign = GaitEventDetector::swingSign(d.t.data(), g, d.rows(), std::size_t(d.columns), axis);
        GaitEventDetector detector(params, f.swingSign);
        detector.updateBatch(d.t.data(), g, d.rows(), std::size_t(d.columns), axis);
        for (const auto& e : detector.events())
            if (e.type == GaitEventType::InitialContact) f.ics.push_back(e.t);
        f.strides = detector.strides();
        out.push_back(std::move(f));
    }
    return out;
}

Expected<GaitValidation> validateGaitmap(const QString& imuCsv, const QString& bordersCsv, double tol,
                                         const GaitEventDetector::Params& params) {
    auto feet = detectGaitmapFile(imuCsv, params);
    if (!feet) return feet.error();
    if (feet->empty()) return makeError(QStringLiteral("%1: no IMU streams").arg(imuCsv));
    auto reference = readStrideBorders(bordersCsv, feet->front().rate);
    if (!reference) return reference.error();
    GaitValidation v;
    for (const auto& f : *feet) {
        std::vector<ReferenceStride> ref;
        for (const auto& r : *reference)
            if (r.foot == f.foot) ref.push_back(r);
        std::vector<std::pair<double, double>> strides;
        for (const auto& s : f.strides) strides.push_back({s.tStart, s.tEnd});
        const IcScore score = scoreInitialContacts(ref, f.ics, strides, tol);
        (f.foot == QLatin1String("left") ? v.left : v.right) = score;
        v.total.add(score);
    }
    return v;
}

}  // namespace athlos::events
