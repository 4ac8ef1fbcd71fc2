#include "plugins/events/FootMotionSimulator.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::events {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;

// Minimum-jerk profile and its derivatives in τ.
double s0(double u) { return u * u * u * (10.0 - 15.0 * u + 6.0 * u * u); }
double s1(double u) { return 30.0 * u * u * (1.0 - u) * (1.0 - u); }
double s2(double u) { return 60.0 * u * (1.0 - u) * (1.0 - 2.0 * u); }

struct Phase {
    double t0 = 0.0, duration = 0.0;  // swing
    double heading0 = 0.0;
    Eigen::Vector3d p0 = Eigen::Vector3d::Zero();
    SimStride stride;
};
}  // namespace

SimRecording simulateFoot(const SimConfig& c) {
    // Swing phases in time; the stances are the still gaps between them.
    std::vector<Phase> phases;
    double t = c.standStart, heading = 0.0;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    SimRecording rec;
    double previousSwingEnd = 0.0;
    for (std::size_t i = 0; i < c.strides.size(); ++i) {
        const SimStride& s = c.strides[i];
        t += s.stance;
        Phase ph{t, s.swing, heading, p, s};
        phases.push_back(ph);
        const double mean = heading + 0.5 * s.turn;
        p += Eigen::Vector3d(s.length * std::cos(mean), s.length * std::sin(mean), s.rise);
        heading += s.turn;
        SimTruth truth;
        truth.start = i == 0 ? t - 0.5 * s.stance : 0.5 * (previousSwingEnd + t);
        truth.length = s.length;
        truth.rise = s.rise;
        truth.turn = s.turn;
        truth.lift = s.lift;
        truth.swing = s.swing;
        truth.swingStart = t;
        t += s.swing;
        previousSwingEnd = t;
        if (i > 0) rec.truth.back().end = truth.start;
        rec.truth.push_back(truth);
    }
    const double tEnd = t + c.standEnd;
    if (!rec.truth.empty()) {
        const double nextStance = c.standEnd;
        rec.truth.back().end = previousSwingEnd + 0.5 * std::min(nextStance, c.strides.back().stance);
    }
    for (auto& tr : rec.truth) tr.stance = (tr.end - tr.start) - tr.swing;

    std::mt19937 rng(c.seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    const std::size_t n = std::size_t(tEnd * c.rate) + 1;
    rec.t.resize(n);
    rec.values.resize(n * 6);
    std::size_t phase = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const double tk = double(k) / c.rate;
        rec.t[k] = tk;
        while (phase + 1 < phases.size() && tk >= phases[phase + 1].t0) ++phase;
        double psi = 0.0, dpsi = 0.0, theta = 0.0, dtheta = 0.0;
        Eigen::Vector3d acc = Eigen::Vector3d::Zero();
        if (!phases.empty()) {
            const Phase& ph = phases[phase];
            const SimStride& s = ph.stride;
            const double u = (tk - ph.t0) / ph.duration;
            if (tk < ph.t0) {
                psi = ph.heading0;  // before the first swing
            } else if (u >= 1.0) {
                psi = ph.heading0 + s.turn;
            } else {
                const double T = ph.duration;
                psi = ph.heading0 + s.turn * s0(u);
                dpsi = s.turn * s1(u) / T;
                const double sn = std::sin(kPi * u), s2pi = std::sin(2.0 * kPi * u), c2pi = std::cos(2.0 * kPi * u);
                theta = s.pitch * s2pi * sn * sn;
                // d/dτ [sin 2πτ sin² πτ] = 2π cos 2πτ sin² πτ + π sin 2πτ sin 2πτ
                dtheta = s.pitch * (2.0 * kPi * c2pi * sn * sn + kPi * s2pi * s2pi) / T;
                const double mean = ph.heading0 + 0.5 * s.turn;
                const Eigen::Vector3d dir(std::cos(mean), std::sin(mean), 0.0);
                acc = s.length * s2(u) / (T * T) * dir;
                acc.z() = s.lift * 2.0 * kPi * kPi * c2pi / (T * T) + s.rise * s2(u) / (T * T);
            }
        }
        const Eigen::Matrix3d Rz = Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        const Eigen::Matrix3d Ry = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
        const Eigen::Matrix3d R = Rz * Ry;
        const Eigen::Vector3d f = R.transpose() * (acc + kG * Eigen::Vector3d::UnitZ());
        const Eigen::Vector3d w =
            Ry.transpose() * (dpsi * Eigen::Vector3d::UnitZ()) + dtheta * Eigen::Vector3d::UnitY();
        for (int i = 0; i < 3; ++i) {
            rec.values[k * 6 + std::size_t(i)] = f[i] + c.accBias[i] + c.accNoise * normal(rng);
            rec.values[k * 6 + 3 + std::size_t(i)] = w[i] + c.gyrBias[i] + c.gyrNoise * normal(rng);
        }
    }
    return rec;
}

}  // namespace athlos::events
