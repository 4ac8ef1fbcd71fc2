#include "plugins/inertial/VelocityReset.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::inertial {

using math::Quat;
using math::Vec3;

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Centred moving mean over 2·half + 1 samples (shorter at the ends).
std::vector<double> movingMean(const std::vector<double>& x, std::size_t half) {
    const std::size_t n = x.size();
    std::vector<double> prefix(n + 1, 0.0);
    for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + x[k];
    std::vector<double> out(n);
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t a = k >= half ? k - half : 0, b = std::min(n, k + half + 1);
        out[k] = (prefix[b] - prefix[a]) / double(b - a);
    }
    return out;
}

std::size_t centre(const VelocityReset::Phase& p) { return (p.begin + p.end - 1) / 2; }

// The central `share` of a phase, [first, second) (at least one sample).
std::pair<std::size_t, std::size_t> centralPart(const VelocityReset::Phase& p, double share) {
    const std::size_t length = p.end - p.begin;
    const auto trim = static_cast<std::size_t>(std::floor(0.5 * (1.0 - share) * double(length)));
    const std::size_t a = p.begin + std::min(trim, (length - 1) / 2);
    return {a, std::max(a + 1, p.end - trim)};
}
}  // namespace

std::vector<VelocityReset::Phase> VelocityReset::detect(const std::vector<Vec3>& acc, const std::vector<Vec3>& gyr,
                                                        double ts) const {
    const std::size_t n = std::min(acc.size(), gyr.size());
    std::vector<double> g(n), a(n);
    for (std::size_t k = 0; k < n; ++k) {
        g[k] = gyr[k].norm();
        a[k] = std::abs(acc[k].norm() - p_.nominalG);
    }
    const auto half = static_cast<std::size_t>(std::max(0L, std::lround(0.5 * p_.window / ts)));
    const std::vector<double> gm = movingMean(g, half), am = movingMean(a, half);
    // Spread of the acceleration vector: √(Σ_axes mean(x²) − mean(x)²) over the same window.
    std::vector<double> spread(n, 0.0);
    if (p_.accStdThreshold > 0.0)
        for (int axis = 0; axis < 3; ++axis) {
            std::vector<double> x(n), x2(n);
            for (std::size_t k = 0; k < n; ++k) {
                x[k] = acc[k][axis];
                x2[k] = x[k] * x[k];
            }
            const std::vector<double> m = movingMean(x, half), m2 = movingMean(x2, half);
            for (std::size_t k = 0; k < n; ++k) spread[k] += std::max(0.0, m2[k] - m[k] * m[k]);
        }
    const auto minLength = static_cast<std::size_t>(std::max(1L, std::lround(p_.minDuration / ts)));
    const auto maxGap = static_cast<std::size_t>(std::max(0L, std::lround(p_.mergeGap / ts)));
    std::vector<Phase> runs;
    std::size_t begin = n;
    for (std::size_t k = 0; k <= n; ++k) {
        const bool still = k < n && gm[k] < p_.gyrThreshold && (p_.accThreshold <= 0.0 || am[k] < p_.accThreshold) &&
                           (p_.accStdThreshold <= 0.0 || std::sqrt(spread[k]) < p_.accStdThreshold);
        if (still && begin == n) begin = k;
        if (!still && begin != n) {
            if (!runs.empty() && begin - runs.back().end < maxGap)
                runs.back().end = k;
            else
                runs.push_back({begin, k, Vec3::Zero(), 0.0});
            begin = n;
        }
    }
    std::vector<Phase> phases;
    for (const Phase& r : runs)
        if (r.end - r.begin >= minLength) phases.push_back(r);
    return phases;
}

