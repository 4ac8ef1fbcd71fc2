#include "plugins/inertial/SimulateBodyProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/BodySimulator.h"
#include "plugins/inertial/SegmentMounts.h"
#include "plugins/inertial/SimulatedStreams.h"

#include <limits>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "SimulateBodyProcessor"};

Stream imuStream(const BodySimulation& sim, int s, const QJsonObject& attributes) {
    const BodySensor& seg = sim.sensors[s];
    return simulatedImuStream(sim.t, seg.acc, seg.gyr, bodySegmentName(static_cast<BodySegment>(s)), seg.mount,
                              attributes);
}

Stream angleStream(const BodySimulation& sim, int j, const QJsonObject& attributes) {
    const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
    return trueJointAngles(sim.t, sim.joints[j].angles, info.joint, info.side, attributes);
}

// The mounts of one side under the segment names joint-angles looks up (jointSegments()).
Table sideMounts(const BodySimulation& sim, Side side, const QJsonObject& attributes) {
    const int o = side == Side::Right ? 0 : 3;
    return segmentMountTable({QStringLiteral("pelvis"), QStringLiteral("thorax"), QStringLiteral("thigh"),
                              QStringLiteral("shank"), QStringLiteral("foot")},
                             {sim.sensors[0].mount, sim.sensors[1].mount, sim.sensors[2 + o].mount,
                              sim.sensors[3 + o].mount, sim.sensors[4 + o].mount},
                             attributes);
}

Table jointVectors(const BodySimulation& sim, const QJsonObject& attributes) {
    Table t;
    t.kind = QStringLiteral("sensor-to-joint");
    t.attributes = attributes;
    t.attributes.insert(QStringLiteral("convention"),
                        QStringLiteral("vectors from each sensor to the joint centre in that sensor's frame (m)"));
    TableColumn joint{QStringLiteral("joint"), QString(), true, {}, {}};
    TableColumn proximal{QStringLiteral("proximal"), QString(), true, {}, {}};
    TableColumn distal{QStringLiteral("distal"), QString(), true, {}, {}};
    std::vector<TableColumn> v;
    for (const char* c : {"rp_x", "rp_y", "rp_z", "rd_x", "rd_y", "rd_z"})
        v.push_back(TableColumn{QLatin1String(c), QStringLiteral("m"), false, {}, {}});
    for (int j = 0; j < kBodyJoints; ++j) {
        const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
        joint.texts << bodyJointName(static_cast<BodyJoint>(j));
        proximal.texts << bodySegmentName(info.proximal);
        distal.texts << bodySegmentName(info.distal);
        for (int i = 0; i < 3; ++i) {
            v[i].numbers.push_back(sim.joints[j].proximalToJoint[i]);
            v[3 + i].numbers.push_back(sim.joints[j].distalToJoint[i]);
        }
    }
    t.columns = {joint, proximal, distal};
    for (TableColumn& c : v) t.columns.push_back(std::move(c));
    return t;
}
}  // namespace

QString SimulateBodyProcessor::name() const { return tr("Simulate body IMUs"); }

QString SimulateBodyProcessor::description() const {
    return tr(
        "Eight IMUs (sacrum, sternum, thighs, shanks, feet) with known, misaligned mounts off the joint axes: upright "
        "standing and squats for calibration, then walking or an alpine skiing run (turns 27 m apart at 20 m/s on a "
        "26° slope), with gyroscope bias, slow drift, noise, scale, g-sensitivity, vibration and impacts. The sacrum "
        "IMU is at <output>, the others at <output>-<segment>; truth: segment orientations at <output>-segments, "
        "joint-centre positions at <output>-joint-centres, reference angles at <output>-<joint>-reference, the true "
        "mounts per side at <output>-right-mounts / <output>-left-mounts and sensor-to-joint vectors at "
        "<output>-joint-vectors.");
}

