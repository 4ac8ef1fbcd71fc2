#include "plugins/body/WholeBodySimulator.h"

#include "plugins/inertial/LimbSimulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::body {

using inertial::BodyJoint;
using inertial::BodySegment;

namespace {
Quat about(int axis, double angle) { return math::quatFromAxisAngle(Vec3::Unit(axis), angle); }

constexpr std::array<const char*, kUpperSensors> kUpperNames{"head",          "upper-back",     "right-upper-arm",
                                                             "right-forearm", "left-upper-arm", "left-forearm"};
// How much of the ski vibration and impacts reaches each sensor (BodySimulator: feet 1, sternum 0.1).
constexpr std::array<double, kUpperSensors> kTransmission{0.08, 0.1, 0.08, 0.06, 0.08, 0.06};

// Cosine ramp 0 → 1 over x ∈ [0, 1].
double ramp(double x) { return 0.5 - 0.5 * std::cos(std::numbers::pi * std::clamp(x, 0.0, 1.0)); }

// The calibration blocks' times (BodySimulation) and durations (BodySimulatorParams).
struct Timing {
    double squatBegin = 0, squatEnd = 0, squatDuration = 1, armBegin = 0, armEnd = 0, armDuration = 1, grip = 1,
           pause = 0, motionBegin = 0;
};

// Head and arm orientations (segment → ENU) riding on the thorax at time t.
struct Upper {
    Quat head = Quat::Identity();
    std::array<Quat, 2> upperArm{Quat::Identity(), Quat::Identity()}, forearm{Quat::Identity(), Quat::Identity()};
};
Upper upperAt(const WholeBodyParams& p, const Timing& tm, const Quat& thorax, double t) {
    Upper u;
    const double ph = 2.0 * std::numbers::pi * p.swingFrequency * t;
    if (!p.calibrationPosture) {
        u.head = thorax * about(2, p.headNod * std::sin(0.7 * ph));
        for (int side = 0; side < 2; ++side) {
            const double sign = side == 0 ? 1.0 : -1.0, phase = side == 0 ? 0.0 : std::numbers::pi;
            // Flexion about Z, then a little abduction about X (away from the body on both sides).
            u.upperArm[side] = thorax * about(2, p.shoulderFlexion + p.shoulderSwing * std::sin(ph + phase)) *
                               about(0, sign * p.abductionSwing * (1.0 + std::sin(1.3 * ph)));
            u.forearm[side] = u.upperArm[side] * about(2, p.elbowFlexion + p.elbowSwing * std::sin(ph + phase + 0.5));
        }
        return u;
    }
    // The motion's swing fades in after the motion begins; before it the calibration posture (header).
    const double e = ramp((t - tm.motionBegin) / 2.0);
    double squat = 0.0, swing = 0.0;
    if (t > tm.squatBegin && t < tm.squatEnd) {
        const double x = std::fmod(t - tm.squatBegin, tm.squatDuration) / tm.squatDuration;
        squat = std::pow(std::sin(std::numbers::pi * x), 2);  // the squat's depth shape (BodySimulator)
    }
    if (t > tm.armBegin && t < tm.armEnd) {
        const double x = std::fmod(t - tm.armBegin, tm.armDuration) / tm.armDuration;
        swing = std::pow(std::sin(std::numbers::pi * x), 2);  // up to the horizontal and back, arms first up
    }
    // Grip: pronation ramps in during the pause before the swings and out in the pause after them.
    const double grip =
        ramp((t - (tm.armBegin - tm.pause - tm.grip)) / tm.grip) * (1.0 - ramp((t - (tm.armEnd + tm.pause)) / tm.grip));
    // Forward head flexion turns the head about −Z (JointAngles.h: forward lean −Z).
    u.head = thorax * about(2, e * p.headNod * std::sin(0.7 * ph) - p.headSquatFlexion * squat);
    for (int side = 0; side < 2; ++side) {
        const double sign = side == 0 ? 1.0 : -1.0, phase = side == 0 ? 0.0 : std::numbers::pi;
        u.upperArm[side] =
            thorax *
            about(2, e * (p.shoulderFlexion + p.shoulderSwing * std::sin(ph + phase)) + p.armSwingAmplitude * swing) *
            about(0, sign * (e * p.abductionSwing * (1.0 + std::sin(1.3 * ph)) + p.armSwingAbduction * swing));
        // Thumbs medially: the right forearm turns about +Y (its X, anterior, to the left), the left about −Y.
        u.forearm[side] = u.upperArm[side] *
                          about(2, e * (p.elbowFlexion + p.elbowSwing * std::sin(ph + phase + 0.5))) *
                          about(1, sign * 0.5 * std::numbers::pi * grip);
    }
    return u;
}

// Where each upper sensor sits in its segment (segment coordinates, m, from the segment's proximal joint)
// and its mount: off the joint axes and turned (LimbSimulator's mountFromAxes), as a strap never sits square.
Vec3 sensorInSegment(const Anthropometry& a, int s) {
    const double lat = s >= 4 ? -1.0 : 1.0;  // lateral side of the right (+Z) or left (−Z) arm
    switch (s) {
        case 0:  // back of the head / helmet
            return 0.7 * a[Segment::Head].distal + Vec3(-0.09, 0.0, 0.0);
        case 1:  // upper back at T2–C7, on the thorax below the cervical joint
            return 0.9 * a[Segment::Thorax].distal + Vec3(-0.08, 0.0, 0.0);
        case 2:
        case 4:  // lateral upper arm, mid-length
            return 0.5 * a.segments[s == 2 ? 3 : 6].distal + Vec3(0.0, 0.0, lat * 0.045);
        default:  // dorsal wrist (lateral in the upright's palms-on-the-thighs posture)
            return 0.85 * a.segments[s == 3 ? 4 : 7].distal + Vec3(0.0, 0.0, lat * 0.025);
    }
}
Quat sensorMount(int s) {
    const double lat = s >= 4 ? -1.0 : 1.0;
    switch (s) {
        case 0:  // x forward, z up
            return inertial::mountFromAxes(Vec3::UnitX(), Vec3::UnitY(), Vec3(0.05, -0.07, 0.09));
        case 1:  // x up, z out of the back
            return inertial::mountFromAxes(Vec3::UnitY(), -Vec3::UnitX(), Vec3(-0.06, 0.08, 0.05));
        case 2:
        case 4:  // x down the arm, z out of the skin (lateral)
            return inertial::mountFromAxes(-Vec3::UnitY(), lat * Vec3::UnitZ(), Vec3(0.10, -0.07, 0.12 * lat));
        default:  // x towards the hand, z out of the back of the wrist
            return inertial::mountFromAxes(-Vec3::UnitY(), lat * Vec3::UnitZ() + 0.3 * Vec3::UnitX(),
                                           Vec3(-0.08, 0.11, -0.06 * lat));
    }
}

// Every upper sensor's position (ENU) and segment orientation at t.
struct SensorPoints {
    std::array<Vec3, kUpperSensors> position;
    std::array<Quat, kUpperSensors> segment;
};
SensorPoints sensorsAt(const WholeBodyParams& p, const Timing& tm, const Anthropometry& a, double t) {
    const inertial::BodyPose body = inertial::bodyPoseAt(p.body, t);
    const Quat& thorax = body.segment[static_cast<int>(BodySegment::Sternum)];
    const Vec3& lumbar = body.joint[static_cast<int>(BodyJoint::Lumbar)];
    const Upper u = upperAt(p, tm, thorax, t);
    const Vec3 cervical = lumbar + thorax * a[Segment::Thorax].distal;
    SensorPoints r;
    r.segment[0] = u.head;
    r.position[0] = cervical + u.head * sensorInSegment(a, 0);
    r.segment[1] = thorax;
    r.position[1] = lumbar + thorax * sensorInSegment(a, 1);
    for (int side = 0; side < 2; ++side) {
        const double mz = side == 0 ? 1.0 : -1.0;
        const int s = 2 + 2 * side;
        const Vec3 shoulder =
            cervical + thorax * Vec3(a.rightShoulder.x(), a.rightShoulder.y(), mz * a.rightShoulder.z());
        const Vec3 elbow = shoulder + u.upperArm[side] * a.segments[3 + 3 * side].distal;
        r.segment[s] = u.upperArm[side];
        r.position[s] = shoulder + u.upperArm[side] * sensorInSegment(a, s);
        r.segment[s + 1] = u.forearm[side];
        r.position[s + 1] = elbow + u.forearm[side] * sensorInSegment(a, s + 1);
    }
    return r;
}

// The upper sensors' IMU signals with BodySimulator's construction and error model.
void simulateUpperSensors(const WholeBodyParams& p, const Timing& tm, WholeBodySimulation& w) {
    const inertial::BodySimulation& b = w.body;
    const std::size_t n = b.t.size();
    const double dt = 1.0 / p.body.rate, h = 1e-3;
    inertial::ImuErrorSource source(p.body.seed * 104729 + 71, p.body);
    std::array<inertial::ImuErrors, kUpperSensors> errors;
    for (int s = 0; s < kUpperSensors; ++s) {
        inertial::BodySensor& x = w.sensors[s];
        x.mount = sensorMount(s);
        errors[s] = source.draw();
        x.gyrBias = errors[s].gyrBias;
        x.gyrDrift = errors[s].gyrDrift;
        x.accBias = errors[s].accBias;
        for (auto* v : {&x.acc, &x.gyr, &x.position}) v->resize(n);
        x.sensor.resize(n);
        x.segment.resize(n);
    }
    const bool skiing = p.body.scenario == inertial::BodyScenario::Skiing;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = b.t[k];
        const SensorPoints now = sensorsAt(p, tm, w.geometry, t), before = sensorsAt(p, tm, w.geometry, t - dt),
                           pm = sensorsAt(p, tm, w.geometry, t - h), pp = sensorsAt(p, tm, w.geometry, t + h);
        double impact = 0.0;
        for (double ti : b.impacts)
            if (t >= ti && t < ti + 0.01) impact = p.body.impactPeak * std::sin(std::numbers::pi * (t - ti) / 0.01);
        const double speedShare = skiing ? inertial::bodyPoseAt(p.body, t).speedShare : 0.0;
        const double driftShare = inertial::ImuErrorSource::driftShare(t, b.motionBegin);
        for (int s = 0; s < kUpperSensors; ++s) {
            inertial::BodySensor& x = w.sensors[s];
            const Quat sensor = (now.segment[s] * x.mount.conjugate()).normalized();
            const Quat previous = (before.segment[s] * x.mount.conjugate()).normalized();
            x.segment[k] = now.segment[s];
            x.sensor[k] = sensor;
            x.position[k] = now.position[s];
            const Vec3 omega = inertial::idealRate(previous, sensor, dt);
            Vec3 f = inertial::idealSpecificForce(sensor, pm.position[s], now.position[s], pp.position[s], h,
                                                  p.body.gravity);
            if (skiing)
                f += kTransmission[s] * (speedShare * p.body.vibration * inertial::ImuErrorSource::shake(errors[s], t) +
                                         sensor.conjugate() * Vec3(0, 0, impact));
            source.measure(errors[s], omega, f, driftShare, x.gyr[k], x.acc[k]);
        }
    }
}

}  // namespace

