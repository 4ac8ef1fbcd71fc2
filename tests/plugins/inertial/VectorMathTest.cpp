// The vectorised acos/atan2 (SLEEF, ≤ 1 ULP) against the C library, odd lengths, clamping and NaN.
#include "plugins/inertial/VectorMath.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace athlos::inertial;

namespace {
// |a − b| in units of the last place of b (2 ULP allows 1 ULP on either side of the true value).
double ulps(double a, double b) {
    if (a == b) return 0.0;
    return std::abs(a - b) / std::abs(std::nextafter(b, 2.0 * b + 1.0) - b);
}
}  // namespace

TEST(VectorMath, AcosMatchesTheCLibraryAndClamps) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> x(1001);  // odd: the scalar tail runs too
    for (double& v : x) v = u(rng);
    x[0] = 1.0;
    x[1] = -1.0;
    x[2] = 1.0 + 1e-12;  // rounding past ±1 (a dot product of unit vectors) is clamped, not NaN
    x[3] = -1.0 - 1e-12;
    x[4] = 1.0 - 1e-15;  // near 1, where acos is steep
    std::vector<double> out(x.size());
    acosBatch(x, out);
    for (std::size_t i = 0; i < x.size(); ++i)
        EXPECT_LE(ulps(out[i], std::acos(std::clamp(x[i], -1.0, 1.0))), 2.0) << "x = " << x[i];
    EXPECT_EQ(out[2], 0.0);
    EXPECT_DOUBLE_EQ(out[3], M_PI);
    // In place, and NaN stays NaN in both the vector part and the tail.
    std::vector<double> y{0.5, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    acosBatch(y, y);
    EXPECT_NEAR(y[0], M_PI / 3.0, 1e-15);
    EXPECT_TRUE(std::isnan(y[1]));
    EXPECT_TRUE(std::isnan(y[2]));
}

TEST(VectorMath, Atan2MatchesTheCLibraryInEveryQuadrant) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    std::vector<double> y(777), x(777);
    for (std::size_t i = 0; i < y.size(); ++i) {
        y[i] = u(rng);
        x[i] = u(rng);
    }
    y[0] = 0.0, x[0] = -1.0;   // π
    y[1] = -0.0, x[1] = -1.0;  // −π
    y[2] = 1.0, x[2] = 0.0;    // π/2
    y[3] = 1e-300, x[3] = 1.0;
    std::vector<double> out(y.size());
    atan2Batch(y, x, out);
    for (std::size_t i = 0; i < y.size(); ++i)
        EXPECT_LE(ulps(out[i], std::atan2(y[i], x[i])), 2.0) << "y = " << y[i] << ", x = " << x[i];
    atan2Batch(y, x, y);  // in place
    EXPECT_EQ(y, out);
}