ParameterSpecs SimulateBodyProcessor::parameters() const {
    const BodySimulatorParams d;
    return {
        ParameterSpec::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(), tr("Random seed.")),
        ParameterSpec::choice(QStringLiteral("scenario"),
                              {QStringLiteral("skiing"), QStringLiteral("walking"), QStringLiteral("squats")},
                              QStringLiteral("skiing"), tr("Movement after the calibration block.")),
        ParameterSpec::number(QStringLiteral("rate"), d.rate, 10.0, 2000.0, QStringLiteral("Hz"),
                              tr("IMU sampling rate.")),
        ParameterSpec::number(QStringLiteral("motion_duration"), d.motionDuration, 4.0, 3600.0, QStringLiteral("s"),
                              tr("Length of the walking or skiing phase (including the speed ramps).")),
        ParameterSpec::integer(QStringLiteral("squats"), d.squats, 0, 100, tr("Number of calibration squats.")),
        ParameterSpec::integer(QStringLiteral("trunk_rotations"), d.trunkRotations, 0, 100,
                               tr("Calibration trunk rotations after the squats (0 = none; the protocol has 3).")),
        ParameterSpec::integer(QStringLiteral("hip_abductions"), d.hipAbductions, 0, 100,
                               tr("Calibration hip ab/adductions per leg after them (0 = none; the protocol has 3).")),
        ParameterSpec::number(QStringLiteral("gyr_bias"), d.gyrBias, 0.0, 1.0, QStringLiteral("rad/s"),
                              tr("Largest constant gyroscope bias per axis (drawn uniformly).")),
        ParameterSpec::number(QStringLiteral("gyr_drift"), d.gyrDrift, 0.0, 1.0, QStringLiteral("rad/s"),
                              tr("Slow gyroscope bias change during the motion (norm; ≈ 0.15°/s on snow, Fasel "
                                 "2017 ch. 5).")),
        ParameterSpec::number(QStringLiteral("gyr_noise"), d.gyrNoise, 0.0, 1.0, QStringLiteral("rad/s"),
                              tr("Gyroscope white noise per sample (standard deviation).")),
        ParameterSpec::number(QStringLiteral("acc_noise"), d.accNoise, 0.0, 10.0, QStringLiteral("m/s^2"),
                              tr("Accelerometer white noise per sample (standard deviation).")),
        ParameterSpec::number(QStringLiteral("vibration"), d.vibration, 0.0, 100.0, QStringLiteral("m/s^2"),
                              tr("Skiing: 15–30 Hz vibration amplitude at the feet (damped up the body).")),
        ParameterSpec::number(QStringLiteral("impact_rate"), d.impactRate, 0.0, 100.0, QStringLiteral("1/s"),
                              tr("Skiing: mean rate of 10 ms impacts.")),
    };
}

QList<OutputSpec> SimulateBodyProcessor::outputs() const {
    QList<OutputSpec> out{OutputSpec{QStringLiteral("imu"), false, QString(), tr("Sacrum IMU: acc_x..z, gyr_x..z.")}};
    for (int s = 1; s < kBodySegments; ++s)
        out << OutputSpec{QStringLiteral("imu"), false, bodySegmentName(static_cast<BodySegment>(s)),
                          tr("IMU of this segment.")};
    out << OutputSpec{QStringLiteral("segment-orientation"), false, QStringLiteral("segments"),
                      tr("True segment orientations <segment>_qw..qz (segment to ENU).")}
        << OutputSpec{QStringLiteral("joint-centres"), false, QStringLiteral("joint-centres"),
                      tr("True joint-centre positions <joint>_x..z (m, ENU).")};
    for (int j = 0; j < kBodyJoints; ++j)
        out << OutputSpec{QStringLiteral("joint-angles"), false,
                          bodyJointName(static_cast<BodyJoint>(j)) + QStringLiteral("-reference"),
                          tr("True joint angles (rad).")};
    out << OutputSpec{kSegmentCalibrationKind, true, QStringLiteral("right-mounts"),
                      tr("True mounts of pelvis, thorax and the right leg (segment, qw..qz).")}
        << OutputSpec{kSegmentCalibrationKind, true, QStringLiteral("left-mounts"),
                      tr("True mounts of pelvis, thorax and the left leg.")}
        << OutputSpec{QStringLiteral("sensor-to-joint"), true, QStringLiteral("joint-vectors"),
                      tr("True sensor-to-joint vectors (joint, proximal, distal, rp_x..z, rd_x..z in m).")};
    return out;
}

