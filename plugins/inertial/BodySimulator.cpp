#include "plugins/inertial/BodySimulator.h"

#include "plugins/inertial/LimbSimulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::inertial {

using math::kDeg;
using math::Quat;
using math::Vec3;

namespace {

constexpr double kPi = std::numbers::pi;
// Knee flexion when standing upright; the screw-home coupling acts on the flexion beyond it.
constexpr double kUprightKnee = 0.0;

// Quintic smoothstep on [0, 1] and its first two derivatives (continuous accelerations at phase edges).
double smooth(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
}
double smooth1(double x) { return (x <= 0.0 || x >= 1.0) ? 0.0 : 30.0 * x * x * (1.0 - x) * (1.0 - x); }
double smooth2(double x) { return (x <= 0.0 || x >= 1.0) ? 0.0 : 60.0 * x - 180.0 * x * x + 120.0 * x * x * x; }
// ∫₀ˣ smooth: 2.5x⁴ − 3x⁵ + x⁶ on [0, 1], continued linearly with slope 1 beyond.
double smoothIntegral(double x) {
    if (x <= 0.0) return 0.0;
    if (x >= 1.0) return 0.5 + (x - 1.0);
    return x * x * x * x * (2.5 + x * (-3.0 + x));
}
// Window that ramps up over `ramp` s after `begin` and down over `ramp` s before `end`.
double window(double t, double begin, double end, double ramp) {
    return smooth((t - begin) / ramp) * smooth((end - t) / ramp);
}
// Periodic bump of a cycle: phase p (cycles) near centre c with width s (cycles).
double bump(double p, double c, double s) {
    double d = p - c;
    d -= std::round(d);
    return std::exp(-0.5 * d * d / (s * s));
}

Quat axisRotation(int axis, double angle) { return math::quatFromAxisAngle(Vec3::Unit(axis), angle); }

constexpr std::array<const char*, kBodySegments> kSegmentNames{"sacrum",     "sternum",    "right-thigh", "right-shank",
                                                               "right-foot", "left-thigh", "left-shank",  "left-foot"};
constexpr std::array<const char*, kBodyJoints> kJointNames{"lumbar",   "right-hip", "right-knee", "right-ankle",
                                                           "left-hip", "left-knee", "left-ankle"};
// How strongly vibration and impacts from the skis reach each sensor (feet 1, damped up the chain).
constexpr std::array<double, kBodySegments> kTransmission{0.15, 0.1, 0.3, 0.6, 1.0, 0.3, 0.6, 1.0};

struct Pose {
    std::array<Quat, kBodySegments> segment;  // segment → ENU
    std::array<AnatomicalAngles, kBodyJoints> angles;
    Vec3 pelvisOrigin = Vec3::Zero();  // ENU, including the translation along the path
    unsigned char phase = 0;
};

class Script {
public:
    explicit Script(const BodySimulatorParams& p) : p_(p) {
        squatBegin = p.uprightDuration;
        squatEnd = squatBegin + p.squats * p.squatDuration;
        // Optional blocks; with none of them calibrationEnd = squatEnd exactly.
        double c = squatEnd;
        const auto block = [&](int count, double duration, double& b, double& e) {
            b = e = c;
            if (count <= 0) return;
            b = c + p.calibrationPause;
            e = b + count * duration;
            c = e;
        };
        block(p.trunkRotations, p.trunkRotationDuration, trunkBegin, trunkEnd);
        block(p.hipAbductions, p.hipAbductionDuration, rightBegin, rightEnd);
        block(p.hipAbductions, p.hipAbductionDuration, leftBegin, leftEnd);
        // Arm swings: pause, grip, pause, swings, pause, let go (the grip is the arms' own movement).
        armBegin = armEnd = c;
        if (p.armSwings > 0) {
            armBegin = c + p.calibrationPause + p.armGrip + p.calibrationPause;
            armEnd = armBegin + p.armSwings * p.armSwingDuration;
            c = armEnd + p.calibrationPause + p.armGrip;
        }
        motionBegin = c + p.standDuration;
        motionEnd = motionBegin + p.motionDuration;
        end = motionEnd + p.standDuration;
        skiing = p.scenario == BodyScenario::Skiing;
        walking = p.scenario == BodyScenario::Walking;
        if (p.scenario == BodyScenario::Squats) motionEnd = motionBegin;
        speed = skiing ? p.skiSpeed * std::cos(p.slope) : walking ? p.walkSpeed : 0.0;
        ramp = std::min(skiing ? 5.0 : 1.0, 0.25 * (motionEnd - motionBegin));
    }

