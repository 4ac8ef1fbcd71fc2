#include "plugins/inertial/JointAnglesProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/RowRange.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/JointAngles.h"
#include "plugins/inertial/SegmentMounts.h"

#include <algorithm>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "JointAnglesProcessor"};
const QString kIdentity = QStringLiteral("1,0,0,0");

struct Plan {
    JointAngles::Params params;
    bool alignHeading = true;
    double alignDuration = 2.0;
    InputSamples proximal, distal;
    std::vector<math::Quat> qProximal, qDistal;  // distal already at the proximal's times
};

Expected<std::vector<math::Quat>> readQuaternions(const InputSamples& s) {
    const StreamInfo& info = s.info();
    int c[4];
    int i = 0;
    for (const char* name : {"qw", "qx", "qy", "qz"}) {
        c[i] = info.columnIndex(QLatin1String(name));
        if (c[i] < 0)
            return s.error(QStringLiteral("no column '%1' (an orientation stream needs qw, qx, qy, qz; it has: %2)")
                               .arg(QLatin1String(name), info.columnNames().join(QStringLiteral(", "))));
        ++i;
    }
    const StreamData& d = *s.data;
    std::vector<math::Quat> q(d.rows());
    for (std::size_t k = 0; k < d.rows(); ++k) {
        q[k] = math::Quat(d.at(k, c[0]), d.at(k, c[1]), d.at(k, c[2]), d.at(k, c[3]));
        if (q[k].coeffs().allFinite() && q[k].norm() > 1e-9) q[k].normalize();
    }
    return q;
}

Expected<Plan> makePlan(const RunContext& c, bool load) {
    Plan plan;
    auto joint = parseJoint(c.has(QStringLiteral("joint")) ? c.text(QStringLiteral("joint")) : QStringLiteral("knee"));
    if (!joint) return joint.error();
    auto side = parseSide(c.has(QStringLiteral("side")) ? c.text(QStringLiteral("side")) : QStringLiteral("right"));
    if (!side) return side.error();
    plan.params.joint = *joint;
    plan.params.side = *side;
    const auto mount = [&](const char* name) -> Expected<math::Quat> {
        const QString n = QLatin1String(name);
        return parseQuaternion(c.has(n) ? c.text(n) : kIdentity, n);
    };
    auto mp = mount("proximal_mount");
    if (!mp) return mp.error();
    auto md = mount("distal_mount");
    if (!md) return md.error();
    plan.params.proximalMount = *mp;
    plan.params.distalMount = *md;
    if (c.inputCount() > 2 && c.table(2)) {
        // A calibration table replaces the mount parameters; giving both would be ambiguous.
        for (const char* name : {"proximal_mount", "distal_mount"})
            if (c.has(QLatin1String(name)) && c.text(QLatin1String(name)) != kIdentity)
                return makeError(
                    QStringLiteral("%1: give either the mount parameters or the calibration table '%2', not both")
                        .arg(QLatin1String(name), c.inputPath(2)));
        const QStringList segments = jointSegments(*joint);
        auto p = segmentMount(*c.table(2), c.inputPath(2), segments[0]);
        if (!p) return p.error();
        auto d = segmentMount(*c.table(2), c.inputPath(2), segments[1]);
        if (!d) return d.error();
        plan.params.proximalMount = *p;
        plan.params.distalMount = *d;
    }
    plan.alignHeading =
        !c.has(QStringLiteral("heading")) || c.text(QStringLiteral("heading")) == QLatin1String("align-start");
    if (c.has(QStringLiteral("align_duration"))) plan.alignDuration = c.number(QStringLiteral("align_duration"));
    if (!load) return plan;

    auto proximal = c.samples(0);
    if (!proximal) return proximal.error();
    auto distal = c.samples(1);
    if (!distal) return distal.error();
    plan.proximal = *proximal;
    plan.distal = *distal;
    auto qp = readQuaternions(plan.proximal);
    if (!qp) return qp.error();
    auto qd = readQuaternions(plan.distal);
    if (!qd) return qd.error();
    const std::vector<double>& tp = plan.proximal.data->t;
    const std::vector<double>& td = plan.distal.data->t;
    if (tp.empty() || td.empty())
        return makeError(QStringLiteral("stream '%1' is empty").arg(tp.empty() ? c.inputPath(0) : c.inputPath(1)));
    if (tp.back() < td.front() || td.back() < tp.front())
        return makeError(QStringLiteral("streams '%1' (%2–%3 s) and '%4' (%5–%6 s) do not overlap in time")
                             .arg(c.inputPath(0))
                             .arg(tp.front())
                             .arg(tp.back())
                             .arg(c.inputPath(1))
                             .arg(td.front())
                             .arg(td.back()));
    plan.qProximal = std::move(*qp);
    plan.qDistal = tp == td ? std::move(*qd) : slerpAt(td, *qd, tp);
    return plan;
}
}  // namespace

QString JointAnglesProcessor::name() const { return tr("Joint angles"); }

