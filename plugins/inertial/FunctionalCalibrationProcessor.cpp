#include "plugins/inertial/FunctionalCalibrationProcessor.h"

#include "core/math/Angles.h"
#include "core/model/Project.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/FunctionalCalibration.h"
#include "plugins/inertial/ImuColumns.h"
#include "plugins/inertial/SegmentMounts.h"

#include <QRegularExpression>
#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "FunctionalCalibrationProcessor"};
// The lower body and trunk (8), head, upper back and both arms (6), with room for a second back sensor.
constexpr int kMaxInputs = 16;
const QString kDefaultSegments =
    QStringLiteral("sacrum,sternum,right-thigh,right-shank,right-foot,left-thigh,left-shank,left-foot");

Expected<QStringList> segmentNames(const RunContext& c) {
    static const QRegularExpression separators(QStringLiteral("[,;\\s]+"));
    const QStringList names = c.text(QStringLiteral("segments")).split(separators, Qt::SkipEmptyParts);
    int inputs = 0;
    for (int i = 0; i < c.inputCount(); ++i) inputs += c.stream(i) ? 1 : 0;
    // Exactly one name per input: a default list longer than the inputs would silently mislabel them.
    if (names.size() != inputs)
        return makeError(QStringLiteral("segments: %1 name(s) for %2 IMU stream(s); name every input, in order")
                             .arg(names.size())
                             .arg(inputs));
    return names;
}

// "squats=12-24.5; right-abduction=40-49" → given movements.
Expected<std::vector<FunctionalCalibration::Movement>> parseIntervals(const QString& text) {
    std::vector<FunctionalCalibration::Movement> out;
    static const QRegularExpression item(
        QStringLiteral("^\\s*([a-z-]+)\\s*=\\s*([-+0-9.eE]+)\\s*-\\s*([-+0-9.eE]+)\\s*$"));
    for (const QString& part : text.split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        if (part.trimmed().isEmpty()) continue;
        const auto m = item.match(part);
        bool okB = false, okE = false;
        const double b = m.hasMatch() ? m.captured(2).toDouble(&okB) : 0.0;
        const double e = m.hasMatch() ? m.captured(3).toDouble(&okE) : 0.0;
        if (!m.hasMatch() || !okB || !okE || !(e > b))
            return makeError(QStringLiteral("intervals: '%1' is not <movement>=<begin>-<end> (s, end after begin)")
                                 .arg(part.trimmed()));
        auto kind = parseCalibrationMovement(m.captured(1));
        if (!kind) return makeError(QStringLiteral("intervals: %1").arg(kind.message()));
        FunctionalCalibration::Movement mv;
        mv.movement = *kind;
        mv.interval = {b, e};
        mv.given = true;
        out.push_back(mv);
    }
    return out;
}

FunctionalCalibration::Params engineParams(const RunContext& c) {
    FunctionalCalibration::Params p;
    p.restRate = c.number(QStringLiteral("rest_rate"));
    p.minUpright = c.number(QStringLiteral("min_upright"));
    p.minPause = c.number(QStringLiteral("min_pause"));
    p.moveRate = c.number(QStringLiteral("move_rate"));
    p.stillRatio = c.number(QStringLiteral("still_ratio"));
    p.axialTolerance = c.number(QStringLiteral("axial_tolerance"));
    p.minRepetitions = c.integer(QStringLiteral("repetitions"));
    p.maxDispersion = c.number(QStringLiteral("max_dispersion"));
    p.maxAxisTilt = c.number(QStringLiteral("max_axis_tilt"));
    return p;
}

TableColumn numbers(const char* name, const char* unit) {
    return TableColumn{QLatin1String(name), QLatin1String(unit), false, {}, {}};
}
TableColumn texts(const char* name) { return TableColumn{QLatin1String(name), QString(), true, {}, {}}; }

bool isThorax(const QString& segment) {
    return segment == QLatin1String("sternum") || segment == QLatin1String("trunk") ||
           segment == QLatin1String("thorax");
}

