#include "plugins/events/SkiingSimulator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::events {

namespace {
constexpr double kG = 9.81;
constexpr double kPi = std::numbers::pi;

struct Track {
    double b0, b1, lambda;
    double beta(double s) const { return b0 + b1 * std::sin(2.0 * kPi * s / lambda); }
    double dbeta(double s) const { return b1 * 2.0 * kPi / lambda * std::cos(2.0 * kPi * s / lambda); }
    // (Δx, Δz) between arc lengths a and b (Simpson).
    Eigen::Vector2d displacement(double a, double b) const {
        const int n = 200;
        const double h = (b - a) / n;
        Eigen::Vector2d sum = Eigen::Vector2d::Zero();
        for (int i = 0; i <= n; ++i) {
            const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
            const double beta = this->beta(a + i * h);
            sum += w * Eigen::Vector2d(std::cos(beta), std::sin(beta));
        }
        return sum * h / 3.0;
    }
};

struct Cycle {
    double t0, tMove, t1;  // thrust start, thrust end (moving starts), next thrust start
    double s0, length;
    double plant, lift, liftEnd;
};

// Moving profile: w(τ) = 60 τ² (1 − τ)³ (integral 1), its integral and derivative.
double profileW(double x) { return 60.0 * x * x * std::pow(1.0 - x, 3); }
double profileDW(double x) { return 60.0 * (2.0 * x * std::pow(1.0 - x, 3) - 3.0 * x * x * std::pow(1.0 - x, 2)); }
double profileS(double x) {
    // ∫₀ˣ 60 τ²(1−τ)³ dτ = 60 (x³/3 − 3x⁴/4 + 3x⁵/5 − x⁶/6)
    return 60.0 * (std::pow(x, 3) / 3.0 - 0.75 * std::pow(x, 4) + 0.6 * std::pow(x, 5) - std::pow(x, 6) / 6.0);
}
double smoothStep(double x) { return 0.5 * (1.0 - std::cos(kPi * x)); }
}  // namespace

SkiCycleSimConfig skimoConfig(unsigned seed) {
    SkiCycleSimConfig c;
    c.cycleTimeMin = 1.3;
    c.cycleTimeMax = 1.9;
    c.stillFraction = 0.3;
    c.speedMin = 0.6;
    c.speedMax = 1.2;
    c.slope0 = 0.31;  // 18°
    c.slope1 = 0.09;
    c.slopeWavelength = 40.0;
    c.skiPitch = 0.0;
    c.vibration = 0.3;
    c.pole = false;
    c.truthZeroAcc = 1e9;  // skimo-phases refines on the speed only
    c.seed = seed;
    return c;
}

