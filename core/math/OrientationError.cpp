#include "core/math/OrientationError.h"

#include "core/math/Angles.h"

#include <cmath>

namespace athlos::math {

OrientationErrors orientationError(const Quat& estimate, const Quat& reference) {
    const Quat e = estimate.normalized() * reference.normalized().conjugate();
    OrientationErrors r;
    r.total = 2.0 * std::acos(std::clamp(std::abs(e.w()), 0.0, 1.0));
    r.heading = 2.0 * std::atan(std::abs(e.z() / e.w()));  // e_w = 0 → atan(inf) = π/2 → π
    r.inclination = 2.0 * std::acos(std::clamp(std::sqrt(e.w() * e.w() + e.z() * e.z()), 0.0, 1.0));
    return r;
}

ErrorRms orientationErrorRms(std::span<const Quat> estimate, std::span<const Quat> reference,
                             std::span<const bool> mask) {
    ErrorRms r;
    double st = 0.0, sh = 0.0, si = 0.0;
    const std::size_t n = std::min(estimate.size(), reference.size());
    for (std::size_t i = 0; i < n; ++i) {
        if (!mask.empty() && !mask[i]) continue;
        if (!estimate[i].coeffs().allFinite() || !reference[i].coeffs().allFinite()) continue;
        const OrientationErrors e = orientationError(estimate[i], reference[i]);
        st += e.total * e.total;
        sh += e.heading * e.heading;
        si += e.inclination * e.inclination;
        ++r.count;
    }
    if (r.count == 0) return r;
    const double n1 = static_cast<double>(r.count);
    r.total = std::sqrt(st / n1) / kDeg;
    r.heading = std::sqrt(sh / n1) / kDeg;
    r.inclination = std::sqrt(si / n1) / kDeg;
    return r;
}

}  // namespace athlos::math