// The name joint-angles looks up (jointSegments()) for a protocol segment seen from one side, or
// empty when the segment belongs to the other side. The upper back stands for the thorax only when no
// sternum was calibrated (one thorax row per side).
QString jointAnglesName(const QString& segment, const QString& side, const QStringList& all) {
    if (segment == QLatin1String("sacrum") || segment == QLatin1String("pelvis") ||
        segment == QLatin1String("lower-back"))
        return QStringLiteral("pelvis");
    if (isThorax(segment)) return QStringLiteral("thorax");
    if (segment == QLatin1String("upper-back"))
        return std::any_of(all.begin(), all.end(), isThorax) ? QString() : QStringLiteral("thorax");
    if (segment == QLatin1String("head")) return segment;
    const QString prefix = side + QLatin1Char('-');
    return segment.startsWith(prefix) ? segment.mid(prefix.size()) : QString();
}
}  // namespace

QString FunctionalCalibrationProcessor::name() const { return tr("Functional calibration (protocol)"); }

QString FunctionalCalibrationProcessor::description() const {
    return tr(
        "Sensor-to-segment mounts from the whole functional calibration protocol in one recording: upright standing, "
        "squats, trunk rotations, hip ab/adduction per leg and the optional arm swings, found automatically (or from "
        "annotations). Gravity gives each segment's superior axis, the principal axis of the angular velocity its "
        "medio-lateral axis (squats: pelvis, trunk, upper back, head, thighs, shanks; arm swings: upper arms) or "
        "antero-posterior axis (ab/adduction: feet; arm swings: forearms). Writes a segment-calibration table for "
        "joint-angles and body-com and a quality table (dispersion between repetitions, orthogonality, CMC).");
}

ParameterSpecs FunctionalCalibrationProcessor::parameters() const {
    const FunctionalCalibration::Params d;
    return {
        ParameterSpec::text(QStringLiteral("segments"), kDefaultSegments,
                            tr("Segment of each input IMU, in input order: sacrum (pelvis, lower-back), sternum "
                               "(trunk), upper-back, head, right-/left-thigh, right-/left-shank, right-/left-foot, "
                               "right-/left-upper-arm, right-/left-forearm.")),
        ParameterSpec::text(QStringLiteral("intervals"), QString(),
                            tr("Movements given by hand, e.g. 'squats=12-24; right-abduction=40-49' (s); they "
                               "override the detection and the annotations.")),
        ParameterSpec::boolean(QStringLiteral("annotations"), true,
                               tr("Take interval annotations of the recording labelled upright, squats, "
                                  "trunk-rotations, right-abduction, left-abduction or arm-swings as the movements.")),
        ParameterSpec::number(QStringLiteral("rest_rate"), d.restRate, 0.01, 5.0, QStringLiteral("rad/s"),
                              tr("Rest: every sensor's angular rate (0.5 s mean) below this (11°/s).")),
        ParameterSpec::number(QStringLiteral("min_upright"), d.minUpright, 1.0, 600.0, QStringLiteral("s"),
                              tr("Shortest upright standing (the protocol asks for 10 s; Fasel ch. 6).")),
        ParameterSpec::number(QStringLiteral("min_pause"), d.minPause, 0.1, 60.0, QStringLiteral("s"),
                              tr("Rest that separates two movements.")),
        ParameterSpec::number(QStringLiteral("move_rate"), d.moveRate, 0.01, 10.0, QStringLiteral("rad/s"),
                              tr("RMS angular rate above which a segment takes part in a movement (8°/s).")),
        ParameterSpec::number(QStringLiteral("still_ratio"), d.stillRatio, 0.01, 1.0, QStringLiteral("1"),
                              tr("Ab/adduction: the standing leg's RMS rate below this share of the moving leg's.")),
        ParameterSpec::number(QStringLiteral("axial_tolerance"), d.axialTolerance, 0.01, 1.5, QStringLiteral("rad"),
                              tr("Trunk rotations: largest angle between the sternum's turning axis and gravity; "
                                 "squats and ab/adduction: smallest angle from the horizontal plane is 90° minus it.")),
        ParameterSpec::integer(QStringLiteral("repetitions"), d.minRepetitions, 1, 100,
                               tr("Repetitions each movement needs (the protocol's ×3, spec §4).")),
        ParameterSpec::number(QStringLiteral("max_dispersion"), d.maxDispersion, 0.001, 1.5, QStringLiteral("rad"),
                              tr("Largest dispersion χ of the functional axis between repetitions (10°; Fasel "
                                 "Table 6.3 reports up to 5.5° for the shank).")),
        ParameterSpec::number(QStringLiteral("max_axis_tilt"), d.maxAxisTilt, 0.01, 1.5, QStringLiteral("rad"),
                              tr("Largest angle between the functional axis and the plane perpendicular to gravity "
                                 "(30°; the simulated shank's coupled rotation tilts it by ≈ 8°).")),
    };
}

