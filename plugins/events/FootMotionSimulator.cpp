#include "plugins/events/FootMotionSimulator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <tuple>
#include <utility>

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
    double stance0 = 0.0;             // start of the stance before the swing
    double heading0 = 0.0;            // heading before the stance pivot
    Eigen::Vector3d p0 = Eigen::Vector3d::Zero();
    SimStride stride;
};

// Pose of the pivot point F at time t: position, acceleration (world), heading ψ, pitch θ and rates.
struct Pose {
    Eigen::Vector3d p = Eigen::Vector3d::Zero(), acc = Eigen::Vector3d::Zero();
    double psi = 0.0, dpsi = 0.0, theta = 0.0, dtheta = 0.0;
    Eigen::Matrix3d R() const {
        return (Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitY()))
            .toRotationMatrix();
    }
};

// Cubic Hermite on [0, 1] from (a, da) to (b, db) (derivatives in u): value and derivative in u.
std::pair<double, double> hermite(double u, double a, double da, double b, double db) {
    const double u2 = u * u, u3 = u2 * u;
    const double value = (2 * u3 - 3 * u2 + 1) * a + (u3 - 2 * u2 + u) * da + (-2 * u3 + 3 * u2) * b + (u3 - u2) * db;
    const double slope =
        (6 * u2 - 6 * u) * a + (3 * u2 - 4 * u + 1) * da + (-6 * u2 + 6 * u) * b + (3 * u2 - 2 * u) * db;
    return {value, slope};
}

// The heel-to-toe roll of a stance of length S (rad and rad/s at τ ∈ [0, 1]): the rate is
// ω₀ + c (2τ − 1)², c = ω_e − ω₀, so the foot is quietest (ω₀) at mid-stance and rolls at ω_e at
// initial contact and push-off; θ runs from −B to +B, B = S (ω₀ + c/3)/2. The first stance starts
// from standing (rate ω_e τ²), the stance after the last swing ends standing (rate ω_e (1 − τ)²).
struct Roll {
    double w0 = 0.0, we = 0.0;
    double amplitude(double S) const { return 0.5 * S * (w0 + (we - w0) / 3.0); }
    std::pair<double, double> middle(double tau, double S) const {
        const double c = we - w0, x = 2.0 * tau - 1.0;
        return {-amplitude(S) + S * (w0 * tau + c * (x * x * x + 1.0) / 6.0), w0 + c * x * x};
    }
    std::pair<double, double> first(double tau, double S) const {
        return {S * we * tau * tau * tau / 3.0, we * tau * tau};
    }
    std::pair<double, double> last(double tau, double S) const {
        const double r = 1.0 - tau;
        return {-amplitude(S) + S * we * (1.0 - r * r * r) / 3.0, we * r * r};
    }
};

