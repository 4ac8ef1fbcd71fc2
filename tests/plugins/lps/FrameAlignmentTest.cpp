// Frame alignment (§3.1.2 step 9, Kabsch [Kabs 76]): marks land exactly where the user says.
#include "plugins/lps/FrameAlignment.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

using namespace athlos::lps;

namespace {
RigidTransform known() {
    RigidTransform t;
    t.rotation = Eigen::AngleAxisd(0.7, Vector3::UnitZ()).toRotationMatrix();
    t.translation = Vector3(12.5, -3.0, 0.4);
    return t;
}
}  // namespace

TEST(FrameAlignment, TwoMarksYawMapExactly) {
    const RigidTransform truth = known();
    const std::vector<Vector3> from = {Vector3(1, 2, 0), Vector3(40, -7, 0)};
    std::vector<Vector3> to;
    for (const auto& p : from) to.push_back(truth.apply(p));
    auto t = fitRigid(from, to, AlignMode::Yaw);
    ASSERT_TRUE(t.ok());
    for (std::size_t k = 0; k < from.size(); ++k) EXPECT_LT((t->apply(from[k]) - to[k]).norm(), 1e-9);
    EXPECT_LT((t->rotation - truth.rotation).norm(), 1e-9);
}

TEST(FrameAlignment, ThreeMarksFullKabschMapExactly) {
    RigidTransform truth;
    truth.rotation =
        (Eigen::AngleAxisd(0.3, Vector3::UnitX()) * Eigen::AngleAxisd(-1.1, Vector3::UnitZ())).toRotationMatrix();
    truth.translation = Vector3(-5, 8, 2);
    const std::vector<Vector3> from = {Vector3(0, 0, 0), Vector3(30, 0, 1), Vector3(5, 20, -2)};
    std::vector<Vector3> to;
    for (const auto& p : from) to.push_back(truth.apply(p));
    auto t = fitRigid(from, to, AlignMode::Full);
    ASSERT_TRUE(t.ok());
    for (std::size_t k = 0; k < from.size(); ++k) EXPECT_LT((t->apply(from[k]) - to[k]).norm(), 1e-9);
    EXPECT_NEAR(t->rotation.determinant(), 1.0, 1e-12);  // no reflection
}

TEST(FrameAlignment, RefusesDegenerateMarks) {
    EXPECT_FALSE(fitRigid({Vector3(0, 0, 0)}, {Vector3(1, 1, 1)}, AlignMode::Yaw).ok());
    const std::vector<Vector3> line = {Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(2, 0, 0)};
    EXPECT_FALSE(fitRigid(line, line, AlignMode::Full).ok());
}

TEST(FrameAlignment, YawAboutPivotAndAlignedRmse) {
    const Vector3 pivot(1, 1, 0);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(0.05, Vector3::UnitZ()).toRotationMatrix();
    std::vector<Vector3> from = {Vector3(50, 0, 3), Vector3(0, 40, 5), Vector3(-60, -10, 4)}, to;
    for (const auto& p : from) to.push_back(pivot + r * (p - pivot));
    EXPECT_NEAR(fitYawAboutPivot(from, to, pivot), 0.05, 1e-12);
    EXPECT_LT(alignedRmse(from, to), 1e-9);
}
