#include "plugins/positioning/GateRunSimulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::positioning {

using math::Quat;
using math::Vec3;

namespace {

double smoothstep(double a, double b, double x) {
    const double s = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return s * s * (3.0 - 2.0 * s);
}

// The sacrum line of the course: u along the fall line (horizontal, m), gate n at phase φ = nπ.
struct Course {
    Vec3 start, forward, left;
    double tanSlope = 0.0, u0 = 0.0, spacing = 1.0, jitter = 0.0, amplitude = 0.0, rampInEnd = 0.0, rampOutBegin = 0.0;

    double phase(double u) const {
        const double s = (u - u0) / spacing;
        return std::numbers::pi * s + jitter * std::sin(2.0 * std::numbers::pi * s / 5.3);
    }
    double ramp(double u) const {
        return smoothstep(rampInEnd - spacing, rampInEnd, u) *
               (1.0 - smoothstep(rampOutBegin, rampOutBegin + spacing, u));
    }
    Vec3 position(double u) const {
        const double phi = phase(u), r = ramp(u);
        const double w = amplitude * r * std::cos(phi);
        const double bob = -0.1 * r * 0.5 * (1.0 - std::cos(2.0 * phi));  // lower in every turn
        return start + u * forward + w * left + (-u * tanSlope + bob) * Vec3::UnitZ();
    }
    Vec3 d1(double u) const {
        const double h = 1e-3;
        return (position(u + h) - position(u - h)) / (2.0 * h);
    }
    Vec3 d2(double u) const {
        const double h = 1e-3;
        return (position(u + h) - 2.0 * position(u) + position(u - h)) / (h * h);
    }
    // u of gate n (φ(u) = nπ), by bisection (φ is increasing).
    double gateU(int n) const {
        double a = u0 + (n - 1.0) * spacing, b = u0 + (n + 1.0) * spacing;
        for (int i = 0; i < 80; ++i) {
            const double m = 0.5 * (a + b);
            (phase(m) < n * std::numbers::pi ? a : b) = m;
        }
        return 0.5 * (a + b);
    }
};

}  // namespace

double GateRunSimulator::magnetExcess(double distance) {
    // Eq. 9.1 solved for |B|: |r| = −0.4|B| + 1.0 (|B| < 1.62), else −0.062|B| + 0.452.
    if (distance >= 1.0) return 0.0;
    if (distance >= 1.0 - 0.4 * 1.62) return (1.0 - distance) / 0.4;
    return (0.452 - std::max(distance, 0.02)) / 0.062;
}

