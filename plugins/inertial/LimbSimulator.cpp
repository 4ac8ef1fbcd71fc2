#include "plugins/inertial/LimbSimulator.h"

#include "core/math/Angles.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::inertial {

using math::kDeg;
using math::Quat;
using math::Vec3;

namespace {

// Quintic smoothstep on [0, 1] (zero first and second derivative at both ends, so accelerations
// stay continuous when a phase starts or stops) and its derivative.
double smooth(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * x * (10.0 + x * (-15.0 + 6.0 * x));
}
double smoothDerivative(double x) {
    if (x <= 0.0 || x >= 1.0) return 0.0;
    return 30.0 * x * x * (1.0 - x) * (1.0 - x);
}

// Periodic bump of the gait cycle: phase p (cycles) near centre c with width s (cycles).
double bump(double p, double c, double s) {
    double d = p - c;
    d -= std::round(d);
    return std::exp(-0.5 * d * d / (s * s));
}

Quat axisRotation(int axis, double angle) { return math::quatFromAxisAngle(Vec3::Unit(axis), angle); }

struct Pose {
    Quat pelvis, thigh, shank;
    Vec3 pelvisOrigin;  // without the walking translation (handled analytically)
    AnatomicalAngles hip, knee;
    unsigned char phase = 0;
};

class Script {
public:
    explicit Script(const LimbSimulatorParams& p) : p_(p) {
        walkBegin = p.standDuration;
        walkEnd = walkBegin + p.walkDuration;
        squatBegin = walkEnd + p.standDuration;
        squatEnd = squatBegin + p.squats * p.squatDuration;
        end = squatEnd + p.standDuration;
        lateral = p.side == Side::Right ? 1.0 : -1.0;
    }

    // Walking envelope: ramps in and out over 1 s so the gait starts and stops smoothly.
    double envelope(double t) const { return smooth(t - walkBegin) * smooth(walkEnd - t); }
    double envelopeDerivative(double t) const {
        return smoothDerivative(t - walkBegin) * smooth(walkEnd - t) -
               smooth(t - walkBegin) * smoothDerivative(walkEnd - t);
    }
    double heading(double t) const {
        return p_.initialHeading + p_.walkTurn * smooth((t - walkBegin) / (walkEnd - walkBegin));
    }
    double headingRate(double t) const {
        return p_.walkTurn * smoothDerivative((t - walkBegin) / (walkEnd - walkBegin)) / (walkEnd - walkBegin);
    }
    // Acceleration of the walking translation: v = s(t) (cos ψ, sin ψ, 0).
    Vec3 walkAcceleration(double t) const {
        const double s = p_.walkSpeed * envelope(t), ds = p_.walkSpeed * envelopeDerivative(t);
        const double psi = heading(t), dpsi = headingRate(t);
        return ds * Vec3(std::cos(psi), std::sin(psi), 0.0) + s * dpsi * Vec3(-std::sin(psi), std::cos(psi), 0.0);
    }

