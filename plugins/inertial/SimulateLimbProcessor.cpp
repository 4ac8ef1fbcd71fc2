#include "plugins/inertial/SimulateLimbProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/LimbSimulator.h"
#include "plugins/inertial/SegmentMounts.h"
#include "plugins/inertial/SimulatedStreams.h"

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "SimulateLimbProcessor"};

const QStringList kSegments{QStringLiteral("pelvis"), QStringLiteral("thigh"), QStringLiteral("shank")};

Stream imuStream(const LimbSimulation& sim, int s, const QJsonObject& attributes) {
    const SimulatedSegment& seg = sim.segments[s];
    return simulatedImuStream(sim.t, seg.acc, seg.gyr, kSegments[s], seg.mount, attributes);
}
}  // namespace

QString SimulateLimbProcessor::name() const { return tr("Simulate lower limb IMUs"); }

QString SimulateLimbProcessor::description() const {
    return tr(
        "Pelvis, thigh and shank IMUs with known, non-trivial mounts during standing, walking along a curve and "
        "squats, with the true hip and knee angles (3 DOF). Thigh IMU at <output>, shank and pelvis IMUs at "
        "<output>-shank and <output>-pelvis, true segment orientations at <output>-segments, reference angles at "
        "<output>-knee-reference and <output>-hip-reference, the true mounts as a segment-calibration table at "
        "<output>-mounts.");
}

ParameterSpecs SimulateLimbProcessor::parameters() const {
    const LimbSimulatorParams d;
    return {
        ParameterSpec::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(), tr("Random seed.")),
        ParameterSpec::choice(QStringLiteral("side"), {QStringLiteral("right"), QStringLiteral("left")},
                              QStringLiteral("right"), tr("Which leg carries the thigh and shank sensors.")),
        ParameterSpec::number(QStringLiteral("rate"), d.rate, 10.0, 2000.0, QStringLiteral("Hz"),
                              tr("IMU sampling rate.")),
        ParameterSpec::number(QStringLiteral("walk_duration"), d.walkDuration, 2.0, 3600.0, QStringLiteral("s"),
                              tr("Length of the walking phase.")),
        ParameterSpec::integer(QStringLiteral("squats"), d.squats, 0, 100, tr("Number of squats after walking.")),
        ParameterSpec::number(QStringLiteral("gyr_bias"), d.gyrBias, 0.0, 1.0, QStringLiteral("rad/s"),
                              tr("Largest gyroscope bias per axis (drawn uniformly).")),
        ParameterSpec::number(QStringLiteral("gyr_noise"), d.gyrNoise, 0.0, 1.0, QStringLiteral("rad/s"),
                              tr("Gyroscope white noise per sample (standard deviation).")),
        ParameterSpec::number(QStringLiteral("acc_noise"), d.accNoise, 0.0, 10.0, QStringLiteral("m/s^2"),
                              tr("Accelerometer white noise per sample (standard deviation).")),
    };
}

QList<OutputSpec> SimulateLimbProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("imu"), false, QString(), tr("Thigh IMU: acc_x..z, gyr_x..z.")},
            OutputSpec{QStringLiteral("imu"), false, QStringLiteral("shank"), tr("Shank IMU.")},
            OutputSpec{QStringLiteral("imu"), false, QStringLiteral("pelvis"), tr("Pelvis IMU.")},
            OutputSpec{QStringLiteral("segment-orientation"), false, QStringLiteral("segments"),
                       tr("True segment orientations pelvis_qw..qz, thigh_qw..qz, shank_qw..qz (segment to ENU).")},
            OutputSpec{QStringLiteral("joint-angles"), false, QStringLiteral("knee-reference"),
                       tr("True knee angles (rad).")},
            OutputSpec{QStringLiteral("joint-angles"), false, QStringLiteral("hip-reference"),
                       tr("True hip angles (rad).")},
            OutputSpec{kSegmentCalibrationKind, true, QStringLiteral("mounts"), tr("True mounts (segment, qw..qz).")}};
}

Expected<std::vector<ProcessorOutput>> SimulateLimbProcessor::run(const RunContext& c) const {
    LimbSimulatorParams p;
    if (c.has(QStringLiteral("seed"))) p.seed = static_cast<std::uint64_t>(c.integer(QStringLiteral("seed")));
    if (c.has(QStringLiteral("side"))) {
        auto side = parseSide(c.text(QStringLiteral("side")));
        if (!side) return side.error();
        p.side = *side;
    }
    if (c.has(QStringLiteral("rate"))) p.rate = c.number(QStringLiteral("rate"));
    if (c.has(QStringLiteral("walk_duration"))) p.walkDuration = c.number(QStringLiteral("walk_duration"));
    if (c.has(QStringLiteral("squats"))) p.squats = c.integer(QStringLiteral("squats"));
    if (c.has(QStringLiteral("gyr_bias"))) p.gyrBias = c.number(QStringLiteral("gyr_bias"));
    if (c.has(QStringLiteral("gyr_noise"))) p.gyrNoise = c.number(QStringLiteral("gyr_noise"));
    if (c.has(QStringLiteral("acc_noise"))) p.accNoise = c.number(QStringLiteral("acc_noise"));
    c.report(0.1, QStringLiteral("simulating"));
    const LimbSimulation sim = simulateLimb(p);
    if (c.isCancelled()) return cancelledError();
    const QJsonObject attrs{{"simulated", true},        {"seed", static_cast<double>(p.seed)},
                            {"side", sideName(p.side)}, {"walk_begin", sim.walkBegin},
                            {"walk_end", sim.walkEnd},  {"squat_begin", sim.squatBegin},
                            {"squat_end", sim.squatEnd}};
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), imuStream(sim, 1, attrs)});
    out.push_back({QStringLiteral("shank"), imuStream(sim, 2, attrs)});
    out.push_back({QStringLiteral("pelvis"), imuStream(sim, 0, attrs)});
    out.push_back(
        {QStringLiteral("segments"),
         trueSegmentOrientations(
             sim.t, kSegments, {&sim.segments[0].segment, &sim.segments[1].segment, &sim.segments[2].segment}, attrs)});
    out.push_back({QStringLiteral("knee-reference"), trueJointAngles(sim.t, sim.knee, Joint::Knee, p.side, attrs)});
    out.push_back({QStringLiteral("hip-reference"), trueJointAngles(sim.t, sim.hip, Joint::Hip, p.side, attrs)});
    out.push_back(
        {QStringLiteral("mounts"),
         segmentMountTable(kSegments, {sim.segments[0].mount, sim.segments[1].mount, sim.segments[2].mount}, attrs)});
    c.report(1.0);
    return out;
}

}  // namespace athlos::inertial