QString upperSensorName(UpperSensor sensor) { return QLatin1String(kUpperNames[static_cast<int>(sensor)]); }

Segment upperSensorSegment(UpperSensor sensor) {
    switch (sensor) {
        case UpperSensor::Head:
            return Segment::Head;
        case UpperSensor::UpperBack:
            return Segment::Thorax;
        case UpperSensor::RightUpperArm:
            return Segment::RightUpperArm;
        case UpperSensor::RightForearm:
            return Segment::RightForearm;
        case UpperSensor::LeftUpperArm:
            return Segment::LeftUpperArm;
        case UpperSensor::LeftForearm:
            return Segment::LeftForearm;
    }
    return Segment::Thorax;
}

WholeBodySimulation simulateWholeBody(const WholeBodyParams& p) {
    WholeBodySimulation w;
    w.body = inertial::simulateBody(p.body);
    auto geometry = anthropometry(p.table, p.sex, p.height);
    if (!geometry) return w;  // height out of range: no truth
    w.geometry = *geometry;
    const Anthropometry& a = w.geometry;
    for (int s = 0; s < kSegments; ++s) w.mass[s] = a.segments[s].massFraction * p.mass + p.equipment[s];
    const inertial::BodySimulation& b = w.body;
    const std::size_t n = b.t.size();
    w.segment.resize(n);
    w.lumbar.resize(n);
    w.com.resize(n);
    w.antenna.resize(n);
    const double twoPi = 2.0 * std::numbers::pi;
    Timing tm;
    tm.squatBegin = b.squatBegin;
    tm.squatEnd = b.squatEnd;
    tm.squatDuration = p.body.squatDuration;
    tm.armBegin = b.armSwingBegin;
    tm.armEnd = b.armSwingEnd;
    tm.armDuration = p.body.armSwingDuration;
    tm.grip = p.body.armGrip;
    tm.pause = p.body.calibrationPause;
    tm.motionBegin = b.motionBegin;
    const auto centre = [&](BodyJoint j, std::size_t k) { return b[j].centre[k]; };
    const auto orient = [&](BodySegment s, std::size_t k) { return b[s].segment[k]; };
    double total = 0.0;
    for (double m : w.mass) total += m;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = b.t[k];
        std::array<Quat, kSegments>& q = w.segment[k];
        q[0] = orient(BodySegment::Sacrum, k);
        q[1] = orient(BodySegment::Sternum, k);
        const Upper upper = upperAt(p, tm, q[1], t);
        q[2] = upper.head;
        for (int side = 0; side < 2; ++side) {
            const int o = 3 * side;
            q[3 + o] = upper.upperArm[side];
            q[4 + o] = upper.forearm[side];
            q[5 + o] = q[4 + o];
            q[9 + 3 * side] = orient(side == 0 ? BodySegment::RightThigh : BodySegment::LeftThigh, k);
            q[10 + 3 * side] = orient(side == 0 ? BodySegment::RightShank : BodySegment::LeftShank, k);
            q[11 + 3 * side] = orient(side == 0 ? BodySegment::RightFoot : BodySegment::LeftFoot, k);
        }
        // True points in ENU: legs and lumbar joint from the simulator, the rest from the table on the thorax.
        const Vec3 lumbar = centre(BodyJoint::Lumbar, k);
        const Vec3 hip[2] = {centre(BodyJoint::RightHip, k), centre(BodyJoint::LeftHip, k)};
        const Vec3 knee[2] = {centre(BodyJoint::RightKnee, k), centre(BodyJoint::LeftKnee, k)};
        const Vec3 ankle[2] = {centre(BodyJoint::RightAnkle, k), centre(BodyJoint::LeftAnkle, k)};
        const Vec3 cervical = lumbar + q[1] * a[Segment::Thorax].distal;
        const Vec3 vertex = cervical + q[2] * a[Segment::Head].distal;
        Vec3 sum = Vec3::Zero();
        const auto add = [&](Segment s, const Vec3& c) { sum += w.mass[static_cast<int>(s)] * c; };
        // Pelvis: Dumas from the lumbar joint, de Leva from the mid-hip point.
        const Vec3 pelvisOrigin = a[Segment::Pelvis].comFromMidHip ? Vec3(0.5 * (hip[0] + hip[1])) : lumbar;
        add(Segment::Pelvis, pelvisOrigin + q[0] * a[Segment::Pelvis].com);
        add(Segment::Thorax, lumbar + q[1] * a[Segment::Thorax].com);
        add(Segment::Head, cervical + q[2] * a[Segment::Head].com);
        for (int side = 0; side < 2; ++side) {
            const int o = 3 * side;
            const double mz = side == 0 ? 1.0 : -1.0;
            const Vec3 shoulder =
                cervical + q[1] * Vec3(a.rightShoulder.x(), a.rightShoulder.y(), mz * a.rightShoulder.z());
            const Vec3 elbow = shoulder + q[3 + o] * a.segments[3 + o].distal;
            const Vec3 wrist = elbow + q[4 + o] * a.segments[4 + o].distal;
            add(static_cast<Segment>(3 + o), shoulder + q[3 + o] * a.segments[3 + o].com);
            add(static_cast<Segment>(4 + o), elbow + q[4 + o] * a.segments[4 + o].com);
            add(static_cast<Segment>(5 + o), wrist + q[5 + o] * a.segments[5 + o].com);
            // Thigh and shank: the table's fraction of the simulator's own joint-to-joint vector, plus the
            // anterior/lateral offsets in the segment frame.
            const int th = 9 + 3 * side, sh = 10 + 3 * side, ft = 11 + 3 * side;
            const auto limb = [&](int s, const Vec3& from, const Vec3& to) {
                const SegmentParameters& sp = a.segments[s];
                const double f = sp.com.y() / sp.distal.y();
                add(static_cast<Segment>(s), from + f * (to - from) + q[s] * Vec3(sp.com.x(), 0.0, sp.com.z()));
            };
            limb(th, hip[side], knee[side]);
            limb(sh, knee[side], ankle[side]);
            add(static_cast<Segment>(ft), ankle[side] + q[ft] * a.segments[ft].com);
        }
        w.lumbar[k] = lumbar;
        w.com[k] = sum / total - lumbar;
        w.antenna[k] = vertex + q[2] * p.antennaOffset;
    }
    // GNSS: every (rate / gnssRate)-th sample, white noise plus a slowly varying offset (two sinusoids of
    // random phase per axis, periods of tens of seconds: the satellite-constellation error of spec §10).
    std::mt19937_64 rng(p.body.seed * 7919 + 13);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> phase(0.0, twoPi);
    std::array<double, 6> phases{};
    for (double& v : phases) v = phase(rng);
    const std::size_t step = std::max<std::size_t>(1, std::size_t(std::lround(p.body.rate / p.gnssRate)));
    for (std::size_t k = 0; k < n; k += step) {
        const double t = b.t[k];
        Vec3 e;
        for (int i = 0; i < 3; ++i)
            e[i] = p.gnssNoise * normal(rng) +
                   p.gnssWander * 0.5 *
                       (std::sin(twoPi * t / 47.0 + phases[i]) + std::sin(twoPi * t / 19.0 + phases[3 + i]));
        w.gnssT.push_back(t);
        w.gnss.push_back(w.antenna[k] + e);
    }
    simulateUpperSensors(p, tm, w);
    return w;
}

}  // namespace athlos::body
