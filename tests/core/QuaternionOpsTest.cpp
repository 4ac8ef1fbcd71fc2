// Quaternion toolkit: exp/log, rotation vectors, SLERP, Markley averaging, error metrics.
#include "core/math/OrientationError.h"
#include "core/math/QuaternionAverage.h"
#include "core/math/QuaternionOps.h"

#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace athlos::math;

namespace {
constexpr double kPi = std::numbers::pi;
double angleBetween(const Quat& a, const Quat& b) { return orientationError(a, b).total; }
Quat randomQuat(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}
}  // namespace

TEST(QuaternionOps, ExpLogRoundTrip) {
    std::mt19937 rng(3);
    for (int i = 0; i < 200; ++i) {
        const Quat q = canonical(randomQuat(rng));
        const Quat back = quatExp(quatLog(q));
        EXPECT_NEAR((back.coeffs() - q.coeffs()).norm(), 0.0, 1e-12);
    }
    EXPECT_NEAR(quatLog(Quat::Identity()).norm(), 0.0, 1e-15);
    // exp of a pure quaternion of norm π/2 about z: 180° rotation about z.
    const Quat half = quatExp(Vec3(0, 0, kPi / 2));
    EXPECT_NEAR(half.w(), 0.0, 1e-15);
    EXPECT_NEAR(half.z(), 1.0, 1e-15);
}

TEST(QuaternionOps, RotationVectorMatchesEigenAngleAxis) {
    const Vec3 r(0.3, -1.1, 0.7);
    const Quat q = quatFromRotationVector(r);
    const Quat e(Eigen::AngleAxisd(r.norm(), r.normalized()));
    EXPECT_NEAR(angleBetween(q, e), 0.0, 1e-12);
    EXPECT_NEAR((rotationVectorFromQuat(q) - r).norm(), 0.0, 1e-12);
    // Conventions: sensor→earth, v_E = q v_S; 90° about z maps sensor x to earth y (north).
    EXPECT_NEAR(((quatFromAxisAngle(Vec3::UnitZ(), kPi / 2) * Vec3::UnitX()) - Vec3::UnitY()).norm(), 0.0, 1e-12);
}

TEST(QuaternionOps, StrapdownConstantRateIsExact) {
    const Vec3 w(0.4, -0.2, 1.3);  // rad/s, body frame
    const double dt = 0.01;
    Quat q = quatFromAxisAngle(Vec3(1, 2, 3), 0.5);
    const Quat q0 = q;
    for (int k = 0; k < 1000; ++k) q = integrateBodyRate(q, w, dt);
    const Quat expected = q0 * quatFromRotationVector(w * 10.0);  // constant body rate: q0 ⊗ exp(ω t / 2)
    EXPECT_LT(angleBetween(q, expected), 1e-9);
}

TEST(QuaternionOps, SlerpEndpointsMidpointAndShortestArc) {
    const Quat a = quatFromAxisAngle(Vec3::UnitX(), 0.2);
    const Quat b = quatFromAxisAngle(Vec3::UnitX(), 1.4);
    EXPECT_LT(angleBetween(slerp(a, b, 0.0), a), 1e-12);
    EXPECT_LT(angleBetween(slerp(a, b, 1.0), b), 1e-12);
    EXPECT_LT(angleBetween(slerp(a, b, 0.5), quatFromAxisAngle(Vec3::UnitX(), 0.8)), 1e-12);
    Quat negB;
    negB.coeffs() = -b.coeffs();
    EXPECT_LT(angleBetween(slerp(a, negB, 0.5), quatFromAxisAngle(Vec3::UnitX(), 0.8)), 1e-12);
    EXPECT_NEAR(slerp(a, b, 0.37).norm(), 1.0, 1e-12);
}

TEST(QuaternionOps, MarkleyAverageOfSymmetricSetIsCentre) {
    const Quat centre = quatFromAxisAngle(Vec3(1, -1, 2), 1.0);
    std::vector<Quat> set;
    for (int ax = 0; ax < 3; ++ax) {
        const Vec3 axis = Vec3::Unit(ax);
        for (double s : {-1.0, 1.0}) {
            Quat q = centre * quatFromAxisAngle(axis, s * 0.3);
            if (s > 0) q.coeffs() = -q.coeffs();  // sign flips must not matter
            set.push_back(q);
        }
    }
    EXPECT_LT(angleBetween(markleyAverage(set), centre), 1e-10);
    // Weights pull the average towards the heavier member.
    const std::vector<Quat> two{Quat::Identity(), quatFromAxisAngle(Vec3::UnitZ(), 1.0)};
    const std::vector<double> w{1.0, 3.0};
    EXPECT_GT(headingAngle(markleyAverage(two, w)), 0.5);
}

TEST(OrientationError, MetricsSplitHeadingAndInclination) {
    const Quat ref = quatFromAxisAngle(Vec3(0.3, 0.2, 1.0), 0.7);
    const Quat yawErr = headingRotation(0.1) * ref;  // error about earth z only
    auto e = orientationError(yawErr, ref);
    EXPECT_NEAR(e.total, 0.1, 1e-12);
    EXPECT_NEAR(e.heading, 0.1, 1e-12);
    EXPECT_NEAR(e.inclination, 0.0, 1e-7);
    const Quat tiltErr = quatFromAxisAngle(Vec3::UnitX(), 0.05) * ref;  // horizontal axis in E
    e = orientationError(tiltErr, ref);
    EXPECT_NEAR(e.inclination, 0.05, 1e-12);
    EXPECT_NEAR(e.heading, 0.0, 1e-12);
    const std::vector<Quat> est{yawErr, ref}, refs{ref, ref};
    const bool mask[] = {true, false};
    const auto rms = orientationErrorRms(est, refs, mask);
    EXPECT_EQ(rms.count, 1);
    EXPECT_NEAR(rms.heading, 0.1 * 180.0 / kPi, 1e-9);
}

TEST(QuaternionOps, AccMagGivesEnuOrientation) {
    const Quat truth = quatFromAxisAngle(Vec3(0.2, -0.4, 1.0), 1.2);
    const Vec3 field(0.0, 20.0, -44.0);
    const Vec3 acc = truth.conjugate() * Vec3(0, 0, 9.81), mag = truth.conjugate() * field;
    EXPECT_LT(angleBetween(quatFromAccMag(acc, mag), truth), 1e-9);
    EXPECT_NEAR(orientationError(quatFromAccelerometer(acc), truth).inclination, 0.0, 1e-9);
    Quat h, i;
    splitHeadingInclination(truth, h, i);
    EXPECT_LT(angleBetween(h * i, truth), 1e-12);
    EXPECT_NEAR(i.z(), 0.0, 1e-12);
}
