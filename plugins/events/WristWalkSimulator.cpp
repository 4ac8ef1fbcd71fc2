#include "plugins/events/WristWalkSimulator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::events {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kGravity = 9.80665;

enum class Activity { Stand, Gesture, Walk };

struct Segment {
    double t0 = 0.0, t1 = 0.0;
    Activity activity = Activity::Stand;
    double grade = 0.0;
    double cadence0 = 100.0, cadenceAmp = 0.0, cadencePeriod = 40.0, cadencePhase = 0.0;  // steps/min, s
    double swingScale = 1.0;  // arm swing relative to the walker's usual one (0.15: hand held still)
};

// Bouts of walking between pauses of standing or gesturing, until `duration`.
std::vector<Segment> schedule(const WristWalkParams& p, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Segment> segments;
    const double meanWalk = 80.0;
    const double meanPause = meanWalk * (1.0 - p.walkingShare) / std::max(p.walkingShare, 0.05);
    double t = 0.0;
    segments.push_back({0.0, 8.0, Activity::Stand});
    t = 8.0;
    while (t < p.duration) {
        Segment walk;
        walk.t0 = t;
        walk.t1 = t + meanWalk * (0.5 + u(rng));
        walk.activity = Activity::Walk;
        walk.grade = p.maxGrade * (2.0 * u(rng) - 1.0);
        if (u(rng) < 0.3) walk.grade = 0.0;  // flat paths are common
        const double margin = std::min(8.0, 0.25 * (p.cadenceMax - p.cadenceMin));
        walk.cadence0 = p.cadenceMin + margin + (p.cadenceMax - p.cadenceMin - 2.0 * margin) * u(rng);
        walk.cadenceAmp = std::min(margin, 2.0 + 8.0 * u(rng));
        walk.cadencePeriod = 20.0 + 40.0 * u(rng);
        walk.cadencePhase = 2.0 * kPi * u(rng);
        walk.swingScale = u(rng) < 0.15 ? 0.15 : 1.0;
        segments.push_back(walk);
        t = walk.t1;
        Segment pause;
        pause.t0 = t;
        pause.t1 = t + meanPause * (0.5 + u(rng));
        pause.activity = u(rng) < 0.5 ? Activity::Stand : Activity::Gesture;
        segments.push_back(pause);
        t = pause.t1;
    }
    return segments;
}

double smoothstep(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

}  // namespace