    // Distance along the fall line (horizontal, m): speed ramps up after motionBegin and down before motionEnd.
    double distance(double t) const {
        if (motionEnd <= motionBegin) return 0.0;
        return speed * ramp *
               (smoothIntegral((t - motionBegin) / ramp) - smoothIntegral((t - motionEnd + ramp) / ramp));
    }
    double velocity(double t) const {
        if (motionEnd <= motionBegin) return 0.0;
        return speed * (smooth((t - motionBegin) / ramp) - smooth((t - motionEnd + ramp) / ramp));
    }
    // Lateral path Y(X) = A s(X/D) sin(πX/D) and its derivatives in X (turn amplitude ramps in over one turn).
    void lateral(double x, double& y, double& dy, double& ddy) const {
        const double a = skiing ? p_.turnAmplitude : 0.0, d = p_.turnDistance, w = kPi / d;
        const double s = smooth(x / d), s1 = smooth1(x / d) / d, s2 = smooth2(x / d) / (d * d);
        const double sn = std::sin(w * x), cs = std::cos(w * x);
        y = a * s * sn;
        dy = a * (s1 * sn + s * w * cs);
        ddy = a * (s2 * sn + 2.0 * s1 * w * cs - s * w * w * sn);
    }

    Pose pose(double t) const {
        Pose pose;
        const double x = distance(t), v = velocity(t);
        double y = 0, dy = 0, ddy = 0;
        lateral(x, y, dy, ddy);
        const double psi0 = p_.initialHeading;
        const Vec3 fall(std::cos(psi0), std::sin(psi0), 0.0), left(-std::sin(psi0), std::cos(psi0), 0.0);
        const double psi = psi0 + std::atan(dy);
        const double climb = skiing ? -std::tan(p_.slope) : 0.0;

        std::array<AnatomicalAngles, kBodyJoints>& a = pose.angles;
        // Upright posture: the anatomical neutral, as the functional calibration assumes (it takes the
        // segments' long axes from gravity while standing upright, spec §4).
        for (int s = 0; s < 2; ++s) a[2 + 3 * s].flexion = kUprightKnee;
        double pelvisRotation = 0, pelvisTilt = 0, pelvisObliquity = 0, drop = 0, back = 0;
        if (t > squatBegin && t < squatEnd) {
            pose.phase = 1;
            const double u = std::fmod(t - squatBegin, p_.squatDuration) / p_.squatDuration;
            const double d = std::pow(std::sin(kPi * u), 2);
            for (int s = 0; s < 2; ++s) {
                const double asym = s == 0 ? 1.0 : 0.92;
                a[1 + 3 * s].flexion += asym * 80.0 * d * kDeg;
                a[1 + 3 * s].abduction += 2.0 * d * kDeg;
                a[2 + 3 * s].flexion += asym * 90.0 * d * kDeg;
                a[2 + 3 * s].rotation += 6.0 * d * kDeg;
                // The foot stays flat: dorsiflexion = knee − hip flexion + the pelvis' anterior tilt.
                a[3 + 3 * s].flexion += asym * (90.0 - 80.0) * d * kDeg + 20.0 * d * kDeg;
            }
            a[0].flexion = 25.0 * d * kDeg;
            pelvisTilt = -20.0 * d * kDeg;
            drop = 0.35 * d;
            back = 0.15 * d;
        } else if (t > trunkBegin && t < trunkEnd) {
            pose.phase = 4;
            // Axial rotation to the right first (negative: JointAngles counts rotation to the left),
            // sin(2πu)·sin²(πu) (peak 3√3/8) starts and ends each repetition at rest.
            const double u = std::fmod(t - trunkBegin, p_.trunkRotationDuration) / p_.trunkRotationDuration;
            const double peak = 3.0 * std::sqrt(3.0) / 8.0;
            a[0].rotation =
                -p_.trunkRotationAmplitude / peak * std::sin(2.0 * kPi * u) * std::pow(std::sin(kPi * u), 2);
        } else if ((t > rightBegin && t < rightEnd) || (t > leftBegin && t < leftEnd)) {
            const bool right = t < rightEnd;
            pose.phase = right ? 5 : 6;
            // Abduction of the straight leg and back (knee and ankle fixed, the foot lifted).
            const double u =
                std::fmod(t - (right ? rightBegin : leftBegin), p_.hipAbductionDuration) / p_.hipAbductionDuration;
            a[right ? 1 : 4].abduction += p_.hipAbductionAmplitude * std::pow(std::sin(kPi * u), 2);
        } else if (t > armBegin && t < armEnd) {
            pose.phase = 7;  // the arms swing (body::simulateWholeBody); the body stands
        } else if (t > motionBegin && t < motionEnd && walking) {
            pose.phase = 2;
            const double e = window(t, motionBegin, motionEnd, 1.0);
            const double cycles = (t - motionBegin) / p_.gaitPeriod;
            for (int s = 0; s < 2; ++s) {
                const double c = cycles + 0.5 * s, phi = 2.0 * kPi * c;
                AnatomicalAngles& hip = a[1 + 3 * s];
                AnatomicalAngles& knee = a[2 + 3 * s];
                AnatomicalAngles& ankle = a[3 + 3 * s];
                hip.flexion += e * (6.0 + 22.0 * std::sin(phi)) * kDeg;
                hip.abduction += e * 4.0 * std::sin(phi + 1.2) * kDeg;
                hip.rotation += e * 5.0 * std::sin(phi + 2.1) * kDeg;
                knee.flexion += e * (14.0 * bump(c, 0.12, 0.07) + 56.0 * bump(c, 0.72, 0.11)) * kDeg;
                knee.abduction += e * 2.0 * std::sin(phi + 0.7) * kDeg;
                knee.rotation += e * 5.0 * std::sin(phi - 0.4) * kDeg + 0.08 * (knee.flexion - kUprightKnee);
                ankle.flexion += e * (8.0 * std::sin(phi + 0.8) - 12.0 * bump(c, 0.62, 0.06)) * kDeg;
                ankle.abduction += e * 2.0 * std::sin(phi) * kDeg;
            }
            const double phi = 2.0 * kPi * cycles;
            a[0] = {e * 2.0 * std::sin(2.0 * phi) * kDeg, e * 2.0 * std::cos(phi) * kDeg,
                    e * 4.0 * std::sin(phi) * kDeg};
            pelvisRotation = e * 5.0 * std::sin(phi) * kDeg;
            pelvisObliquity = e * 3.0 * std::cos(phi) * kDeg;
            pelvisTilt = e * 2.0 * std::sin(2.0 * phi) * kDeg;
            drop = -e * 0.02 * std::cos(2.0 * phi);
        } else if (t > motionBegin && t < motionEnd && skiing) {
            pose.phase = 3;
            // Ski posture ramps in over 2 s; turn-driven motion grows with the speed.
            const double e = window(t, motionBegin, motionEnd, 2.0), g = v / std::max(speed, 1e-9);
            const double phi = kPi * x / p_.turnDistance, u = g * std::sin(phi);
            const double absorb = g * std::sin(2.0 * kPi * 1.7 * t);
            for (int s = 0; s < 2; ++s) {
                const double sigma = s == 0 ? 1.0 : -1.0;  // the outside leg alternates with the turns
                AnatomicalAngles& hip = a[1 + 3 * s];
                AnatomicalAngles& knee = a[2 + 3 * s];
                AnatomicalAngles& ankle = a[3 + 3 * s];
                hip.flexion += (e * 46.0 + 12.0 * sigma * u + 3.0 * absorb) * kDeg;
                hip.abduction += (e * 3.0 + 7.0 * sigma * u) * kDeg;
                hip.rotation += (8.0 * sigma * u + 2.0 * std::cos(phi) * g) * kDeg;
                knee.flexion += (e * 50.0 + 15.0 * sigma * u + 4.0 * absorb) * kDeg;
                knee.abduction += (2.0 * sigma * u) * kDeg;
                knee.rotation += (5.0 * sigma * u) * kDeg + 0.08 * (knee.flexion - kUprightKnee);
                ankle.flexion += (e * 14.0 + 4.0 * sigma * u + 1.5 * absorb) * kDeg;
                ankle.abduction += 2.0 * sigma * u * kDeg;
            }
            a[0] = {(e * 25.0 + 4.0 * g * std::cos(2.0 * phi)) * kDeg, 6.0 * u * kDeg, 6.0 * u * kDeg};
            // Lean into the turn: the lateral acceleration is ≈ Y''(X) Ẋ² (to the left for Y'' > 0).
            pelvisObliquity = 0.6 * std::atan(ddy * v * v / p_.gravity);
            pelvisRotation = -8.0 * u * kDeg;
            pelvisTilt = -15.0 * e * kDeg;
            drop = e * 0.25 + 0.05 * g * std::cos(2.0 * phi);
            back = e * 0.1;
        }
        // ISB pelvis frame in ENU facing ψ: X → (cos ψ, sin ψ, 0), Y → up, Z → right.
        const Quat pelvis = (math::headingRotation(psi) * axisRotation(0, kPi / 2) * axisRotation(1, pelvisRotation) *
                             axisRotation(2, pelvisTilt) * axisRotation(0, pelvisObliquity))
                                .normalized();
        std::array<Quat, kBodySegments>& q = pose.segment;
        q[0] = pelvis;
        q[1] = (pelvis * relativeFromAnatomical(a[0], Joint::Trunk, Side::Right)).normalized();
        for (int s = 0; s < 2; ++s) {
            const Side side = s == 0 ? Side::Right : Side::Left;
            q[2 + 3 * s] = (pelvis * relativeFromAnatomical(a[1 + 3 * s], Joint::Hip, side)).normalized();
            q[3 + 3 * s] = (q[2 + 3 * s] * relativeFromAnatomical(a[2 + 3 * s], Joint::Knee, side)).normalized();
            q[4 + 3 * s] = (q[3 + 3 * s] * relativeFromAnatomical(a[3 + 3 * s], Joint::Ankle, side)).normalized();
        }
        const Vec3 heading(std::cos(psi), std::sin(psi), 0.0);
        pose.pelvisOrigin = x * fall + y * left + Vec3(0.0, 0.0, x * climb + 0.95 - drop) - back * heading;
        return pose;
    }