    Pose pose(double t) const {
        Pose pose;
        const double psi = heading(t);
        double pelvisRotation = 0, pelvisTilt = 0, pelvisObliquity = 0, drop = 0, back = 0, bounce = 0;
        if (t > walkBegin && t < walkEnd) {
            pose.phase = 1;
            const double e = envelope(t);
            const double cycles = (t - walkBegin) / p_.gaitPeriod, phi = 2.0 * std::numbers::pi * cycles;
            pose.hip.flexion = e * (10.0 + 22.0 * std::sin(phi)) * kDeg;
            pose.hip.abduction = e * 4.0 * std::sin(phi + 1.2) * kDeg;
            pose.hip.rotation = e * 5.0 * std::sin(phi + 2.1) * kDeg;
            pose.knee.flexion = e * (4.0 + 14.0 * bump(cycles, 0.12, 0.07) + 56.0 * bump(cycles, 0.72, 0.11)) * kDeg;
            pose.knee.abduction = e * 2.0 * std::sin(phi + 0.7) * kDeg;
            // Screw-home coupling: the tibia rotates internally as the knee flexes.
            pose.knee.rotation = e * 5.0 * std::sin(phi - 0.4) * kDeg + 0.08 * pose.knee.flexion;
            pelvisRotation = e * 5.0 * std::sin(phi) * kDeg;
            pelvisObliquity = e * 3.0 * std::cos(phi) * kDeg;
            pelvisTilt = e * 2.0 * std::sin(2.0 * phi) * kDeg;
            bounce = e * 0.02 * std::cos(2.0 * phi);
        } else if (t > squatBegin && t < squatEnd) {
            pose.phase = 2;
            const double u = std::fmod(t - squatBegin, p_.squatDuration) / p_.squatDuration;
            const double d = std::pow(std::sin(std::numbers::pi * u), 2);
            pose.knee = {90.0 * d * kDeg, 3.0 * d * kDeg, 6.0 * d * kDeg};
            pose.hip = {80.0 * d * kDeg, -2.0 * d * kDeg, 3.0 * d * kDeg};
            pelvisTilt = -20.0 * d * kDeg;  // anterior tilt: the pelvis' Y leans forward
            drop = 0.35 * d;
            back = 0.15 * d;
        }
        // ISB pelvis frame in ENU facing ψ: X → (cos ψ, sin ψ, 0), Y → up, Z → right.
        pose.pelvis = (math::headingRotation(psi) * axisRotation(0, std::numbers::pi / 2) *
                       axisRotation(1, pelvisRotation) * axisRotation(2, pelvisTilt) * axisRotation(0, pelvisObliquity))
                          .normalized();
        pose.thigh = (pose.pelvis * relativeFromAnatomical(pose.hip, Joint::Hip, p_.side)).normalized();
        pose.shank = (pose.thigh * relativeFromAnatomical(pose.knee, Joint::Knee, p_.side)).normalized();
        pose.pelvisOrigin = Vec3(0.0, 0.0, 0.95 - drop + bounce) - back * Vec3(std::cos(psi), std::sin(psi), 0.0);
        return pose;
    }

    // Body geometry in segment coordinates (m): joint centres and sensor positions.
    Vec3 hipInPelvis() const { return {0.0, -0.08, lateral * 0.09}; }
    Vec3 kneeInThigh() const { return {0.0, -0.42, 0.0}; }
    std::array<Vec3, 3> sensorInSegment() const {
        return {Vec3(-0.12, 0.02, 0.0), Vec3(0.0, -0.20, lateral * 0.08), Vec3(0.03, -0.15, lateral * 0.04)};
    }

    // Sensor positions (without the walking translation) of pelvis, thigh, shank: the thigh hangs at
    // the hip, the shank at the knee.
    std::array<Vec3, 3> sensorPositions(double t) const {
        const Pose p = pose(t);
        const std::array<Vec3, 3> s = sensorInSegment();
        const Vec3 hip = p.pelvisOrigin + p.pelvis * hipInPelvis();
        const Vec3 knee = hip + p.thigh * kneeInThigh();
        return {p.pelvisOrigin + p.pelvis * s[0], hip + p.thigh * s[1], knee + p.shank * s[2]};
    }

    double walkBegin = 0, walkEnd = 0, squatBegin = 0, squatEnd = 0, end = 0, lateral = 1;

private:
    const LimbSimulatorParams& p_;
};

}  // namespace

Quat mountFromAxes(const Vec3& x, const Vec3& z, const Vec3& misalignment) {
    Eigen::Matrix3d sensorToSegment;
    sensorToSegment.col(0) = x.normalized();
    sensorToSegment.col(2) = z.normalized();
    sensorToSegment.col(1) = sensorToSegment.col(2).cross(sensorToSegment.col(0));
    const Quat q = Quat(sensorToSegment) * math::quatFromRotationVector(misalignment);
    return q.conjugate().normalized();
}

