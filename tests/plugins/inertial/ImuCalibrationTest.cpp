// IMU calibration: magnetometer ellipsoid fit, six-position accelerometer calibration, static
// segments, saturation.
#include "plugins/inertial/ImuCalibration.h"

#include <gtest/gtest.h>
#include <random>

using namespace athlos::inertial;

TEST(ImuCalibration, EllipsoidFitRecoversHardAndSoftIron) {
    std::mt19937 rng(11);
    std::normal_distribution<double> n;
    Mat3 soft;  // symmetric distortion
    soft << 1.10, 0.05, -0.03, 0.05, 0.92, 0.02, -0.03, 0.02, 1.04;
    const Vec3 hard(12.0, -30.0, 5.0);
    std::vector<Vec3> samples;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 dir = Vec3(n(rng), n(rng), n(rng)).normalized();
        samples.push_back(soft * (48.0 * dir) + hard + 0.2 * Vec3(n(rng), n(rng), n(rng)));
    }
    const auto c = calibrateMagnetometer(samples);
    ASSERT_TRUE(c.has_value());
    EXPECT_LT((c->hardIron - hard).norm(), 0.2);
    const Mat3 product = c->softIron * soft / (c->radius / 48.0);  // A·S ∝ I
    EXPECT_LT((product - Mat3::Identity()).norm(), 0.01) << product;
    EXPECT_NEAR(c->radius, 48.0 * std::cbrt(soft.determinant()), 0.5);
    EXPECT_LT(c->rms, 0.3);
}

TEST(ImuCalibration, SixPositionRecoversOffsetAndScale) {
    const Vec3 offset(0.15, -0.2, 0.08), scale(1.02, 0.97, 1.01);
    std::vector<Vec3> means;
    for (int axis = 0; axis < 3; ++axis)
        for (double s : {1.0, -1.0}) {
            Vec3 a = Vec3::Zero();
            a[axis] = s * 9.81;
            means.push_back(scale.cwiseProduct(a) + offset);
        }
    const auto c = calibrateAccelerometer(means, 9.81);
    ASSERT_TRUE(c.has_value());
    EXPECT_LT((c->offset - offset).norm(), 1e-6);
    EXPECT_LT((c->scale - scale).norm(), 1e-7);
    means.pop_back();  // z never points down any more: refuse
    means.push_back(means.front());
    EXPECT_FALSE(calibrateAccelerometer(means, 9.81).has_value());
}

TEST(ImuCalibration, StaticSegmentsAndGyroOffset) {
    // 3 s rest, 2 s rotation, 6 s rest at 100 Hz with a gyro offset.
    const Vec3 gyrOffset(0.01, -0.02, 0.005);
    std::vector<double> v;
    for (int k = 0; k < 1100; ++k) {
        const bool moving = k >= 300 && k < 500;
        const Vec3 g = gyrOffset + (moving ? Vec3(0, 0, 2.0) : Vec3::Zero());
        const Vec3 a(0, 0, 9.81);
        v.insert(v.end(), a.data(), a.data() + 3);
        v.insert(v.end(), g.data(), g.data() + 3);
    }
    const ImuBatch b{v.data() + 3, v.data(), nullptr, 1100, 6};
    const auto segments = findStaticSegments(b, 0.01, 1.5);
    ASSERT_EQ(segments.size(), 2u);
    EXPECT_LT((segments[0].gyr - gyrOffset).norm(), 1e-12);
    EXPECT_LE(segments[0].end, 300u);
    EXPECT_GE(segments[1].begin, 500u);
}

TEST(ImuCalibration, SaturationCount) {
    std::vector<double> v{1, 2, 3, 16, 0, 0, 16, 0, 0, 16, 0, 0, 5, 0, 0};
    EXPECT_EQ(countSaturated(v.data(), 5, 3, 0.0)[0], 3);  // clipped run at the extreme
    EXPECT_EQ(countSaturated(v.data(), 5, 3, 16.0)[0], 3);
    EXPECT_EQ(countSaturated(v.data(), 5, 3, 0.0)[1], 0);
}

TEST(ImuCalibration, EllipsoidFitRefusesPlanarCoverage) {
    std::vector<Vec3> ring;  // turning about the vertical only
    for (int i = 0; i < 500; ++i) {
        const double a = 0.05 * i;
        ring.emplace_back(20.0 * std::cos(a) + 5.0, 20.0 * std::sin(a), -44.0);
    }
    EXPECT_FALSE(calibrateMagnetometer(ring).has_value());
}
