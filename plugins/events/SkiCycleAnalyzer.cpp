#include "plugins/events/SkiCycleAnalyzer.h"

#include <algorithm>
#include <cmath>

namespace athlos::events {

namespace {
struct Window {
    std::size_t begin, end;
};

// Central 50 % of a phase (at least one sample), where the drift is estimated (Fasel 2017 ch. 4).
Window central(const SkiPhase& p) {
    const std::size_t quarter = (p.end - p.begin) / 4;
    return {p.begin + quarter, std::max(p.begin + quarter + 1, p.end - quarter)};
}

double mean(const std::vector<double>& v, Window w) {
    double s = 0.0;
    for (std::size_t i = w.begin; i < w.end; ++i) s += v[i];
    return s / double(w.end - w.begin);
}

// Piecewise-linear interpolation of anchor values over sample indices, constant outside.
std::vector<double> interpolate(const std::vector<double>& at, const std::vector<double>& value, std::size_t n) {
    std::vector<double> out(n, 0.0);
    if (at.empty()) return out;
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = double(i);
        while (k + 1 < at.size() && x > at[k + 1]) ++k;
        if (x <= at.front())
            out[i] = value.front();
        else if (k + 1 >= at.size())
            out[i] = value.back();
        else
            out[i] = value[k] + (value[k + 1] - value[k]) * (x - at[k]) / (at[k + 1] - at[k]);
    }
    return out;
}

std::vector<SkiPhase> merged(std::vector<SkiPhase> phases) {
    std::sort(phases.begin(), phases.end(), [](const SkiPhase& a, const SkiPhase& b) { return a.begin < b.begin; });
    std::vector<SkiPhase> out;
    for (const SkiPhase& p : phases) {
        if (p.end <= p.begin) continue;
        if (!out.empty() && p.begin <= out.back().end)
            out.back().end = std::max(out.back().end, p.end);
        else
            out.push_back(p);
    }
    return out;
}

double interval(const SkiImu& imu) {
    return imu.size() > 1 ? (imu.t.back() - imu.t.front()) / double(imu.size() - 1) : 1.0;
}
}  // namespace

std::vector<SkiPhase> SkiCycleAnalyzer::stillPhases(const SkiImu& imu) const {
    std::vector<SkiPhase> out;
    const auto minSamples = std::size_t(std::ceil(p_.minStill / interval(imu)));
    std::size_t start = 0;
    bool in = false;
    for (std::size_t i = 0; i <= imu.size(); ++i) {
        bool still = false;
        if (i < imu.size()) {
            const double a = std::sqrt(imu.accForward[i] * imu.accForward[i] + imu.accLeft[i] * imu.accLeft[i] +
                                       imu.accUp[i] * imu.accUp[i]);
            still = imu.gyrNorm[i] < p_.stillGyro && std::abs(a - p_.gravity) < p_.stillAcc;
        }
        if (still && !in) {
            start = i;
            in = true;
        } else if (!still && in) {
            if (i - start >= minSamples) out.push_back({start, i});
            in = false;
        }
    }
    return out;
}

std::vector<SkiPhase> SkiCycleAnalyzer::speedMinimumPhases(const SkiImu& imu) const {
    const double ts = interval(imu);
    const auto n0 = std::size_t(std::ceil(p_.initialStill / ts));
    const std::size_t n = imu.size();
    if (n0 < 2 || n0 * 2 > n) return {};
    // First pass: the start is still; its mean gyroscope is the bias, its accelerometer the inclination.
    const Window first{0, n0};
    double bias = mean(imu.gyrLeft, first);
    double phi = std::atan2(-mean(imu.accForward, first), mean(imu.accUp, first));
    std::vector<double> vx(n, 0.0);
    double ax0 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        if (i > 0) phi += 0.5 * (imu.gyrLeft[i] + imu.gyrLeft[i - 1] - 2.0 * bias) * (imu.t[i] - imu.t[i - 1]);
        const double ax = std::cos(phi) * imu.accForward[i] + std::sin(phi) * imu.accUp[i];
        if (i > 0) vx[i] = vx[i - 1] + 0.5 * (ax + ax0) * (imu.t[i] - imu.t[i - 1]);
        ax0 = ax;
    }
    std::vector<SkiPhase> out{{0, n0}};
    const auto half = std::max<std::size_t>(1, std::size_t(0.5 * p_.minCycle / ts));
    const auto maxHalf = std::max<std::size_t>(1, std::size_t(0.5 * p_.maxThrust / ts));
    for (std::size_t i = n0; i + half < n; ++i) {
        const std::size_t lo = i - std::min(i, half);
        const auto it = std::min_element(vx.begin() + std::ptrdiff_t(lo), vx.begin() + std::ptrdiff_t(i + half + 1));
        if (std::size_t(it - vx.begin()) != i) continue;
        std::size_t b = i, e = i + 1;
        while (b > 0 && i - b < maxHalf && vx[b - 1] < vx[i] + p_.zeroSpeed) --b;
        while (e < n && e - i < maxHalf && vx[e] < vx[i] + p_.zeroSpeed) ++e;
        out.push_back({b, e});
        i += half;
    }
    return merged(out);
}