    // Body geometry in segment coordinates (m): where each joint sits in its proximal segment (the
    // distal segment's origin) and where each sensor sits in its segment.
    static Vec3 jointInProximal(int j) {
        switch (j) {
            case 0:
                return {-0.03, 0.10, 0.0};  // lumbar joint in the pelvis
            case 1:
                return {0.0, -0.08, 0.09};  // right hip
            case 4:
                return {0.0, -0.08, -0.09};  // left hip
            case 2:
            case 5:
                return {0.0, -0.42, 0.0};  // knee in the thigh
            default:
                return {0.0, -0.40, 0.0};  // ankle in the shank
        }
    }
    static Vec3 sensorInSegment(int s) {
        const double lat = s >= 5 ? -1.0 : 1.0;
        switch (s) {
            case 0:
                return {-0.12, 0.02, 0.0};  // sacrum
            case 1:
                return {0.12, 0.30, 0.0};  // sternum, from the lumbar joint
            case 2:
            case 5:
                return {0.0, -0.20, lat * 0.08};  // lateral thigh
            case 3:
            case 6:
                return {0.03, -0.15, lat * 0.04};  // anterolateral shank
            default:
                return {0.09, -0.05, lat * 0.02};  // top of the foot / boot
        }
    }
    static Quat mount(int s) {
        const double lat = s >= 5 ? -1.0 : 1.0;
        const Side side = lat > 0 ? Side::Right : Side::Left;
        switch (s) {
            case 0:
                return simulatedMount(LimbSegment::Pelvis, side);
            case 1:  // sternum: x up, z out of the chest (anterior)
                return mountFromAxes(Vec3::UnitY(), Vec3::UnitX(), Vec3(0.07, -0.05, 0.10));
            case 2:
            case 5:
                return simulatedMount(LimbSegment::Thigh, side);
            case 3:
            case 6:
                return simulatedMount(LimbSegment::Shank, side);
            default:  // foot: x forward, z up, twisted a little
                return mountFromAxes(Vec3::UnitX(), Vec3::UnitY(), Vec3(0.06 * lat, 0.08, -0.12 * lat));
        }
    }
    static int parentJointOf(int s) { return s == 0 ? -1 : s - 1; }  // segment s hangs at joint s − 1