QString JointAnglesProcessor::description() const {
    return tr(
        "Knee, hip, ankle or trunk angles from the orientations of a proximal and a distal sensor (ISB "
        "recommendations, "
        "Grood & Suntay joint coordinate system = Z-X-Y Cardan angles of the relative segment rotation): flexion, "
        "abduction and internal rotation, positive on both sides (the left side is mirrored). The sensors' mounts "
        "(segment to sensor rotations) come from parameters or a segment-calibration table. Independent 6D headings "
        "are aligned over the first seconds, where the segments must face the same way (e.g. standing).");
}

ParameterSpecs JointAnglesProcessor::parameters() const {
    return {
        ParameterSpec::choice(
            QStringLiteral("joint"), jointNames(), QStringLiteral("knee"),
            tr("knee (thigh → shank), hip (pelvis → thigh), ankle (shank → foot) or trunk (pelvis → thorax).")),
        ParameterSpec::choice(
            QStringLiteral("side"), {QStringLiteral("right"), QStringLiteral("left")}, QStringLiteral("right"),
            tr("Body side; the left side is mirrored so that positive abduction and internal rotation mean "
               "the same on both sides.")),
        ParameterSpec::text(
            QStringLiteral("proximal_mount"), kIdentity,
            tr("Proximal segment frame in the sensor frame as a quaternion w,x,y,z (maps segment to sensor "
               "coordinates; ISB segment axes X anterior, Y superior, Z right).")),
        ParameterSpec::text(QStringLiteral("distal_mount"), kIdentity,
                            tr("Distal segment frame in the sensor frame (w,x,y,z).")),
        ParameterSpec::choice(
            QStringLiteral("heading"), {QStringLiteral("align-start"), QStringLiteral("none")},
            QStringLiteral("align-start"),
            tr("align-start: rotate the distal sensor's earth frame about the vertical so that both segments "
               "face the same way at the start (needed for 6D orientations); none: use the headings as they "
               "are (9D or optical).")),
        ParameterSpec::number(QStringLiteral("align_duration"), 2.0, 0.0, 3600.0, QStringLiteral("s"),
                              tr("Length of the start window for heading alignment.")),
    };
}

QList<InputSpec> JointAnglesProcessor::inputs() const {
    return {InputSpec{QStringLiteral("proximal"),
                      {QStringLiteral("orientation")},
                      false,
                      false,
                      tr("Orientation of the proximal segment's sensor (qw, qx, qy, qz).")},
            InputSpec{QStringLiteral("distal"),
                      {QStringLiteral("orientation")},
                      false,
                      false,
                      tr("Orientation of the distal segment's sensor (qw, qx, qy, qz).")},
            InputSpec{QStringLiteral("calibration"),
                      {kSegmentCalibrationKind},
                      true,
                      true,
                      tr("Segment-calibration table (segment, qw..qz) with rows for both segments of the joint.")}};
}

QList<OutputSpec> JointAnglesProcessor::outputs() const {
    return {OutputSpec{
        QStringLiteral("joint-angles"), false, QString(),
        tr("flexion, abduction, rotation (rad), long_axis_angle, proximal_inclination, distal_inclination (rad).")}};
}

// The checks need no samples: the parameters and the calibration table.
Status JointAnglesProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context, false)); }

Expected<std::vector<ProcessorOutput>> JointAnglesProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context, true);
    if (!plan) return plan.error();
    const std::vector<double>& t = plan->proximal.data->t;
    if (plan->alignHeading) {
        const std::size_t n =
            std::max<std::size_t>(1, rowsInTimeRange(t, t.front(), t.front() + plan->alignDuration).size());
        plan->params.headingOffset =
            JointAngles::estimateHeadingOffset(std::span(plan->qProximal).first(n), std::span(plan->qDistal).first(n),
                                               plan->params.proximalMount, plan->params.distalMount);
    }
    if (context.isCancelled()) return cancelledError();
    const JointAngles joint(plan->params);
    const std::size_t n = std::min(plan->qProximal.size(), plan->qDistal.size());
    StreamData out(n, static_cast<int>(JointAngles::kColumns));  // the batch's column order is the stream's
    out.t.assign(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(n));
    joint.updateBatch(plan->qProximal, plan->qDistal, out.values);
    context.report(1.0);
    const QJsonObject attributes{
        {"joint", jointName(plan->params.joint)},
        {"side", sideName(plan->params.side)},
        {"convention", QStringLiteral("ISB / Grood & Suntay: Z-X-Y Cardan angles of the distal segment relative to the "
                                      "proximal; flexion, abduction, internal rotation positive")},
        {"proximal_mount", formatQuaternion(plan->params.proximalMount)},
        {"distal_mount", formatQuaternion(plan->params.distalMount)},
        {"heading_offset", plan->params.headingOffset},
        {"proximal", context.inputPath(0)},
        {"distal", context.inputPath(1)}};
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), outputStream(QStringLiteral("joint-angles"), QStringLiteral("segment"),
                                               columnsOf({"flexion", "abduction", "rotation", "long_axis_angle",
                                                          "proximal_inclination", "distal_inclination"},
                                                         {"rad", "rad", "rad", "rad", "rad", "rad"}),
                                               std::move(out), attributes)});
    return outputs;
}

}  // namespace athlos::inertial