void SkiCycleAnalyzer::integrate(const SkiImu& imu, const std::vector<SkiPhase>& phases, SkiCycleResult& r) const {
    const std::size_t n = imu.size();
    // φ: rotation about the left axis (nose down positive), integrated and re-anchored to the
    // accelerometer's static φ = atan2(−a_f, a_u) in each phase (linear in between).
    std::vector<double> phiInt(n, 0.0);
    for (std::size_t i = 1; i < n; ++i)
        phiInt[i] = phiInt[i - 1] + 0.5 * (imu.gyrLeft[i] + imu.gyrLeft[i - 1]) * (imu.t[i] - imu.t[i - 1]);
    std::vector<double> at, offset;
    for (const SkiPhase& p : phases) {
        const Window w = central(p);
        at.push_back(0.5 * double(w.begin + w.end - 1));
        offset.push_back(std::atan2(-mean(imu.accForward, w), mean(imu.accUp, w)) - mean(phiInt, w));
    }
    const std::vector<double> off = interpolate(at, offset, n);
    r.inclination.assign(n, 0.0);
    std::vector<double> ax(n), az(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double phi = phiInt[i] + off[i];
        r.inclination[i] = -phi;
        ax[i] = std::cos(phi) * imu.accForward[i] + std::sin(phi) * imu.accUp[i];
        az[i] = -std::sin(phi) * imu.accForward[i] + std::cos(phi) * imu.accUp[i] - p_.gravity;
    }
    r.vx.assign(n, 0.0);
    r.vz.assign(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
        const double dt = imu.t[i] - imu.t[i - 1];
        r.vx[i] = r.vx[i - 1] + 0.5 * (ax[i] + ax[i - 1]) * dt;
        r.vz[i] = r.vz[i - 1] + 0.5 * (az[i] + az[i - 1]) * dt;
    }
    // Zero-velocity update: the drift is the mean velocity on the central 50 % of each phase.
    std::vector<double> dx, dz;
    for (const SkiPhase& p : phases) {
        const Window w = central(p);
        dx.push_back(mean(r.vx, w));
        dz.push_back(mean(r.vz, w));
    }
    const std::vector<double> driftX = interpolate(at, dx, n), driftZ = interpolate(at, dz, n);
    r.speed.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        r.vx[i] -= driftX[i];
        r.vz[i] -= driftZ[i];
        r.speed[i] = std::hypot(r.vx[i], r.vz[i]);
    }
}

std::vector<SkiPhase> SkiCycleAnalyzer::refine(const SkiImu& imu, const std::vector<SkiPhase>& phases,
                                               const SkiCycleResult& r) const {
    const std::size_t n = imu.size();
    const bool xc = p_.mode == SkiCycleParams::Mode::CrossCountry;
    auto still = [&](std::size_t i) {
        if (r.speed[i] >= p_.zeroSpeed) return false;
        if (!xc) return true;
        const double phi = -r.inclination[i];
        const double ax = std::cos(phi) * imu.accForward[i] + std::sin(phi) * imu.accUp[i];
        const double az = -std::sin(phi) * imu.accForward[i] + std::cos(phi) * imu.accUp[i] - p_.gravity;
        return std::hypot(ax, az) < p_.zeroAcc;
    };
    std::vector<SkiPhase> out;
    for (const SkiPhase& p : phases) {
        std::size_t m = p.begin;
        for (std::size_t i = p.begin; i < p.end; ++i)
            if (r.speed[i] < r.speed[m]) m = i;
        if (!still(m)) continue;
        std::size_t b = m, e = m + 1;
        while (b > 0 && still(b - 1)) --b;
        while (e < n && still(e)) ++e;
        out.push_back({b, e});
    }
    return merged(out);
}

SkiCycleResult SkiCycleAnalyzer::analyze(const SkiImu& imu) const {
    SkiCycleResult r;
    if (imu.size() < 3) return r;
    std::vector<SkiPhase> phases =
        p_.mode == SkiCycleParams::Mode::CrossCountry ? stillPhases(imu) : speedMinimumPhases(imu);
    if (phases.empty()) return r;
    for (int pass = 0; pass < 2 && !phases.empty(); ++pass) {
        integrate(imu, phases, r);
        phases = refine(imu, phases, r);
    }
    if (phases.empty()) return r;
    integrate(imu, phases, r);
    r.phases = phases;

    const double ts = interval(imu);
    for (std::size_t k = 0; k + 1 < phases.size(); ++k) {
        const SkiPhase& a = phases[k];
        const SkiPhase& b = phases[k + 1];
        const double duration = imu.t[b.begin] - imu.t[a.begin];
        if (double(a.end - a.begin) * ts > p_.maxThrust || duration < p_.minCycle || duration > p_.maxCycle) continue;
        SkiCycle c;
        c.thrustStart = imu.t[a.begin];
        c.thrustEnd = imu.t[a.end - 1];
        c.end = imu.t[b.begin];
        c.duration = duration;
        std::size_t peak = a.end;
        double dx = 0.0;
        for (std::size_t i = a.begin + 1; i <= b.begin; ++i) {
            const double dt = imu.t[i] - imu.t[i - 1];
            c.length += 0.5 * (r.speed[i] + r.speed[i - 1]) * dt;
            dx += 0.5 * (r.vx[i] + r.vx[i - 1]) * dt;
            c.elevation += 0.5 * (r.vz[i] + r.vz[i - 1]) * dt;
            if (i >= a.end && i < b.begin && r.speed[i] > r.speed[peak]) peak = i;
        }
        c.glideStart = imu.t[peak];
        c.maxSpeed = r.speed[peak];
        c.speed = c.length / duration;
        c.slope = std::atan2(c.elevation, dx);
        r.cycles.push_back(c);
    }
    return r;
}

}  // namespace athlos::events
