// Euler/Cardan decompositions: all 12 sequences, intrinsic and extrinsic, including gimbal lock.
#include "core/math/EulerAngles.h"

#include <QStringList>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace athlos::math;

namespace {
const QStringList kSequences{"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};
// 2·atan2(|e_v|, |e_w|): unlike 2·acos(|e_w|) accurate to rounding near zero.
double angleBetween(const Quat& a, const Quat& b) {
    const Quat e = a.normalized() * b.normalized().conjugate();
    return 2.0 * std::atan2(e.vec().norm(), std::abs(e.w()));
}
}  // namespace

TEST(EulerAngles, RoundTripAllSequences) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const QString& base : kSequences) {
        for (const QString& name : {base, base.toLower()}) {
            auto seq = EulerSequence::parse(name);
            ASSERT_TRUE(seq.ok()) << qPrintable(name);
            EXPECT_EQ(seq->name(), name);
            for (int i = 0; i < 300; ++i) {
                const Quat q = Quat(u(rng), u(rng), u(rng), u(rng)).normalized();
                const Vec3 a = eulerFromQuaternion(q, *seq);
                EXPECT_LT(angleBetween(quaternionFromEuler(a, *seq), q), 1e-9) << qPrintable(name);
                if (seq->isProper()) {
                    EXPECT_GE(a[1], -1e-12);
                    EXPECT_LE(a[1], std::numbers::pi + 1e-12);
                } else {
                    EXPECT_LE(std::abs(a[1]), std::numbers::pi / 2 + 1e-12);
                }
                // Angles inside the principal ranges come back unchanged.
                Vec3 angles(2.5 * u(rng), 1.2 * u(rng), 2.5 * u(rng));
                if (seq->isProper()) angles[1] = 1.5 + 1.4 * u(rng);
                const Vec3 back = eulerFromQuaternion(quaternionFromEuler(angles, *seq), *seq);
                EXPECT_LT((back - angles).norm(), 1e-9) << qPrintable(name);
            }
        }
    }
}

TEST(EulerAngles, GimbalLockReproducesRotation) {
    for (const QString& base : kSequences) {
        for (const QString& name : {base, base.toLower()}) {
            const auto seq = *EulerSequence::parse(name);
            const double middles[] = {seq.isProper() ? 0.0 : std::numbers::pi / 2,
                                      seq.isProper() ? std::numbers::pi : -std::numbers::pi / 2};
            for (double middle : middles) {
                const Quat q = quaternionFromEuler(Vec3(0.4, middle, -0.9), seq);
                const Vec3 a = eulerFromQuaternion(q, seq);
                EXPECT_LT(angleBetween(quaternionFromEuler(a, seq), q), 1e-7)
                    << qPrintable(name) << " middle " << middle;
                EXPECT_TRUE(std::abs(a[0]) < 1e-9 || std::abs(a[2]) < 1e-9)
                    << qPrintable(name);  // one outer angle zero
            }
        }
    }
}

TEST(EulerAngles, AerospaceYawPitchRoll) {
    const auto zyx = *EulerSequence::parse(QStringLiteral("ZYX"));
    // Yaw 30° (counter-clockwise from East), pitch 10°, roll -5°.
    const double d = std::numbers::pi / 180.0;
    const Quat q = Quat(Eigen::AngleAxisd(30 * d, Vec3::UnitZ())) * Quat(Eigen::AngleAxisd(10 * d, Vec3::UnitY())) *
                   Quat(Eigen::AngleAxisd(-5 * d, Vec3::UnitX()));
    const Vec3 a = eulerFromQuaternion(q, zyx);
    EXPECT_NEAR(a[0], 30 * d, 1e-12);
    EXPECT_NEAR(a[1], 10 * d, 1e-12);
    EXPECT_NEAR(a[2], -5 * d, 1e-12);
    // Extrinsic xyz with reversed angles is the same rotation.
    const auto xyz = *EulerSequence::parse(QStringLiteral("xyz"));
    const Vec3 e = eulerFromQuaternion(q, xyz);
    EXPECT_NEAR(e[0], -5 * d, 1e-12);
    EXPECT_NEAR(e[2], 30 * d, 1e-12);
}

TEST(EulerAngles, RejectsBadSequences) {
    for (const char* bad : {"ZZX", "XY", "XyZ", "ABC", "XYZZ"}) {
        const auto s = EulerSequence::parse(QString::fromLatin1(bad));
        ASSERT_FALSE(s.ok()) << bad;
        EXPECT_TRUE(s.message().contains(QLatin1String(bad)));
    }
}

// The two-step form used by batches gives exactly the one-step angles, gimbal lock included.
TEST(EulerAngles, TwoStepEqualsOneStep) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const QString& base : kSequences) {
        for (const QString& name : {base, base.toLower()}) {
            const EulerSequence seq = *EulerSequence::parse(name);
            for (int i = 0; i < 200; ++i) {
                Quat q = Quat(u(rng), u(rng), u(rng), u(rng)).normalized();
                if (i % 10 == 0)
                    q = quaternionFromEuler(Vec3(u(rng), seq.isProper() ? 0.0 : std::numbers::pi / 2, u(rng)), seq);
                const EulerAtan2Arguments a = eulerAtan2Arguments(q, seq);
                const Vec3 twoStep = eulerFromAtan2(
                    {std::atan2(a.y[0], a.x[0]), std::atan2(a.y[1], a.x[1]), std::atan2(a.y[2], a.x[2])}, seq);
                const Vec3 oneStep = eulerFromQuaternion(q, seq);
                for (int k = 0; k < 3; ++k) EXPECT_EQ(twoStep[k], oneStep[k]) << qPrintable(name) << " sample " << i;
            }
        }
    }
}