    struct Points {
        std::array<Vec3, kBodyJoints> joint;
        std::array<Vec3, kBodySegments> sensor;
    };
    Points points(const Pose& p) const {
        Points r;
        const std::array<Quat, kBodySegments>& q = p.segment;
        r.joint[0] = p.pelvisOrigin + q[0] * jointInProximal(0);
        for (int s = 0; s < 2; ++s) {
            const int o = 3 * s;
            r.joint[1 + o] = p.pelvisOrigin + q[0] * jointInProximal(1 + o);
            r.joint[2 + o] = r.joint[1 + o] + q[2 + o] * jointInProximal(2 + o);
            r.joint[3 + o] = r.joint[2 + o] + q[3 + o] * jointInProximal(3 + o);
        }
        r.sensor[0] = p.pelvisOrigin + q[0] * sensorInSegment(0);
        for (int s = 1; s < kBodySegments; ++s) r.sensor[s] = r.joint[parentJointOf(s)] + q[s] * sensorInSegment(s);
        return r;
    }

    double squatBegin = 0, squatEnd = 0, motionBegin = 0, motionEnd = 0, end = 0, speed = 0, ramp = 1;
    double trunkBegin = 0, trunkEnd = 0, rightBegin = 0, rightEnd = 0, leftBegin = 0, leftEnd = 0;
    double armBegin = 0, armEnd = 0;
    bool skiing = false, walking = false;

private:
    const BodySimulatorParams& p_;
};

}  // namespace

