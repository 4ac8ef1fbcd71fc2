// The medio-lateral axis as the principal axis of the angular velocity (MediolateralAxis.h, eq. 1).
#include "plugins/events/MediolateralAxis.h"

#include <Eigen/Geometry>

#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

using namespace athlos::events;

TEST(MediolateralAxis, PrincipalAxisOfAFootLikeRotation) {
    // 4 rad/s swings about u, 1 rad/s about the two other axes, and noise: the axis is u up to sign,
    // the sign makes the largest component positive, dominance λ₁/Σλ as computed by hand.
    const Eigen::Vector3d u = Eigen::Vector3d(0.3, -0.9, 0.2).normalized();
    const Eigen::Vector3d v = u.unitOrthogonal(), w = u.cross(v);
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, 0.05);
    std::vector<double> gyr;
    double su = 0.0, sv = 0.0, sw = 0.0;
    for (int k = 0; k < 2000; ++k) {
        const double t = 0.01 * k, a = 4.0 * std::sin(6.0 * t), b = std::sin(11.0 * t + 1.0), c = std::cos(3.0 * t);
        const Eigen::Vector3d g = a * u + b * v + c * w;
        su += a * a;
        sv += b * b;
        sw += c * c;
        for (int i = 0; i < 3; ++i) gyr.push_back(g[i] + noise(rng));
    }
    const MediolateralAxis m = principalRotationAxis(gyr.data(), 2000, 3);
    EXPECT_GT(-m.axis.dot(u), 0.999) << m.axis.transpose();  // −u has its largest component (+0.9) positive
    EXPECT_NEAR(m.axis.norm(), 1.0, 1e-12);
    EXPECT_NEAR(m.dominance, su / (su + sv + sw), 0.01);
}

TEST(MediolateralAxis, AutoTakesANearbySensorAxis) {
    // u 11° from y (gaitmap's right foot on the stairs) → y; 30° from y (an oblique mount) → u.
    for (const double degrees : {11.0, -11.0, 30.0}) {
        const double a = degrees * M_PI / 180.0;
        const Eigen::Vector3d u(0.0, std::cos(a), std::sin(a));
        std::vector<double> gyr;
        for (int k = 0; k < 500; ++k)
            for (int i = 0; i < 3; ++i)
                gyr.push_back(3.0 * std::sin(0.05 * k) * u[i] + 0.3 * std::cos(0.11 * k) * (i == 0));
        const MediolateralAxis m = *mediolateralAxis(QStringLiteral("auto"), gyr.data(), 500, 3);
        EXPECT_GT(m.principal.dot(u), 0.999) << degrees;
        if (std::abs(degrees) < 20.0)
            EXPECT_EQ(m.axis, Eigen::Vector3d::UnitY()) << degrees;
        else
            EXPECT_EQ(m.axis, m.principal) << degrees;
    }
}

TEST(MediolateralAxis, ParameterChoices) {
    std::vector<double> still(300, 0.0);
    const auto none = principalRotationAxis(still.data(), 100, 3);
    EXPECT_EQ(none.axis, Eigen::Vector3d::UnitY());  // nothing to tell: the documented default
    EXPECT_EQ(none.dominance, 0.0);
    EXPECT_EQ(mediolateralAxis(QStringLiteral("x"), still.data(), 100, 3)->axis, Eigen::Vector3d::UnitX());
    EXPECT_EQ(mediolateralAxis(QStringLiteral("z"), still.data(), 100, 3)->axis, Eigen::Vector3d::UnitZ());
    EXPECT_FALSE(mediolateralAxis(QStringLiteral("w"), still.data(), 100, 3).has_value());
    EXPECT_EQ(axisText(Eigen::Vector3d(0.0211, 0.9977, -0.0551)), QStringLiteral("[0.021, 0.998, -0.055]"));
}