Pose poseAt(const std::vector<Phase>& phases, double tk, const Roll& roll) {
    Pose pose;
    if (phases.empty()) return pose;
    // The stride whose stance or swing contains tk (the first one before it starts).
    const auto next = std::upper_bound(phases.begin(), phases.end(), tk,
                                       [](double time, const Phase& ph) { return time < ph.stance0; });
    const std::size_t phase = next == phases.begin() ? 0 : std::size_t(next - phases.begin()) - 1;
    const Phase& ph = phases[phase];
    const SimStride& s = ph.stride;
    const bool first = phase == 0, last = phase + 1 == phases.size(), rolling = roll.w0 > 0.0;
    const double u = (tk - ph.t0) / ph.duration;
    pose.p = ph.p0;
    if (tk < ph.t0) {  // stance before the swing (or still before it)
        const double tau = (tk - ph.stance0) / s.stance;
        pose.psi = ph.heading0;
        if (tau > 0.0) {
            pose.psi += s.stancePivot * s0(tau);
            pose.dpsi = s.stancePivot * s1(tau) / s.stance;
            if (rolling)
                std::tie(pose.theta, pose.dtheta) = first ? roll.first(tau, s.stance) : roll.middle(tau, s.stance);
        }
        return pose;
    }
    const double heading = ph.heading0 + s.stancePivot;
    const double mean = heading + 0.5 * s.turn;
    const Eigen::Vector3d dir(std::cos(mean), std::sin(mean), 0.0);
    if (u >= 1.0) {  // after the last swing: the roll slows down to standing
        pose.psi = heading + s.turn;
        pose.p = ph.p0 + s.length * dir + s.rise * Eigen::Vector3d::UnitZ();
        const double tau = (tk - ph.t0 - ph.duration) / s.stance;
        if (last && rolling && tau < 1.0) std::tie(pose.theta, pose.dtheta) = roll.last(tau, s.stance);
        return pose;
    }
    const double T = ph.duration;
    pose.psi = heading + s.turn * s0(u);
    pose.dpsi = s.turn * s1(u) / T;
    const double sn = std::sin(kPi * u), s2pi = std::sin(2.0 * kPi * u), c2pi = std::cos(2.0 * kPi * u);
    pose.theta = s.pitch * s2pi * sn * sn;
    // d/dτ [sin 2πτ sin² πτ] = 2π cos 2πτ sin² πτ + π sin 2πτ sin 2πτ
    pose.dtheta = s.pitch * (2.0 * kPi * c2pi * sn * sn + kPi * s2pi * s2pi) / T;
    if (rolling) {  // from the push-off pitch back to the heel-first pitch of the next contact, ω_e at both ends
        const double from = first ? roll.first(1.0, s.stance).first : roll.amplitude(s.stance);
        const double to = -roll.amplitude(last ? s.stance : phases[phase + 1].stride.stance);
        const auto [h, dh] = hermite(u, from, roll.we * T, to, roll.we * T);
        pose.theta += h;
        pose.dtheta += dh / T;
    }
    pose.p = ph.p0 + s.length * s0(u) * dir;
    pose.p.z() += s.lift * 0.5 * (1.0 - c2pi) + s.rise * s0(u);
    pose.acc = s.length * s2(u) / (T * T) * dir;
    pose.acc.z() = s.lift * 2.0 * kPi * kPi * c2pi / (T * T) + s.rise * s2(u) / (T * T);
    return pose;
}
}  // namespace

SimRecording simulateFoot(const SimConfig& c) {
    // Swing phases in time; the stances are the gaps between them.
    std::vector<Phase> phases;
    double t = c.standStart, heading = 0.0;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    SimRecording rec;
    double previousSwingEnd = 0.0;
    for (std::size_t i = 0; i < c.strides.size(); ++i) {
        const SimStride& s = c.strides[i];
        Phase ph{t + s.stance, s.swing, t, heading, p, s};
        t += s.stance;
        phases.push_back(ph);
        heading += s.stancePivot;
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
    rec.position.resize(n);
    const bool lever = !c.leverArm.isZero();
    const Roll roll{c.stanceRate, c.stanceEdgeRate};
    constexpr double h = 1e-4;  // s, central differences of R d
    for (std::size_t k = 0; k < n; ++k) {
        const double tk = double(k) / c.rate;
        rec.t[k] = tk;
        const Pose pose = poseAt(phases, tk, roll);
        const Eigen::Matrix3d Ry = Eigen::AngleAxisd(pose.theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
        const Eigen::Matrix3d R = pose.R();
        Eigen::Vector3d acc = pose.acc;
        rec.position[k] = pose.p + R * c.leverArm;
        if (lever) {
            const Eigen::Vector3d before = poseAt(phases, tk - h, roll).R() * c.leverArm;
            const Eigen::Vector3d after = poseAt(phases, tk + h, roll).R() * c.leverArm;
            acc += (after - 2.0 * (R * c.leverArm) + before) / (h * h);
        }
        const Eigen::Vector3d f = R.transpose() * (acc + kG * Eigen::Vector3d::UnitZ());
        const Eigen::Vector3d w =
            Ry.transpose() * (pose.dpsi * Eigen::Vector3d::UnitZ()) + pose.dtheta * Eigen::Vector3d::UnitY();
        for (int i = 0; i < 3; ++i) {
            rec.values[k * 6 + std::size_t(i)] = c.accScale[i] * f[i] + c.accBias[i] + c.accNoise * normal(rng);
            rec.values[k * 6 + 3 + std::size_t(i)] = c.gyrScale[i] * w[i] + c.gyrBias[i] + c.gyrNoise * normal(rng);
        }
    }
    return rec;
}

}  // namespace athlos::events