QString bodySegmentName(BodySegment segment) { return QLatin1String(kSegmentNames[static_cast<int>(segment)]); }
QString bodyJointName(BodyJoint joint) { return QLatin1String(kJointNames[static_cast<int>(joint)]); }

Expected<BodyScenario> parseBodyScenario(const QString& name) {
    if (name == QLatin1String("squats")) return BodyScenario::Squats;
    if (name == QLatin1String("walking")) return BodyScenario::Walking;
    if (name == QLatin1String("skiing")) return BodyScenario::Skiing;
    return makeError(QStringLiteral("scenario: '%1' is not one of squats, walking, skiing").arg(name));
}

BodyJointInfo bodyJointInfo(BodyJoint joint) {
    const int j = static_cast<int>(joint);
    if (j == 0) return {BodySegment::Sacrum, BodySegment::Sternum, Joint::Trunk, Side::Right};
    const Side side = j <= 3 ? Side::Right : Side::Left;
    const int o = j <= 3 ? 0 : 3;
    const int k = j - o;  // 1 hip, 2 knee, 3 ankle
    const BodySegment proximal = k == 1 ? BodySegment::Sacrum : static_cast<BodySegment>(k + o);
    return {proximal, static_cast<BodySegment>(k + 1 + o),
            k == 1   ? Joint::Hip
            : k == 2 ? Joint::Knee
                     : Joint::Ankle,
            side};
}

