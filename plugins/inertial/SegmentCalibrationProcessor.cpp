#include "plugins/inertial/SegmentCalibrationProcessor.h"

#include "core/processing/RowRange.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/ImuColumns.h"
#include "plugins/inertial/SegmentCalibration.h"
#include "plugins/inertial/SegmentMounts.h"

#include <QRegularExpression>
#include <cmath>
#include <numbers>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "SegmentCalibrationProcessor"};

// Sign of each segment's first turn about its right-pointing Z axis when a squat starts.
Expected<double> firstRotation(const QString& segment) {
    if (segment == QLatin1String("thigh")) return 1.0;
    if (segment == QLatin1String("shank") || segment == QLatin1String("pelvis") || segment == QLatin1String("thorax"))
        return -1.0;
    return makeError(
        QStringLiteral("segments: '%1' has no known squat rotation; use thigh, shank, pelvis or thorax").arg(segment));
}

Expected<QStringList> segmentNames(const RunContext& c) {
    static const QRegularExpression separators(QStringLiteral("[,;\\s]+"));
    const QStringList names =
        (c.has(QStringLiteral("segments")) ? c.text(QStringLiteral("segments")) : QStringLiteral("thigh,shank,pelvis"))
            .split(separators, Qt::SkipEmptyParts);
    int inputs = 0;
    for (int i = 0; i < c.inputCount(); ++i) inputs += c.stream(i) ? 1 : 0;
    if (names.size() < inputs)
        return makeError(QStringLiteral("segments: %1 name(s) for %2 IMU stream(s); name every input")
                             .arg(names.size())
                             .arg(inputs));
    for (const QString& n : names)
        if (auto s = firstRotation(n); !s) return s.error();
    return names;
}

struct Window {
    double begin = 0.0, end = 0.0;
};

Expected<Window> window(const RunContext& c, const char* begin, const char* end) {
    Window w{c.number(QLatin1String(begin)), c.number(QLatin1String(end))};
    if (!(w.end > w.begin))
        return makeError(QStringLiteral("%1: %2 s must be after %3 (%4 s)")
                             .arg(QLatin1String(end))
                             .arg(w.end)
                             .arg(QLatin1String(begin))
                             .arg(w.begin));
    return w;
}
}  // namespace

QString SegmentCalibrationProcessor::name() const { return tr("Segment calibration (functional)"); }

QString SegmentCalibrationProcessor::description() const {
    return tr(
        "Sensor-to-segment mounts from a functional calibration: standing upright still (gravity gives the superior "
        "axis) and slow squats (the principal axis of the angular velocity gives the medio-lateral axis), combined "
        "by cross products. Writes a segment-calibration table (segment, qw..qz) for joint-angles.");
}

ParameterSpecs SegmentCalibrationProcessor::parameters() const {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    return {
        ParameterSpec::text(QStringLiteral("segments"), QStringLiteral("thigh,shank,pelvis"),
                            tr("Segment of each input IMU, in input order (thigh, shank, pelvis or thorax).")),
        ParameterSpec::number(QStringLiteral("static_begin"), nan, -inf, inf, QStringLiteral("s"),
                              tr("Start of the upright standing window.")),
        ParameterSpec::number(QStringLiteral("static_end"), nan, -inf, inf, QStringLiteral("s"),
                              tr("End of the upright standing window.")),
        ParameterSpec::number(QStringLiteral("movement_begin"), nan, -inf, inf, QStringLiteral("s"),
                              tr("Start of the squats.")),
        ParameterSpec::number(QStringLiteral("movement_end"), nan, -inf, inf, QStringLiteral("s"),
                              tr("End of the squats.")),
    };
}

QList<InputSpec> SegmentCalibrationProcessor::inputs() const {
    return {
        InputSpec{
            QStringLiteral("imu"), {QStringLiteral("imu")}, false, false, tr("IMU of the first segment (acc, gyr).")},
        InputSpec{QStringLiteral("imu2"), {QStringLiteral("imu")}, false, true, tr("IMU of the second segment.")},
        InputSpec{QStringLiteral("imu3"), {QStringLiteral("imu")}, false, true, tr("IMU of the third segment.")}};
}

QList<OutputSpec> SegmentCalibrationProcessor::outputs() const {
    return {OutputSpec{kSegmentCalibrationKind, true, QString(),
                       tr("segment, qw, qx, qy, qz (segment to sensor), axis_share, orthogonality (rad).")}};
}

Status SegmentCalibrationProcessor::prepare(const RunContext& c) const {
    if (auto names = segmentNames(c); !names) return names.error();
    if (auto w = window(c, "static_begin", "static_end"); !w) return w.error();
    if (auto w = window(c, "movement_begin", "movement_end"); !w) return w.error();
    return {};
}

Expected<std::vector<ProcessorOutput>> SegmentCalibrationProcessor::run(const RunContext& c) const {
    auto names = segmentNames(c);
    if (!names) return names.error();
    auto still = window(c, "static_begin", "static_end");
    if (!still) return still.error();
    auto moving = window(c, "movement_begin", "movement_end");
    if (!moving) return moving.error();
    QStringList segments;
    std::vector<math::Quat> mounts;
    TableColumn share{QStringLiteral("axis_share"), QStringLiteral("1"), false, {}, {}};
    TableColumn ortho{QStringLiteral("orthogonality"), QStringLiteral("rad"), false, {}, {}};
    for (int i = 0; i < c.inputCount(); ++i) {
        if (!c.stream(i)) continue;
        auto in = c.samples(i);
        if (!in) return in.error();
        auto cols = imuColumns(*in, false);
        if (!cols) return cols.error();
        auto ts = in->samplingInterval();
        if (!ts) return ts.error();
        const StreamData& d = *in->data;
        std::vector<math::Vec3> acc, gyr;
        const RowRange standing = rowsInTimeRange(d.t, still->begin, still->end);
        for (std::size_t k = standing.begin; k < standing.end; ++k)
            acc.emplace_back(d.at(k, cols->acc), d.at(k, cols->acc + 1), d.at(k, cols->acc + 2));
        const RowRange movement = rowsInTimeRange(d.t, moving->begin, moving->end);
        for (std::size_t k = movement.begin; k < movement.end; ++k)
            gyr.emplace_back(d.at(k, cols->gyr), d.at(k, cols->gyr + 1), d.at(k, cols->gyr + 2));
        SegmentCalibration::Params p;
        p.firstRotation = *firstRotation(names->at(i));
        auto result = SegmentCalibration(p).calibrate(acc, gyr, *ts);
        if (!result)
            return makeError(QStringLiteral("'%1' (%2): %3").arg(c.inputPath(i), names->at(i), result.message()));
        segments << names->at(i);
        mounts.push_back(result->mount);
        share.numbers.push_back(result->axisShare);
        ortho.numbers.push_back(result->orthogonality);
        c.report(double(i + 1) / c.inputCount());
        if (c.isCancelled()) return cancelledError();
    }
    Table table = segmentMountTable(segments, mounts, QJsonObject{{"method", "functional: upright + squats"}});
    table.columns.push_back(share);
    table.columns.push_back(ortho);
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), std::move(table)});
    return out;
}

}  // namespace athlos::inertial