Quat simulatedMount(LimbSegment segment, Side side) {
    const double lat = side == Side::Right ? 1.0 : -1.0;
    switch (segment) {
        case LimbSegment::Pelvis:  // on the sacrum: x to the right, y up, z out of the back
            return mountFromAxes(Vec3::UnitZ(), -Vec3::UnitX(), Vec3(0.05, 0.06, -0.04));
        case LimbSegment::Thigh:  // lateral thigh: x down the thigh, z out of the skin (lateral)
            return mountFromAxes(-Vec3::UnitY(), lat * Vec3::UnitZ(), Vec3(0.12, -0.08, 0.15));
        case LimbSegment::Shank:  // anterolateral shank: x up, z out of the skin at 45° between front and side
            return mountFromAxes(Vec3::UnitY(), Vec3::UnitX() + lat * Vec3::UnitZ(), Vec3(-0.10, 0.14, 0.09));
    }
    return Quat::Identity();
}

LimbSimulation simulateLimb(const LimbSimulatorParams& params) {
    const Script script(params);
    LimbSimulation sim;
    sim.walkBegin = script.walkBegin;
    sim.walkEnd = script.walkEnd;
    sim.squatBegin = script.squatBegin;
    sim.squatEnd = script.squatEnd;
    const double dt = 1.0 / params.rate;
    const auto n = static_cast<std::size_t>(std::floor(script.end * params.rate)) + 1;
    std::mt19937_64 rng(params.seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    // Components drawn one after another (argument evaluation order is unspecified).
    const auto draw3 = [&](auto& distribution) -> Vec3 {
        Vec3 v;
        for (int i = 0; i < 3; ++i) v[i] = distribution(rng);
        return v;
    };
    const auto draw = [&](double scale) -> Vec3 { return draw3(uniform) * scale; };
    for (int s = 0; s < 3; ++s) {
        SimulatedSegment& seg = sim.segments[s];
        seg.mount = simulatedMount(static_cast<LimbSegment>(s), params.side);
        seg.gyrBias = draw(params.gyrBias);
        seg.accBias = draw(params.accBias);
        seg.acc.resize(n);
        seg.gyr.resize(n);
        seg.sensor.resize(n);
        seg.segment.resize(n);
    }
    {
        const std::array<Vec3, 3> s = script.sensorInSegment();
        auto& seg = sim.segments;
        seg[0].toHip = seg[0].mount * (script.hipInPelvis() - s[0]);
        seg[1].toHip = seg[1].mount * (-s[1]);
        seg[1].toKnee = seg[1].mount * (script.kneeInThigh() - s[1]);
        seg[2].toKnee = seg[2].mount * (-s[2]);
    }
    sim.t.resize(n);
    sim.knee.resize(n);
    sim.hip.resize(n);
    sim.phase.resize(n);
    // Second derivative of the sensor positions by central differences on the analytic pose: the
    // step keeps truncation (~h²) and round-off (~ε/h²) both below 1e-5 m/s².
    const double h = 1e-3;
    const Vec3 gravityUp(0.0, 0.0, params.gravity);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = double(k) * dt;
        sim.t[k] = t;
        const Pose pose = script.pose(t), before = script.pose(t - dt);
        sim.knee[k] = pose.knee;
        sim.hip[k] = pose.hip;
        sim.phase[k] = pose.phase;
        const std::array<Vec3, 3> p0 = script.sensorPositions(t), pm = script.sensorPositions(t - h),
                                  pp = script.sensorPositions(t + h);
        const Vec3 walk = script.walkAcceleration(t);
        const std::array<Quat, 3> now{pose.pelvis, pose.thigh, pose.shank},
            then{before.pelvis, before.thigh, before.shank};
        for (int s = 0; s < 3; ++s) {
            SimulatedSegment& seg = sim.segments[s];
            const Quat sensor = (now[s] * seg.mount.conjugate()).normalized();
            const Quat previous = (then[s] * seg.mount.conjugate()).normalized();
            seg.segment[k] = now[s];
            seg.sensor[k] = sensor;
            const Vec3 a = walk + (pp[s] - 2.0 * p0[s] + pm[s]) / (h * h);
            const Vec3 omega = math::rotationVectorFromQuat(previous.conjugate() * sensor) / dt;
            seg.gyr[k] = omega + seg.gyrBias + draw3(normal) * params.gyrNoise;
            seg.acc[k] = sensor.conjugate() * (a + gravityUp) + seg.accBias + draw3(normal) * params.accNoise;
        }
    }
    return sim;
}

}  // namespace athlos::inertial