BodySimulation simulateBody(const BodySimulatorParams& params) {
    const Script script(params);
    BodySimulation sim;
    sim.uprightEnd = script.squatBegin;
    sim.squatBegin = script.squatBegin;
    sim.squatEnd = script.squatEnd;
    sim.motionBegin = script.motionBegin;
    sim.motionEnd = script.motionEnd;
    sim.trunkBegin = script.trunkBegin;
    sim.trunkEnd = script.trunkEnd;
    sim.rightAbductionBegin = script.rightBegin;
    sim.rightAbductionEnd = script.rightEnd;
    sim.leftAbductionBegin = script.leftBegin;
    sim.leftAbductionEnd = script.leftEnd;
    sim.armSwingBegin = script.armBegin;
    sim.armSwingEnd = script.armEnd;
    const double dt = 1.0 / params.rate;
    const auto n = static_cast<std::size_t>(std::floor(script.end * params.rate)) + 1;
    std::array<ImuErrors, kBodySegments> errors;
    ImuErrorSource source(params.seed, params);
    for (int s = 0; s < kBodySegments; ++s) {
        BodySensor& seg = sim.sensors[s];
        seg.mount = Script::mount(s);
        errors[s] = source.draw();
        seg.gyrBias = errors[s].gyrBias;
        seg.gyrDrift = errors[s].gyrDrift;
        seg.accBias = errors[s].accBias;
        seg.acc.resize(n);
        seg.gyr.resize(n);
        seg.sensor.resize(n);
        seg.segment.resize(n);
        seg.position.resize(n);
    }
    // Impacts: Poisson arrivals while skiing at speed.
    std::vector<double>& impacts = sim.impacts;
    if (script.skiing && params.impactRate > 0.0) {
        std::exponential_distribution<double> gap(params.impactRate);
        for (double t = script.motionBegin + script.ramp + gap(source.engine()); t < script.motionEnd - script.ramp;
             t += gap(source.engine()))
            impacts.push_back(t);
    }
    // Sensor-to-joint vectors in sensor coordinates.
    for (int j = 0; j < kBodyJoints; ++j) {
        const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
        const int p = static_cast<int>(info.proximal), d = static_cast<int>(info.distal);
        // The proximal sensor's segment is either the pelvis (joint origin from the pelvis origin) or
        // the segment whose distal end is this joint.
        const Vec3 jointInProximalSegment = p == 0 ? Script::jointInProximal(j) - Script::sensorInSegment(0)
                                                   : Script::jointInProximal(j) - Script::sensorInSegment(p);
        sim.joints[j].proximalToJoint = sim.sensors[p].mount * jointInProximalSegment;
        sim.joints[j].distalToJoint = sim.sensors[d].mount * (-Script::sensorInSegment(d));
        sim.joints[j].centre.resize(n);
        sim.joints[j].angles.resize(n);
    }
    sim.t.resize(n);
    sim.phase.resize(n);
    const double h = 1e-3;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = double(k) * dt;
        sim.t[k] = t;
        const Pose pose = script.pose(t), before = script.pose(t - dt);
        sim.phase[k] = pose.phase;
        const auto p0 = script.points(pose), pm = script.points(script.pose(t - h)),
                   pp = script.points(script.pose(t + h));
        for (int j = 0; j < kBodyJoints; ++j) {
            sim.joints[j].centre[k] = p0.joint[j];
            sim.joints[j].angles[k] = pose.angles[j];
        }
        const double g = script.velocity(t) / std::max(script.speed, 1e-9);
        double impact = 0.0;
        for (double ti : impacts)
            if (t >= ti && t < ti + 0.01) impact = params.impactPeak * std::sin(kPi * (t - ti) / 0.01);
        const double driftShare = ImuErrorSource::driftShare(t, script.motionBegin);
        for (int s = 0; s < kBodySegments; ++s) {
            BodySensor& seg = sim.sensors[s];
            const Quat sensor = (pose.segment[s] * seg.mount.conjugate()).normalized();
            const Quat previous = (before.segment[s] * seg.mount.conjugate()).normalized();
            seg.segment[k] = pose.segment[s];
            seg.sensor[k] = sensor;
            seg.position[k] = p0.sensor[s];
            const Vec3 omega = idealRate(previous, sensor, dt);
            Vec3 f = idealSpecificForce(sensor, pm.sensor[s], p0.sensor[s], pp.sensor[s], h, params.gravity);
            if (script.skiing)
                f += kTransmission[s] * (g * params.vibration * ImuErrorSource::shake(errors[s], t) +
                                         sensor.conjugate() * Vec3(0, 0, impact));
            source.measure(errors[s], omega, f, driftShare, seg.gyr[k], seg.acc[k]);
        }
    }
    return sim;
}

