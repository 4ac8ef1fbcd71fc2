#include "tools/eval/ImuClockOffset.h"

#include "plugins/inertial/LowPass2.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::eval {

namespace {
using math::Quat;
using math::Vec3;

// Zero-phase low-pass: the Butterworth of LowPass2 forwards then backwards.
void zeroPhase(std::vector<Vec3>& x, double tau, double ts) {
    inertial::LowPass2<3> f(tau, ts), b(tau, ts);
    for (Vec3& v : x) v = f.step(v);
    for (std::size_t k = x.size(); k-- > 0;) x[k] = b.step(x[k]);
}

// Linear interpolation over NaN gaps (held at the ends); valid[k] = 0 where a gap was bridged.
template <class T, class Interpolate>
void bridge(std::vector<T>& x, const std::vector<unsigned char>& valid, Interpolate interpolate) {
    const std::size_t n = x.size();
    std::size_t last = n;
    for (std::size_t k = 0; k < n; ++k) {
        if (!valid[k]) continue;
        if (last == n) {
            for (std::size_t j = 0; j < k; ++j) x[j] = x[k];
        } else {
            for (std::size_t j = last + 1; j < k; ++j) {
                const double w = static_cast<double>(j - last) / static_cast<double>(k - last);
                x[j] = interpolate(x[last], x[k], w);
            }
        }
        last = k;
    }
    if (last != n)
        for (std::size_t j = last + 1; j < n; ++j) x[j] = x[last];
}
}  // namespace

ClockOffset imuClockOffset(const std::vector<Vec3>& acc, const std::vector<Quat>& q, const std::vector<Vec3>& pos,
                           double ts) {
    const std::size_t n = std::min({acc.size(), q.size(), pos.size()});
    constexpr double kTau = 0.028;  // s: f_c = √2/(2πτ) ≈ 8 Hz, above hand motion, below the optical noise
    constexpr int kMax = 3;         // whole-sample shifts tried on each side
    const std::size_t margin = static_cast<std::size_t>(std::lround(1.0 / ts));  // filter start-up
    if (n < 2 * margin + 10) return {};
    std::vector<unsigned char> valid(n);
    std::vector<Vec3> p(pos.begin(), pos.begin() + static_cast<std::ptrdiff_t>(n));
    std::vector<Quat> r(q.begin(), q.begin() + static_cast<std::ptrdiff_t>(n));
    for (std::size_t k = 0; k < n; ++k) valid[k] = p[k].allFinite() && r[k].coeffs().allFinite();
    bridge(p, valid, [](const Vec3& a, const Vec3& b, double w) { return Vec3((1.0 - w) * a + w * b); });
    bridge(r, valid, [](const Quat& a, const Quat& b, double w) { return math::slerp(a, b, w); });
    zeroPhase(p, kTau, ts);
    std::vector<Vec3> pdd(n, Vec3::Zero());
    for (std::size_t k = 1; k + 1 < n; ++k) pdd[k] = (p[k + 1] - 2.0 * p[k] + p[k - 1]) / (ts * ts);

    double cost[2 * kMax + 1];
    for (int d = -kMax; d <= kMax; ++d) {
        std::vector<Vec3> aE(n);
        for (std::size_t k = 0; k < n; ++k) {
            const auto j = static_cast<std::size_t>(
                std::clamp<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(k) + d, 0, static_cast<std::ptrdiff_t>(n - 1)));
            aE[k] = r[k] * acc[j];
        }
        zeroPhase(aE, kTau, ts);
        // Mean of the difference removed: gravity (with the accelerometer's own scale) and any bias.
        Vec3 mean = Vec3::Zero();
        std::size_t count = 0;
        for (std::size_t k = margin; k + margin < n; ++k)
            if (valid[k]) {
                mean += aE[k] - pdd[k];
                ++count;
            }
        mean /= static_cast<double>(std::max<std::size_t>(count, 1));
        double s = 0.0;
        for (std::size_t k = margin; k + margin < n; ++k)
            if (valid[k]) s += (aE[k] - pdd[k] - mean).squaredNorm();
        cost[d + kMax] = s / static_cast<double>(std::max<std::size_t>(count, 1));
    }
    const int i = static_cast<int>(std::min_element(cost, cost + 2 * kMax + 1) - cost);
    ClockOffset out;
    out.rms = std::sqrt(cost[i]);
    out.samples = i - kMax;
    if (i > 0 && i < 2 * kMax) {
        const double y0 = cost[i - 1], y1 = cost[i], y2 = cost[i + 1];
        const double den = y0 - 2.0 * y1 + y2;
        if (den > 0.0) out.samples += 0.5 * (y0 - y2) / den;
    }
    return out;
}

}  // namespace athlos::eval