SkiCycleRecording simulateSkiCycles(const SkiCycleSimConfig& c) {
    std::mt19937 rng(c.seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    const Track track{c.slope0, c.slope1, c.slopeWavelength};

    std::vector<Cycle> cycles;
    double t = c.standStart, s = 0.0;
    for (int k = 0; k < c.cycles; ++k) {
        const double duration = c.cycleTimeMin + (c.cycleTimeMax - c.cycleTimeMin) * uni(rng);
        const double speed = c.speedMin + (c.speedMax - c.speedMin) * uni(rng);
        Cycle cy;
        cy.t0 = t;
        cy.tMove = t + c.stillFraction * duration;
        cy.t1 = t + duration;
        cy.s0 = s;
        cy.length = speed * duration;
        cy.plant = t - c.polePlantLead;
        cy.lift = cy.plant + c.poleContactFraction * duration;
        cycles.push_back(cy);
        t += duration;
        s += cy.length;
    }
    for (std::size_t k = 0; k < cycles.size(); ++k)
        cycles[k].liftEnd = k + 1 < cycles.size() ? cycles[k + 1].plant : cycles[k].lift + 0.5;
    const double end = t + c.standEnd;
    const double sEnd = s;

    SkiCycleRecording rec;
    const auto n = static_cast<std::size_t>(std::floor(end * c.rate)) + 1;
    rec.t.resize(n);
    rec.ski.resize(6 * n);
    rec.speed.resize(n);
    std::vector<double> arc(n), inertial(n);
    if (c.pole) rec.pole.resize(6 * n);
    const double poleUp = 0.35, poleBack = -0.6;  // rad from vertical, forward positive
    std::size_t ci = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double ti = double(i) / c.rate;
        rec.t[i] = ti;
        while (ci + 1 < cycles.size() && ti >= cycles[ci + 1].t0) ++ci;
        // Ski kinematics.
        double si = 0, sd = 0, sdd = 0, delta = 0, ddelta = 0;
        if (!cycles.empty() && ti >= cycles[ci].t0 && ti < cycles[ci].t1) {
            const Cycle& cy = cycles[ci];
            const double T = cy.t1 - cy.tMove;
            si = cy.s0;
            if (ti >= cy.tMove) {
                const double x = (ti - cy.tMove) / T;
                si += cy.length * profileS(x);
                sd = cy.length / T * profileW(x);
                sdd = cy.length / (T * T) * profileDW(x);
                delta = c.skiPitch * std::pow(std::sin(kPi * x), 2);
                ddelta = c.skiPitch * kPi * std::sin(2.0 * kPi * x) / T;
            }
        } else if (!cycles.empty() && ti >= cycles.back().t1) {
            si = sEnd;
        }
        const double beta = track.beta(si), db = track.dbeta(si);
        const Eigen::Vector2d tangent(std::cos(beta), std::sin(beta)), across(-std::sin(beta), std::cos(beta));
        const Eigen::Vector2d accWorld = sdd * tangent + sd * sd * db * across + Eigen::Vector2d(0.0, kG);
        // R = R_y(φ) with φ = −(β + δ): body = Rᵀ world; R_y(φ)ᵀ (x, z) = (c x − s z, s x + c z).
        const double phi = -(beta + delta);
        const double cp = std::cos(phi), sp = std::sin(phi);
        const double vib = c.vibration * sd / 5.0;
        double* row = rec.ski.data() + 6 * i;
        row[0] = cp * accWorld.x() - sp * accWorld.y();
        row[1] = 0.0;
        row[2] = sp * accWorld.x() + cp * accWorld.y();
        row[3] = 0.0;
        row[4] = -(db * sd + ddelta);
        row[5] = 0.0;
        for (int a = 0; a < 3; ++a) {
            row[a] += c.accBias[a] + c.accNoise * normal(rng) + vib * normal(rng);
            row[3 + a] += c.gyrBias[a] + c.gyrNoise * normal(rng);
        }
        rec.speed[i] = sd;
        arc[i] = si;
        inertial[i] = (accWorld - Eigen::Vector2d(0.0, kG)).norm();
        if (!c.pole) continue;
        // Pole: forward angle γ from vertical, pushed back on the snow, swung forward in the air.
        double gamma = poleUp, dgamma = 0.0, shock = 0.0, pulse = 0.0;
        for (const Cycle& cy : cycles) {
            if (ti >= cy.plant && ti < cy.lift) {
                const double x = (ti - cy.plant) / (cy.lift - cy.plant);
                gamma = poleUp + (poleBack - poleUp) * smoothStep(x);
                dgamma = (poleBack - poleUp) * 0.5 * kPi * std::sin(kPi * x) / (cy.lift - cy.plant);
            } else if (ti >= cy.lift && ti < cy.liftEnd) {
                const double x = (ti - cy.lift) / (cy.liftEnd - cy.lift);
                gamma = poleBack + (poleUp - poleBack) * smoothStep(x);
                dgamma = (poleUp - poleBack) * 0.5 * kPi * std::sin(kPi * x) / (cy.liftEnd - cy.lift);
            }
            if (ti >= cy.plant && ti < cy.plant + 0.3)
                shock += 25.0 * std::exp(-(ti - cy.plant) / 0.025) * std::sin(2.0 * kPi * 40.0 * (ti - cy.plant));
            pulse += 15.0 * std::exp(-0.5 * std::pow((ti - cy.lift) / 0.01, 2));
        }
        if (!cycles.empty() && ti >= cycles.back().liftEnd) gamma = poleUp;
        const double cg = std::cos(gamma), sg = std::sin(gamma);
        double* p = rec.pole.data() + 6 * i;
        p[0] = -sg * kG + pulse;  // pole frame: z up along the pole, x forward, rotation about y
        p[1] = 0.0;
        p[2] = cg * kG + shock;
        p[3] = 0.0;
        p[4] = -dgamma;
        p[5] = 0.0;
        for (int a = 0; a < 3; ++a) {
            p[a] += c.accNoise * normal(rng);
            p[3 + a] += c.gyrNoise * normal(rng);
        }
    }
    // Thrust start and end as the reference of Fasel 2017 Table 3.1 defines them: the first and last
    // instants at which the ski's speed and inertial acceleration are below small thresholds.
    auto still = [&](std::size_t i) { return rec.speed[i] < c.truthZeroSpeed && inertial[i] < c.truthZeroAcc; };
    auto sampleAt = [&](double ti) { return std::min(n - 1, std::size_t(std::llround(ti * c.rate))); };
    auto thrustStart = [&](double ti) {
        std::size_t i = sampleAt(ti);
        while (i > 0 && still(i - 1)) --i;
        return i;
    };
    for (std::size_t k = 0; k < cycles.size(); ++k) {
        const Cycle& cy = cycles[k];
        const std::size_t a = thrustStart(cy.t0), b = thrustStart(cy.t1);
        std::size_t e = sampleAt(cy.t0);
        while (e + 1 < n && still(e + 1)) ++e;
        SkiCycleTruth tr;
        tr.thrustStart = rec.t[a];
        tr.thrustEnd = rec.t[e];
        tr.glideStart = cy.tMove + 0.4 * (cy.t1 - cy.tMove);  // maximum of w(τ) at τ = 2/5
        tr.end = rec.t[b];
        tr.polePlant = cy.plant;
        tr.poleLift = cy.lift;
        tr.length = arc[b] - arc[a];
        tr.speed = tr.length / (tr.end - tr.thrustStart);
        const Eigen::Vector2d d = track.displacement(arc[a], arc[b]);
        tr.elevation = d.y();
        tr.slope = std::atan2(d.y(), d.x());
        rec.truth.push_back(tr);
    }
    return rec;
}

