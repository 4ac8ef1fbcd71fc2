#pragma once
// Angles: the one degree constant, the one angle wrap, and the one spelling of π (std::numbers::pi).
//
// Angles are radians inside (ARCHITECTURE.md: SI units). Degrees appear only at the edges:
//   const double a = 30.0 * math::kDeg;    // 30° in radians
//   const double d = angle / math::kDeg;   // radians in degrees
#include <cmath>
#include <numbers>

namespace athlos::math {

// One degree in radians, π/180.
inline constexpr double kDeg = std::numbers::pi / 180.0;

// Wraps an angle to (−π, π]. Angles already in range come back unchanged (bit for bit), one turn
// away costs one subtraction (filters call it every step); further ones go through std::remainder.
// NaN and ±∞ come back unchanged.
namespace detail {
double wrapAngleFar(double angle);  // the rare path of wrapAngle(), out of line
}
inline double wrapAngle(double angle) {
    constexpr double pi = std::numbers::pi;
    if (angle > pi)
        angle -= 2.0 * pi;
    else if (angle <= -pi)
        angle += 2.0 * pi;
    return angle > pi || angle <= -pi ? detail::wrapAngleFar(angle) : angle;
}

}  // namespace athlos::math