GateRunSimulator::Result GateRunSimulator::simulate(const Params& p) {
    std::mt19937_64 rng(p.seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    auto gauss = [&] { return Vec3(normal(rng), normal(rng), normal(rng)); };

    Course c;
    c.start = p.start;
    c.forward = Vec3(std::cos(p.courseAzimuth), std::sin(p.courseAzimuth), 0.0);
    c.left = Vec3(-std::sin(p.courseAzimuth), std::cos(p.courseAzimuth), 0.0);
    c.tanSlope = std::tan(p.slope);
    c.spacing = p.gateSpacing;
    c.u0 = 2.5 * p.gateSpacing;
    c.jitter = p.spacingJitter;
    c.amplitude = p.amplitude;
    c.rampInEnd = c.u0 - 0.5 * p.gateSpacing;
    const int nGates = std::max(p.gates, 1);
    const double lastGateU = c.gateU(nGates - 1);
    c.rampOutBegin = lastGateU + 0.5 * p.gateSpacing;
    const double finishU = lastGateU + 2.0 * p.gateSpacing;
    const double speedPhase = 2.0 * std::numbers::pi * uniform(rng);

    // Speed along the path: rest, first-order approach to a slowly varying target (start push
    // limited to 5 m/s²), braking after the finish line, rest. Integrated at 10 kHz-ish sub-steps.
    const double dt = 1.0 / p.imuRate;
    const int sub = 20;
    const double h = dt / sub;
    Result r;
    std::vector<double> us, vs, accs;
    double u = 0.0, v = 0.0, t = 0.0, stopTime = -1.0;
    auto speedRate = [&](double uu, double vv, double tt) {
        if (tt < p.restStart || stopTime >= 0.0) return 0.0;
        if (uu >= finishU) return vv > 0.0 ? -p.brake : 0.0;
        const double target =
            p.meanSpeed + p.speedAmplitude * std::sin(2.0 * std::numbers::pi * uu / 300.0 + speedPhase);
        return std::min((target - vv) / p.accelTime, 5.0);
    };
    for (int k = 0;; ++k) {
        const double vdot = speedRate(u, v, t);
        r.t.push_back(t);
        us.push_back(u);
        vs.push_back(v);
        accs.push_back(vdot);
        if (stopTime >= 0.0 && t >= stopTime + p.restEnd) break;
        if (k > 1e7) break;
        for (int s = 0; s < sub; ++s) {
            const double a = speedRate(u, v, t);
            const double speed = v;
            v = std::max(0.0, v + a * h);
            if (stopTime < 0.0 && u >= finishU && v <= 0.0) stopTime = t;
            u += 0.5 * (speed + v) * h / c.d1(u).norm();
            t += h;
        }
    }
    r.startMove = p.restStart;
    r.stopMove = stopTime;

    const std::size_t n = r.t.size();
    r.position.resize(n);
    r.velocity.resize(n);
    r.orientation.resize(n);
    std::vector<Vec3> accTrue(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Vec3 d1 = c.d1(us[k]), d2 = c.d2(us[k]);
        const double g = d1.norm();
        const double udot = vs[k] / g;
        // d|P'|/dt = (P'·P'')/|P'| · u̇; ü = (v̇ − u̇ d|P'|/dt) / |P'|
        const double dg = d1.dot(d2) / g * udot;
        const double uddot = (accs[k] - udot * dg) / g;
        r.position[k] = c.position(us[k]);
        r.velocity[k] = d1 * udot;
        accTrue[k] = d2 * udot * udot + d1 * uddot;
        // Sacrum frame: x along the horizontal velocity, leaning into the turn (≈ 80 % of the
        // balance angle) and forward by 0.2 rad.
        const Vec3 dir = Vec3(d1.x(), d1.y(), 0.0).normalized();
        const double heading = std::atan2(dir.y(), dir.x());
        const Vec3 leftH(-dir.y(), dir.x(), 0.0);
        const double aLat = accTrue[k].dot(leftH);
        const double roll = -0.8 * std::atan2(aLat, p.gravity);
        r.orientation[k] = (math::headingRotation(heading) * Quat(Eigen::AngleAxisd(0.2, Vec3::UnitY())) *
                            Quat(Eigen::AngleAxisd(roll, Vec3::UnitX())))
                               .normalized();
    }

    // Gates: the magnet on the inside of the turn, below the sacrum along the snow normal.
    std::mt19937_64 courseRng(p.courseSeed != 0 ? p.courseSeed : p.seed + 0x9e3779b97f4a7c15ULL);
    const Vec3 snowNormal = (std::sin(p.slope) * c.forward + std::cos(p.slope) * Vec3::UnitZ()).normalized();
    for (int gi = 0; gi < nGates; ++gi) {
        const double ug = c.gateU(gi);
        const Vec3 pos = c.position(ug);
        const Vec3 d1 = c.d1(ug), d2 = c.d2(ug);
        const Vec3 tangent = d1.normalized();
        Vec3 inward = d2 - d2.dot(tangent) * tangent;
        inward = (inward - inward.dot(snowNormal) * snowNormal).normalized();
        const double lateral = p.lateralMin + (p.lateralMax - p.lateralMin) * uniform(courseRng);
        const double height = p.heightMin + (p.heightMax - p.heightMin) * uniform(courseRng);
        r.gates.push_back(
            {QStringLiteral("G%1").arg(gi + 1, 2, 10, QLatin1Char('0')), pos + lateral * inward - height * snowNormal});
        // Truth crossing: the IMU sample of closest approach, refined on the path.
        double best = 1e300, bestT = 0.0;
        for (std::size_t k = 0; k < n; ++k) {
            const double dist = (r.position[k] - r.gates.back().position).norm();
            if (dist < best) best = dist, bestT = r.t[k];
        }
        r.gateTimes.push_back(bestT);
        r.gateDistance.push_back(std::sqrt(lateral * lateral + height * height));
    }

    // IMU errors and the sensor signals.
    Vec3 gyrBias = p.gyrBias * gauss();
    const Vec3 accBias = p.accBias * gauss();
    const double earthNorm = p.earthField.norm();
    r.acc.resize(n);
    r.gyr.resize(n);
    r.mag.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Quat& q = r.orientation[k];
        const Eigen::Matrix3d Rt = q.toRotationMatrix().transpose();
        Vec3 omega = Vec3::Zero();
        if (k > 0) omega = 2.0 * math::quatLog(r.orientation[k - 1].conjugate() * q) / dt;
        gyrBias += p.gyrBiasWalk * std::sqrt(dt) * gauss();
        r.gyr[k] = omega + gyrBias + p.gyrNoise * gauss();
        const double vib = p.vibration * r.velocity[k].norm() / 20.0;
        r.acc[k] = Rt * (accTrue[k] + p.gravity * Vec3::UnitZ()) + accBias + (p.accNoise + vib) * gauss();
        Vec3 field = p.earthField;
        for (const Gate& gate : r.gates) {
            const Vec3 rho = r.position[k] - gate.position;  // magnet → sensor
            const double dist = rho.norm();
            if (dist >= 1.0) continue;
            const Vec3 rh = rho / dist;
            const Vec3 dipole = (3.0 * rh.z() * rh - Vec3::UnitZ()).normalized();
            field += earthNorm * magnetExcess(dist) * dipole;
        }
        r.mag[k] = Rt * field + p.magNoise * gauss();
    }

    if (p.gnssRate > 0.0) {
        const std::size_t step = std::max<std::size_t>(1, std::size_t(std::lround(p.imuRate / p.gnssRate)));
        for (std::size_t k = 0; k < n; k += step) {
            r.gnssT.push_back(r.t[k]);
            r.gnss.push_back(r.position[k] + p.gnssSigma * gauss());
        }
    }
    return r;
}

}  // namespace athlos::positioning
