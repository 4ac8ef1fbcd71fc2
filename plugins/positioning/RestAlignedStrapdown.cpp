#include "plugins/positioning/RestAlignedStrapdown.h"

#include <algorithm>

namespace athlos::positioning {

using math::Quat;
using math::Vec3;

namespace {
// The earth-frame rotation that turns the specific force f (earth frame) to the vertical.
Quat levelling(const Vec3& fEarth) { return Quat::FromTwoVectors(fEarth.normalized(), Vec3::UnitZ()); }
}  // namespace

Expected<std::vector<Quat>> RestAlignedStrapdown::compute(const std::vector<double>& t, const std::vector<Vec3>& gyr,
                                                          const std::vector<Vec3>& acc, const std::vector<Quat>& stream,
                                                          const std::vector<unsigned char>& startStill,
                                                          const std::vector<unsigned char>& finishStill) {
    const std::size_t n = t.size();
    std::size_t s = 0;
    while (s < n && s < startStill.size() && startStill[s]) ++s;
    if (s < 2 || s >= n) return makeError(QStringLiteral("no rest at the start to calibrate the gyroscope on"));
    Vec3 bias = Vec3::Zero(), f0 = Vec3::Zero();
    for (std::size_t k = 0; k < s; ++k) {
        bias += gyr[k];
        f0 += acc[k];
    }
    bias /= double(s);
    f0 /= double(s);
    Quat q = stream[s - 1].normalized();
    q = (levelling(q * f0) * q).normalized();
    std::vector<Quat> out(n);
    for (std::size_t k = 0; k < s; ++k) out[k] = q;
    for (std::size_t k = s; k < n; ++k) {
        q = math::integrateBodyRate(q, gyr[k] - bias, t[k] - t[k - 1]);
        out[k] = q;
    }
    std::size_t e = n;
    while (e > s && e - 1 < finishStill.size() && finishStill[e - 1]) --e;
    if (e >= n || e <= s) return out;  // no finish rest: no drift removal
    Vec3 f1 = Vec3::Zero();
    for (std::size_t k = e; k < n; ++k) f1 += out[k] * acc[k];
    const Vec3 delta = math::rotationVectorFromQuat(levelling(f1 / double(n - e)));
    const double t0 = t[s - 1], t1 = t[e];
    for (std::size_t k = s; k < n; ++k) {
        const double alpha = std::clamp((t[k] - t0) / (t1 - t0), 0.0, 1.0);
        out[k] = (math::quatFromRotationVector(alpha * delta) * out[k]).normalized();
    }
    return out;
}

}  // namespace athlos::positioning
