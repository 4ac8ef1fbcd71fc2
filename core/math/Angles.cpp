#include "core/math/Angles.h"

namespace athlos::math::detail {

double wrapAngleFar(double angle) {
    constexpr double pi = std::numbers::pi;
    if (!std::isfinite(angle)) return angle;
    angle = std::remainder(angle, 2.0 * pi);  // [−π, π]
    return angle <= -pi ? angle + 2.0 * pi : angle;
}

}  // namespace athlos::math::detail