AlpineRecording simulateAlpine(const AlpineSimConfig& c) {
    std::mt19937 rng(c.seed);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::vector<double> U{0.0}, D;
    for (int k = 0; k < c.turns; ++k) {
        D.push_back(c.turnDistanceMin + (c.turnDistanceMax - c.turnDistanceMin) * uni(rng));
        U.push_back(U.back() + D.back());
    }
    // Lateral position y(u) and its derivatives; turn k has sign (−1)^k.
    auto lateral = [&](double u, double& y, double& dy, double& ddy) {
        std::size_t k = 0;
        while (k + 1 < D.size() && u >= U[k + 1]) ++k;
        const double sign = k % 2 ? -1.0 : 1.0, a = c.amplitudeRatio * D[k], w = kPi / D[k];
        const double x = w * (u - U[k]);
        y = sign * a * std::sin(x);
        dy = sign * a * w * std::cos(x);
        ddy = -sign * a * w * w * std::sin(x);
    };
    const double duration = U.back() / c.speed;
    auto position = [&](double t) {
        const double u = c.speed * t;
        double y, dy, ddy;
        lateral(u, y, dy, ddy);
        return Eigen::Vector3d(u * std::cos(c.slope), y, -u * std::sin(c.slope));
    };
    auto orientation = [&](double t) {
        const double u = c.speed * t;
        double y, dy, ddy;
        lateral(u, y, dy, ddy);
        const double psi = std::atan(dy);
        const double lean = -std::atan(c.speed * c.speed * ddy / kG);
        const double pitch = c.wobble * std::sin(2.0 * kPi * 1.7 * t);
        return Eigen::Quaterniond(
            Eigen::AngleAxisd(c.slope, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitZ()) *
            Eigen::AngleAxisd(lean, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()));
    };
    AlpineRecording rec;
    const auto n = static_cast<std::size_t>(std::floor(duration * c.rate)) + 1;
    rec.t.resize(n);
    rec.sacrum.resize(6 * n);
    const double h = 1e-3;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) / c.rate;
        rec.t[i] = t;
        const Eigen::Quaterniond q = orientation(t);
        const Eigen::Vector3d acc = (position(t + h) - 2.0 * position(t) + position(t - h)) / (h * h);
        const Eigen::Vector3d f = q.conjugate() * (acc + Eigen::Vector3d(0.0, 0.0, kG));
        const Eigen::AngleAxisd delta(orientation(t - h).conjugate() * orientation(t + h));
        const Eigen::Vector3d w = delta.axis() * delta.angle() / (2.0 * h);
        double* row = rec.sacrum.data() + 6 * i;
        for (int a = 0; a < 3; ++a) {
            row[a] = f[a] + c.accNoise * normal(rng) + c.vibration * normal(rng);
            row[3 + a] = w[a] + c.gyrBias[a] + c.gyrNoise * normal(rng);
        }
    }
    for (std::size_t k = 0; k < D.size(); ++k)
        rec.turns.push_back({U[k] / c.speed, U[k + 1] / c.speed, k % 2 == 1});  // y'' > 0 when sign < 0
    return rec;
}

}  // namespace athlos::events