void VelocityReset::integrate(const std::vector<Quat>& qIn, const std::vector<Vec3>& acc, const std::vector<Vec3>& gyr,
                              std::vector<Phase>& phases, double ts, Result& out) const {
    const std::size_t n = qIn.size();
    // Step 2a: the gyroscope bridge between phase centres.
    std::vector<Quat> bridged;
    if (p_.gyroBridge && phases.size() >= 2) {
        bridged = qIn;
        for (std::size_t i = 0; i + 1 < phases.size(); ++i) {
            const std::size_t c0 = centre(phases[i]), c1 = centre(phases[i + 1]);
            Quat f = qIn[c0];
            for (std::size_t k = c0 + 1; k <= c1; ++k) {
                f = math::integrateBodyRate(f, 0.5 * (gyr[k - 1] + gyr[k]), ts);
                bridged[k] = f;
            }
            const Quat mismatch = (qIn[c1] * f.conjugate()).normalized();
            for (std::size_t k = c0 + 1; k <= c1; ++k)
                bridged[k] = (math::slerp(Quat::Identity(), mismatch, double(k - c0) / double(c1 - c0)) * bridged[k])
                                 .normalized();
        }
    }
    const std::vector<Quat>& q = bridged.empty() ? qIn : bridged;
    out.q = q;
    out.velocity.assign(n, Vec3::Constant(kNaN));
    out.position.assign(n, Vec3::Constant(kNaN));
    out.zeroVelocity.assign(n, 0);
    out.first = 1;
    out.last = 0;
    for (const Phase& p : phases)
        for (std::size_t k = p.begin; k < p.end; ++k) out.zeroVelocity[k] = 1;

    // Step 2: inclination resets, spread by SLERP between phase centres (Fasel 2017 Eq. 2.7).
    if (p_.inclinationReset && !phases.empty()) {
        std::vector<Quat> delta(phases.size());
        for (std::size_t i = 0; i < phases.size(); ++i) {
            Vec3 sum = Vec3::Zero();
            const auto [a, b] = centralPart(phases[i], p_.anchorShare);
            for (std::size_t k = a; k < b; ++k) sum += q[k] * acc[k];
            delta[i] = sum.norm() > 0.0 ? Quat::FromTwoVectors(sum, Vec3::UnitZ()) : Quat::Identity();
            phases[i].tilt = 2.0 * std::acos(std::min(1.0, std::abs(delta[i].w())));
        }
        for (std::size_t k = 0; k <= std::min(n - 1, centre(phases.front())); ++k)
            out.q[k] = (delta.front() * q[k]).normalized();
        for (std::size_t i = 0; i + 1 < phases.size(); ++i) {
            const std::size_t c0 = centre(phases[i]), c1 = centre(phases[i + 1]);
            for (std::size_t k = c0 + 1; k <= c1; ++k)
                out.q[k] = (math::slerp(delta[i], delta[i + 1], double(k - c0) / double(c1 - c0)) * q[k]).normalized();
        }
        for (std::size_t k = centre(phases.back()) + 1; k < n; ++k) out.q[k] = (delta.back() * q[k]).normalized();
    }

    // Step 3: g from the zero-velocity samples, gravity removed in the earth frame.
    double gSum = 0.0;
    std::size_t gCount = 0;
    for (const Phase& p : phases) {
        const auto [a, b] = centralPart(p, p_.anchorShare);
        for (std::size_t k = a; k < b; ++k) gSum += acc[k].norm();
        gCount += b - a;
    }
    out.gravity = p_.gravity > 0.0 ? p_.gravity : (gCount > 0 ? gSum / double(gCount) : p_.nominalG);
    std::vector<Vec3> aE(n);
    for (std::size_t k = 0; k < n; ++k) aE[k] = out.q[k] * acc[k] - out.gravity * Vec3::UnitZ();
    out.acceleration = aE;

    // Step 4: integrate, then remove the drift anchored at the phases' central parts.
    std::vector<Vec3> v(n, Vec3::Zero());
    for (std::size_t k = 1; k < n; ++k) v[k] = v[k - 1] + 0.5 * ts * (aE[k - 1] + aE[k]);
    if (phases.size() < 2) return;
    std::vector<unsigned char> anchored(n, 0);
    for (Phase& p : phases) {
        const auto [a, b] = centralPart(p, p_.anchorShare);
        Vec3 sum = Vec3::Zero();
        for (std::size_t k = a; k < b; ++k) {
            sum += v[k];
            anchored[k] = 1;
        }
        p.drift = sum / double(b - a);
    }
    out.first = centre(phases.front());
    out.last = centre(phases.back());
    std::size_t j = 0;
    for (std::size_t k = out.first; k <= out.last; ++k) {
        while (j + 2 < phases.size() && k > centre(phases[j + 1])) ++j;
        const std::size_t c0 = centre(phases[j]), c1 = centre(phases[j + 1]);
        const double alpha = c1 > c0 ? double(k - c0) / double(c1 - c0) : 0.0;
        out.velocity[k] =
            anchored[k] ? Vec3::Zero() : Vec3(v[k] - phases[j].drift - alpha * (phases[j + 1].drift - phases[j].drift));
    }
    // Step 6: position.
    out.position[out.first].setZero();
    for (std::size_t k = out.first + 1; k <= out.last; ++k)
        out.position[k] = out.position[k - 1] + 0.5 * ts * (out.velocity[k - 1] + out.velocity[k]);
}

VelocityReset::Result VelocityReset::run(const std::vector<Quat>& q, const std::vector<Vec3>& acc,
                                         const std::vector<Vec3>& gyr, double ts, const Progress& progress) const {
    Result out;
    const auto keepGoing = [&](double f) { return !progress || progress(f); };
    if (q.empty() || q.size() != acc.size() || q.size() != gyr.size() || !(ts > 0.0)) return out;
    std::vector<Phase> phases = detect(acc, gyr, ts);
    if (!keepGoing(0.3)) return {};
    integrate(q, acc, gyr, phases, ts, out);
    if (p_.refine && phases.size() >= 2) {
        if (!keepGoing(0.6)) return {};
        // Step 5: the thrust is where the corrected speed and the inertial acceleration are small (Fasel
        // 2017 Table 3.1), never reaching into a neighbour.
        const std::size_t n = q.size();
        const auto still = [&](std::size_t k) {
            const Vec3& v = out.velocity[k];
            return v.allFinite() && v.norm() < p_.zeroSpeed && out.acceleration[k].norm() < p_.zeroAcc;
        };
        std::vector<Phase> refined;
        for (std::size_t i = 0; i < phases.size(); ++i) {
            const std::size_t lo = i == 0 ? 0 : phases[i - 1].end, hi = i + 1 < phases.size() ? phases[i + 1].begin : n;
            // From the candidate's centre (anchored, so still) outwards: shrinks a candidate that began
            // while the ski was still slowing down and grows one that the detector's window cut short.
            const std::size_t c = centre(phases[i]);
            std::size_t b = c, e = c + 1;
            while (b > lo && still(b - 1)) --b;
            while (e < hi && still(e)) ++e;
            // Before the first and after the last centre nothing is anchored: keep the candidate's ends.
            if (i == 0) b = std::min(b, phases[i].begin);
            if (i + 1 == phases.size()) e = std::max(e, phases[i].end);
            if (refined.empty() || b >= refined.back().end) refined.push_back({b, e, Vec3::Zero(), 0.0});
        }
        phases = std::move(refined);
        integrate(q, acc, gyr, phases, ts, out);
    }
    out.phases = std::move(phases);
    keepGoing(1.0);
    return out;
}

}  // namespace athlos::inertial