QList<InputSpec> FunctionalCalibrationProcessor::inputs() const {
    QList<InputSpec> in{InputSpec{
        QStringLiteral("imu"), {QStringLiteral("imu")}, false, false, tr("IMU of the first segment (acc, gyr).")}};
    for (int i = 2; i <= kMaxInputs; ++i)
        in.append(InputSpec{
            QStringLiteral("imu%1").arg(i), {QStringLiteral("imu")}, false, true, tr("IMU of segment %1.").arg(i)});
    return in;
}

QList<OutputSpec> FunctionalCalibrationProcessor::outputs() const {
    return {OutputSpec{kSegmentCalibrationKind, true, QString(),
                       tr("segment, qw, qx, qy, qz (segment to sensor), axis_share, orthogonality (rad).")},
            OutputSpec{kSegmentCalibrationKind, true, QStringLiteral("right"),
                       tr("The right side's mounts under the names joint-angles reads: pelvis, thorax, head, "
                          "thigh, shank, foot, upper-arm, forearm.")},
            OutputSpec{kSegmentCalibrationKind, true, QStringLiteral("left"),
                       tr("The left side's mounts (pelvis, thorax, head, thigh, shank, foot, upper-arm, "
                          "forearm).")},
            OutputSpec{kCalibrationQualityKind, true, QStringLiteral("quality"),
                       tr("Per segment: movement, repetitions, dispersion χ, orthogonality, cross_orthogonality "
                          "(rad), cmc, begin, end (s).")},
            OutputSpec{kCalibrationMovementsKind, true, QStringLiteral("movements"),
                       tr("Per movement and repetition: movement, repetition (0 = whole), begin, end (s), given.")}};
}

Status FunctionalCalibrationProcessor::prepare(const RunContext& c) const {
    if (auto names = segmentNames(c); !names) return names.error();
    if (auto given = parseIntervals(c.text(QStringLiteral("intervals"))); !given) return given.error();
    return {};
}

