// core/math/Angles.h: the degree constant and wrapAngle (range (−π, π], in-range angles unchanged
// bit for bit, far angles, non-finite input).
#include "core/math/Angles.h"

#include <gtest/gtest.h>
#include <cmath>
#include <limits>
#include <numbers>

using athlos::math::kDeg;
using athlos::math::wrapAngle;
using std::numbers::pi;

TEST(Angles, DegreeIsPiOver180) {
    EXPECT_EQ(kDeg, pi / 180.0);
    EXPECT_DOUBLE_EQ(180.0 * kDeg, pi);
    EXPECT_DOUBLE_EQ(90.0 * kDeg, pi / 2);
    EXPECT_NEAR(pi / kDeg, 180.0, 1e-12);
    EXPECT_NEAR(1.0 / kDeg, 57.29577951308232, 1e-12);  // one radian in degrees
}

TEST(Angles, WrapKeepsAnglesInRangeUnchanged) {
    for (const double a : {0.0, -0.0, 1e-300, 0.5, -0.5, 3.0, -3.0, pi, std::nextafter(-pi, 0.0)})
        EXPECT_EQ(wrapAngle(a), a) << a;
}

TEST(Angles, WrapRangeIsHalfOpen) {
    EXPECT_EQ(wrapAngle(pi), pi);   // π stays
    EXPECT_EQ(wrapAngle(-pi), pi);  // −π becomes π
    EXPECT_NEAR(wrapAngle(3 * pi), pi, 1e-12);
    EXPECT_NEAR(wrapAngle(-3 * pi), pi, 1e-12);
}

TEST(Angles, WrapNearAndFar) {
    EXPECT_NEAR(wrapAngle(2 * pi + 0.25), 0.25, 1e-15);
    EXPECT_NEAR(wrapAngle(-2 * pi - 0.25), -0.25, 1e-15);
    EXPECT_NEAR(wrapAngle(3.5 * pi), -0.5 * pi, 1e-12);
    EXPECT_NEAR(wrapAngle(-7.5 * pi), 0.5 * pi, 1e-12);
    EXPECT_NEAR(wrapAngle(1000.0 * 2 * pi + 1.0), 1.0, 1e-9);
    for (double a = -50.0; a <= 50.0; a += 0.37) {
        const double w = wrapAngle(a);
        EXPECT_GT(w, -pi) << a;
        EXPECT_LE(w, pi) << a;
        EXPECT_NEAR(std::remainder(a - w, 2 * pi), 0.0, 1e-12) << a;  // a whole number of turns apart
    }
}

TEST(Angles, WrapPassesNonFiniteThrough) {
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_TRUE(std::isnan(wrapAngle(std::numeric_limits<double>::quiet_NaN())));
    EXPECT_EQ(wrapAngle(inf), inf);
    EXPECT_EQ(wrapAngle(-inf), -inf);
}