WristWalkRecording simulateWristWalk(const WristWalkParams& p) {
    std::mt19937_64 rng(p.seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> n01(0.0, 1.0);
    WristWalkRecording rec;
    const double h = p.height;
    rec.subjectFactor = 0.93 + 0.14 * u(rng);
    // Arm swing of this walker: larger for longer steps, partly individual.
    const double swing0 = 0.32 * std::pow(rec.subjectFactor, 1.5) * (0.92 + 0.16 * u(rng));  // rad
    const double armRadius = 0.36 * h;                                                       // m, shoulder–wrist
    // Mounting: the strap's fixed rotation of the sensor on the forearm.
    const Eigen::Matrix3d mounting = (Eigen::AngleAxisd(0.3 * (2.0 * u(rng) - 1.0), Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(0.3 * (2.0 * u(rng) - 1.0), Eigen::Vector3d::UnitX()))
                                         .toRotationMatrix();
    const double drift = (u(rng) < 0.5 ? -1.0 : 1.0) * p.baroDrift / 3600.0;  // Pa/s
    const std::vector<Segment> segments = schedule(p, rng);

    const double dt = 1.0 / p.rate;
    const auto n = std::size_t(std::floor(p.duration * p.rate)) + 1;
    rec.t.resize(n);
    rec.imu.resize(6 * n);
    std::vector<double> altitude(n);
    const auto truthEvery = std::max<std::size_t>(1, std::size_t(std::lround(p.rate / p.truthRate)));

    double phase = 0.0;                  // stride phase φ (rad)
    double z = 0.0;                      // altitude (m)
    double ouAngle = 0.0, ouRate = 0.0;  // arm angle of the non-walking periods (rad, rad/s)
    std::size_t seg = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = double(k) * dt;
        while (seg + 1 < segments.size() && t >= segments[seg].t1) ++seg;
        const Segment& s = segments[seg];
        double cadence = 0.0, speed = 0.0, theta = 0.0, thetaD = 0.0, thetaDD = 0.0;
        Eigen::Vector3d trunk = Eigen::Vector3d::Zero();
        if (s.activity == Activity::Walk) {
            cadence = std::clamp(
                s.cadence0 + s.cadenceAmp * std::sin(2.0 * kPi * (t - s.t0) / s.cadencePeriod + s.cadencePhase),
                p.cadenceMin, p.cadenceMax);
            // Gait initiation and termination: amplitudes and speed ramp over 1.5 s.
            const double ramp = smoothstep((t - s.t0) / 1.5) * smoothstep((s.t1 - t) / 1.5);
            const double gradeFactor = 1.0 - 1.5 * std::max(s.grade, 0.0) - 0.8 * std::max(-s.grade, 0.0);
            const double flatStep = h * (0.415 + 0.004 * (cadence - 100.0)) * rec.subjectFactor;  // m
            const double step = flatStep * gradeFactor;
            speed = ramp * step * cadence / 60.0;
            const double w = 2.0 * kPi * cadence / 120.0;  // stride angular frequency φ' (rad/s)
            phase += w * dt;
            // The arm swings as on flat ground: only the barometer tells a slope's shorter steps.
            const double amp = ramp * swing0 * s.swingScale * flatStep / (0.415 * h);
            // The arm hangs slightly forward (θ0 = 0.2 rad): with it the norm keeps a component at the
            // stride frequency, the fundamental the thesis observed.
            theta = 0.2 * ramp + amp * (std::sin(phase) + 0.15 * std::sin(2.0 * phase));
            thetaD = amp * w * (std::cos(phase) + 0.3 * std::cos(2.0 * phase));
            thetaDD = -amp * w * w * (std::sin(phase) + 0.6 * std::sin(2.0 * phase));
            // Trunk at the step frequency 2φ': vertical bounce B = 0.05 L, fore-aft surge, lateral sway.
            const double ws = 2.0 * w;
            trunk.x() = ramp * 0.8 * (step / 0.72) * std::sin(2.0 * phase);
            trunk.y() = ramp * 0.3 * std::sin(phase);
            // Left and right steps differ by 30 % (bounce at the stride frequency as well).
            trunk.z() = ramp * 0.05 * step * ws * ws * (std::cos(2.0 * phase) + 0.3 * 0.25 * std::cos(phase));
            z += speed * s.grade / std::sqrt(1.0 + s.grade * s.grade) * dt;
            ouAngle = theta;
            ouRate = thetaD;
        } else {
            // Ornstein–Uhlenbeck arm angle (second order): still standing or aperiodic gestures.
            const bool gesture = s.activity == Activity::Gesture;
            const double sigma = gesture ? 0.5 : 0.02, tau = gesture ? 0.35 : 2.0;
            const double wn = 1.0 / tau;
            thetaDD = -2.0 * wn * ouRate - wn * wn * ouAngle + sigma * wn * wn * std::sqrt(4.0 * tau / dt) * n01(rng);
            ouRate += thetaDD * dt;
            ouAngle += ouRate * dt;
            theta = ouAngle;
            thetaD = ouRate;
        }
        const double r = armRadius;
        Eigen::Vector3d acc =
            trunk + Eigen::Vector3d(r * (thetaDD * std::cos(theta) - thetaD * thetaD * std::sin(theta)), 0.0,
                                    r * (thetaDD * std::sin(theta) + thetaD * thetaD * std::cos(theta)));
        const Eigen::Matrix3d rotation =
            Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()).toRotationMatrix() * mounting;
        const Eigen::Vector3d f = rotation.transpose() * (acc + Eigen::Vector3d(0.0, 0.0, kGravity));
        const Eigen::Vector3d gyr = mounting.transpose() * Eigen::Vector3d(0.0, thetaD, 0.0);
        rec.t[k] = t;
        for (int i = 0; i < 3; ++i) {
            rec.imu[6 * k + std::size_t(i)] = f[i] + p.accNoise * n01(rng);
            rec.imu[6 * k + 3 + std::size_t(i)] = gyr[i] + p.gyrNoise * n01(rng);
        }
        altitude[k] = z;
        if (k % truthEvery == 0) {
            rec.tTruth.push_back(t);
            rec.cadence.push_back(cadence);
            rec.speed.push_back(speed);
            rec.grade.push_back(s.activity == Activity::Walk ? s.grade : 0.0);
            rec.altitude.push_back(z);
            rec.walking.push_back(s.activity == Activity::Walk ? 1.0 : 0.0);
        }
    }
    // Barometer: ISA pressure at the altitude, a linear weather drift plus a slow random one, noise.
    const double baroDt = 1.0 / p.baroRate;
    double weather = 0.0;
    for (double t = 0.0; t <= p.duration; t += baroDt) {
        const auto k = std::min(n - 1, std::size_t(std::lround(t * p.rate)));
        weather += -weather * baroDt / 600.0 + 5.0 * std::sqrt(2.0 * baroDt / 600.0) * n01(rng);
        const double isa = 101325.0 * std::pow(1.0 - 2.25577e-5 * altitude[k], 5.25588);
        rec.tBaro.push_back(t);
        rec.pressure.push_back(isa + drift * t + weather + p.baroNoise * n01(rng));
    }
    return rec;
}

}  // namespace athlos::events