Expected<std::vector<ProcessorOutput>> SimulateBodyProcessor::run(const RunContext& c) const {
    BodySimulatorParams p;
    if (c.has(QStringLiteral("seed"))) p.seed = static_cast<std::uint64_t>(c.integer(QStringLiteral("seed")));
    if (c.has(QStringLiteral("scenario"))) {
        auto scenario = parseBodyScenario(c.text(QStringLiteral("scenario")));
        if (!scenario) return scenario.error();
        p.scenario = *scenario;
    }
    const auto num = [&](const char* name, double& value) {
        if (c.has(QLatin1String(name))) value = c.number(QLatin1String(name));
    };
    num("rate", p.rate);
    num("motion_duration", p.motionDuration);
    if (c.has(QStringLiteral("squats"))) p.squats = c.integer(QStringLiteral("squats"));
    if (c.has(QStringLiteral("trunk_rotations"))) p.trunkRotations = c.integer(QStringLiteral("trunk_rotations"));
    if (c.has(QStringLiteral("hip_abductions"))) p.hipAbductions = c.integer(QStringLiteral("hip_abductions"));
    num("gyr_bias", p.gyrBias);
    num("gyr_drift", p.gyrDrift);
    num("gyr_noise", p.gyrNoise);
    num("acc_noise", p.accNoise);
    num("vibration", p.vibration);
    num("impact_rate", p.impactRate);
    c.report(0.1, QStringLiteral("simulating"));
    const BodySimulation sim = simulateBody(p);
    if (c.isCancelled()) return cancelledError();
    QJsonObject attrs{
        {"simulated", true},
        {"seed", static_cast<double>(p.seed)},
        {"scenario", c.has(QStringLiteral("scenario")) ? c.text(QStringLiteral("scenario")) : QStringLiteral("skiing")},
        {"upright_end", sim.uprightEnd},
        {"squat_begin", sim.squatBegin},
        {"squat_end", sim.squatEnd},
        {"motion_begin", sim.motionBegin},
        {"motion_end", sim.motionEnd}};
    // The further calibration blocks only when simulated (the default attributes stay as they were).
    if (p.trunkRotations > 0) {
        attrs.insert(QStringLiteral("trunk_rotations_begin"), sim.trunkBegin);
        attrs.insert(QStringLiteral("trunk_rotations_end"), sim.trunkEnd);
    }
    if (p.hipAbductions > 0) {
        attrs.insert(QStringLiteral("right_abduction_begin"), sim.rightAbductionBegin);
        attrs.insert(QStringLiteral("right_abduction_end"), sim.rightAbductionEnd);
        attrs.insert(QStringLiteral("left_abduction_begin"), sim.leftAbductionBegin);
        attrs.insert(QStringLiteral("left_abduction_end"), sim.leftAbductionEnd);
    }
    const std::size_t n = sim.t.size();
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), imuStream(sim, 0, attrs)});
    for (int s = 1; s < kBodySegments; ++s)
        out.push_back({bodySegmentName(static_cast<BodySegment>(s)), imuStream(sim, s, attrs)});
    {
        QStringList names;
        std::vector<const std::vector<math::Quat>*> orientations;
        for (int s = 0; s < kBodySegments; ++s) {
            names << bodySegmentName(static_cast<BodySegment>(s));
            orientations.push_back(&sim.sensors[s].segment);
        }
        out.push_back({QStringLiteral("segments"), trueSegmentOrientations(sim.t, names, orientations, attrs)});
    }
    {
        StreamData d(n, 3 * kBodyJoints);
        d.t = sim.t;
        QStringList names, units;
        for (int j = 0; j < kBodyJoints; ++j) {
            for (const char* a : {"_x", "_y", "_z"}) {
                names << bodyJointName(static_cast<BodyJoint>(j)) + QLatin1String(a);
                units << QStringLiteral("m");
            }
            for (std::size_t k = 0; k < n; ++k)
                for (int i = 0; i < 3; ++i) d.at(k, 3 * j + i) = sim.joints[j].centre[k][i];
        }
        out.push_back(
            {QStringLiteral("joint-centres"), outputStream(QStringLiteral("joint-centres"), QStringLiteral("ENU"),
                                                           columnsOf(names, units), std::move(d), attrs)});
    }
    for (int j = 0; j < kBodyJoints; ++j)
        out.push_back(
            {bodyJointName(static_cast<BodyJoint>(j)) + QStringLiteral("-reference"), angleStream(sim, j, attrs)});
    out.push_back({QStringLiteral("right-mounts"), sideMounts(sim, Side::Right, attrs)});
    out.push_back({QStringLiteral("left-mounts"), sideMounts(sim, Side::Left, attrs)});
    out.push_back({QStringLiteral("joint-vectors"), jointVectors(sim, attrs)});
    c.report(1.0);
    return out;
}

}  // namespace athlos::inertial