BodyPose bodyPoseAt(const BodySimulatorParams& params, double t) {
    const Script script(params);
    const Pose pose = script.pose(t);
    BodyPose out;
    out.segment = pose.segment;
    out.joint = script.points(pose).joint;
    out.speedShare = script.velocity(t) / std::max(script.speed, 1e-9);
    return out;
}

Vec3 idealRate(const Quat& previous, const Quat& current, double dt) {
    return math::rotationVectorFromQuat(previous.conjugate() * current) / dt;
}

Vec3 idealSpecificForce(const Quat& sensor, const Vec3& before, const Vec3& at, const Vec3& after, double h,
                        double gravity) {
    const Vec3 a = (after - 2.0 * at + before) / (h * h);
    const Vec3 gravityUp(0.0, 0.0, gravity);
    return sensor.conjugate() * (a + gravityUp);
}

Vec3 ImuErrorSource::normal3() {
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = normal_(rng_);
    return v;
}

Vec3 ImuErrorSource::uniform3() {
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = uniform_(rng_);
    return v;
}

ImuErrors ImuErrorSource::draw() {
    ImuErrors e;
    e.gyrBias = uniform3() * params_.gyrBias;
    const Vec3 d = normal3();
    e.gyrDrift = d.normalized() * params_.gyrDrift;
    e.accBias = uniform3() * params_.accBias;
    e.gyrScale = Vec3::Ones() + uniform3() * params_.gyrScale;
    e.accScale = Vec3::Ones() + uniform3() * params_.accScale;
    for (int i = 0; i < 3; ++i) e.gSensitivity.row(i) = uniform3().transpose() * params_.gSensitivity;
    for (int i = 0; i < 3; ++i) {
        std::uniform_real_distribution<double> f(15.0, 30.0), ph(0.0, 2.0 * kPi);
        e.vibration[3 * i] = f(rng_);
        e.vibration[3 * i + 1] = ph(rng_);
        e.vibration[3 * i + 2] = 0.5 + 0.5 * std::abs(uniform_(rng_));
    }
    return e;
}

Vec3 ImuErrorSource::shake(const ImuErrors& e, double t) {
    Vec3 v;
    for (int i = 0; i < 3; ++i)
        v[i] = e.vibration[3 * i + 2] * std::sin(2.0 * kPi * e.vibration[3 * i] * t + e.vibration[3 * i + 1]);
    return v;
}

double ImuErrorSource::driftShare(double t, double motionBegin) {
    const double ramp = 20.0;  // s over which the bias changes by gyrDrift once the motion starts
    return smooth((t - motionBegin) / ramp);
}

void ImuErrorSource::measure(const ImuErrors& e, const Vec3& omega, const Vec3& f, double driftShare, Vec3& gyr,
                             Vec3& acc) {
    gyr = e.gyrScale.cwiseProduct(omega) + e.gyrBias + driftShare * e.gyrDrift + e.gSensitivity * f +
          normal3() * params_.gyrNoise;
    acc = e.accScale.cwiseProduct(f) + e.accBias + normal3() * params_.accNoise;
}

}  // namespace athlos::inertial