Expected<std::vector<ProcessorOutput>> FunctionalCalibrationProcessor::run(const RunContext& c) const {
    auto names = segmentNames(c);
    if (!names) return names.error();
    auto given = parseIntervals(c.text(QStringLiteral("intervals")));
    if (!given) return given.error();
    // Annotations of the first input's recording fill in what the parameter does not give.
    if (c.flag(QStringLiteral("annotations"))) {
        const Recording* rec = c.project().recording(ItemPath::parse(c.inputPath(0)).recording);
        for (const Annotation& a : rec ? rec->annotations : Annotations{}) {
            auto kind = parseCalibrationMovement(a.label.trimmed().toLower());
            if (!kind || !(a.tEnd > a.tStart)) continue;
            bool already = false;
            for (const auto& g : *given) already = already || g.movement == *kind;
            if (already) continue;
            FunctionalCalibration::Movement mv;
            mv.movement = *kind;
            mv.interval = {a.tStart, a.tEnd};
            mv.given = true;
            given->push_back(mv);
        }
    }
    std::vector<FunctionalCalibration::Segment> segments;
    int name = 0;
    for (int i = 0; i < c.inputCount(); ++i) {
        if (!c.stream(i)) continue;
        auto in = c.samples(i);
        if (!in) return in.error();
        auto cols = imuColumns(*in, false);
        if (!cols) return cols.error();
        const StreamData& d = *in->data;
        FunctionalCalibration::Segment s;
        s.name = names->at(name++);
        s.t.assign(d.t.begin(), d.t.end());
        for (std::size_t k = 0; k < d.t.size(); ++k) {
            s.acc.emplace_back(d.at(k, cols->acc), d.at(k, cols->acc + 1), d.at(k, cols->acc + 2));
            s.gyr.emplace_back(d.at(k, cols->gyr), d.at(k, cols->gyr + 1), d.at(k, cols->gyr + 2));
        }
        segments.push_back(std::move(s));
        c.report(0.5 * double(i + 1) / c.inputCount());
        if (c.isCancelled()) return cancelledError();
    }
    auto result = FunctionalCalibration(engineParams(c)).calibrate(segments, *given);
    if (!result) return result.error();
    if (c.isCancelled()) return cancelledError();

    QStringList segmentList;
    std::vector<math::Quat> mounts;
    TableColumn share = numbers("axis_share", "1"), ortho = numbers("orthogonality", "rad");
    TableColumn qName = texts("segment"), qMovement = texts("movement"), qReps = numbers("repetitions", "1"),
                qChi = numbers("dispersion", "rad"), qOrtho = numbers("orthogonality", "rad"),
                qCross = numbers("cross_orthogonality", "rad"), qCmc = numbers("cmc", "1"),
                qBegin = numbers("begin", "s"), qEnd = numbers("end", "s");
    for (const auto& s : result->segments) {
        segmentList << s.name;
        mounts.push_back(s.mount);
        share.numbers.push_back(s.axisShare);
        ortho.numbers.push_back(s.orthogonality);
        qName.texts << s.name;
        qMovement.texts << calibrationMovementName(s.movement);
        qReps.numbers.push_back(s.repetitions);
        qChi.numbers.push_back(s.dispersion);
        qOrtho.numbers.push_back(s.orthogonality);
        qCross.numbers.push_back(s.crossOrthogonality);
        qCmc.numbers.push_back(s.cmc);
        double begin = std::numeric_limits<double>::quiet_NaN(), end = begin;
        for (const auto& m : result->movements)
            if (m.movement == s.movement) begin = m.interval.begin, end = m.interval.end;
        qBegin.numbers.push_back(begin);
        qEnd.numbers.push_back(end);
    }
    bool armSwings = false;
    for (const auto& s : result->segments) armSwings = armSwings || s.movement == CalibrationMovement::ArmSwings;
    QString method = QStringLiteral("functional protocol: upright, squats, trunk rotations, hip ab/adduction");
    if (armSwings) method += QStringLiteral(", arm swings");
    Table mountTable = segmentMountTable(segmentList, mounts, QJsonObject{{"method", method}});
    mountTable.columns.push_back(share);
    mountTable.columns.push_back(ortho);

    Table quality;
    quality.kind = kCalibrationQualityKind;
    quality.attributes.insert(QStringLiteral("cmc"),
                              QStringLiteral("Kadaba et al. 1989, repetition curves resampled to 101 points"));
    quality.columns = {qName, qMovement, qReps, qChi, qOrtho, qCross, qCmc, qBegin, qEnd};

    Table moves;
    moves.kind = kCalibrationMovementsKind;
    TableColumn mName = texts("movement"), mRep = numbers("repetition", "1"), mBegin = numbers("begin", "s"),
                mEnd = numbers("end", "s"), mGiven = numbers("given", "1");
    for (const auto& m : result->movements) {
        mName.texts << calibrationMovementName(m.movement);
        mRep.numbers.push_back(0);
        mBegin.numbers.push_back(m.interval.begin);
        mEnd.numbers.push_back(m.interval.end);
        mGiven.numbers.push_back(m.given ? 1 : 0);
        for (std::size_t r = 0; r < m.repetitions.size(); ++r) {
            mName.texts << calibrationMovementName(m.movement);
            mRep.numbers.push_back(double(r + 1));
            mBegin.numbers.push_back(m.repetitions[r].begin);
            mEnd.numbers.push_back(m.repetitions[r].end);
            mGiven.numbers.push_back(m.given ? 1 : 0);
        }
    }
    moves.columns = {mName, mRep, mBegin, mEnd, mGiven};
    c.report(1.0);

    std::vector<ProcessorOutput> out;
    out.push_back({QString(), std::move(mountTable)});
    for (const char* sideName : {"right", "left"}) {
        const QString side = QLatin1String(sideName);
        QStringList sideNames;
        std::vector<math::Quat> sideMounts;
        for (qsizetype i = 0; i < segmentList.size(); ++i) {
            const QString n = jointAnglesName(segmentList[i], side, segmentList);
            if (n.isEmpty()) continue;
            sideNames << n;
            sideMounts.push_back(mounts[std::size_t(i)]);
        }
        out.push_back({side, segmentMountTable(sideNames, sideMounts,
                                               QJsonObject{{"method", "functional protocol"}, {"side", side}})});
    }
    out.push_back({QStringLiteral("quality"), std::move(quality)});
    out.push_back({QStringLiteral("movements"), std::move(moves)});
    return out;
}

}  // namespace athlos::inertial
