// Joint angles: analytic decompositions with independently built rotations (axis-angle products and
// geometric checks of what "abduction" and "internal rotation" move), left/right mirroring, heading
// alignment, time alignment, and the end-to-end validation simulate-limb → orientation (6D) →
// joint-angles against the simulator's reference angles.
#include "core/math/Angles.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/inertial/JointAngles.h"
#include "plugins/inertial/JointAnglesProcessor.h"
#include "plugins/inertial/LimbSimulator.h"
#include "plugins/inertial/OrientationProcessor.h"
#include "plugins/inertial/SegmentCalibrationProcessor.h"
#include "plugins/inertial/SegmentMounts.h"
#include "plugins/inertial/SimulateLimbProcessor.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <random>

using namespace athlos;
using namespace athlos::inertial;
using math::Quat;
using math::Vec3;

namespace {

using math::kDeg;

Quat rot(const Vec3& axis, double degrees) { return math::quatFromAxisAngle(axis, degrees * kDeg); }

AnatomicalAngles anglesOf(const Quat& relative, Joint joint, Side side) {
    JointAngles::Params p;
    p.joint = joint;
    p.side = side;
    return JointAngles(p).update(Quat::Identity(), relative).angles;
}

void expectAngles(const AnatomicalAngles& a, double flexion, double abduction, double rotation, double tol = 1e-9) {
    EXPECT_NEAR(a.flexion / kDeg, flexion, tol);
    EXPECT_NEAR(a.abduction / kDeg, abduction, tol);
    EXPECT_NEAR(a.rotation / kDeg, rotation, tol);
}

// Reflection through the sagittal plane (Z → −Z) applied to a rotation: M R M.
Quat mirror(const Quat& q) {
    const Eigen::Matrix3d m = Eigen::Vector3d(1, 1, -1).asDiagonal();
    return Quat(Eigen::Matrix3d(m * q.toRotationMatrix() * m)).normalized();
}

}  // namespace

TEST(JointAngles, PureFlexion) {
    // Knee flexion moves the shank's lower end backwards: its long axis Y tilts forward (+X), a
    // negative rotation about Z.
    const Quat knee = rot(Vec3::UnitZ(), -30);
    EXPECT_GT((knee * Vec3::UnitY()).x(), 0.0);
    expectAngles(anglesOf(knee, Joint::Knee, Side::Right), 30, 0, 0);
    expectAngles(anglesOf(knee, Joint::Knee, Side::Left), 30, 0, 0);
    // Hip flexion lifts the thigh forward: the knee (−Y) goes anterior, a positive rotation about Z.
    const Quat hip = rot(Vec3::UnitZ(), 30);
    EXPECT_GT((hip * -Vec3::UnitY()).x(), 0.0);
    expectAngles(anglesOf(hip, Joint::Hip, Side::Right), 30, 0, 0);
    // Ankle dorsiflexion lifts the toes (+X tilts up).
    expectAngles(anglesOf(rot(Vec3::UnitZ(), 15), Joint::Ankle, Side::Right), 15, 0, 0);
    // Trunk flexion bends the thorax forward.
    expectAngles(anglesOf(rot(Vec3::UnitZ(), -25), Joint::Trunk, Side::Right), 25, 0, 0);
    // 2D angle: the long axes enclose the flexion angle.
    JointAngles::Params p;
    EXPECT_NEAR(JointAngles(p).update(Quat::Identity(), knee).longAxisAngle / kDeg, 30, 1e-9);
}

TEST(JointAngles, AbductionAndRotationMeanTheAnatomicalMovement) {
    // Right knee abduction: the shank's lower end (−Y) moves laterally (+Z on the right side).
    const Quat abducted = rot(Vec3::UnitX(), -10);
    EXPECT_GT((abducted * -Vec3::UnitY()).z(), 0.0);
    expectAngles(anglesOf(abducted, Joint::Knee, Side::Right), 0, 10, 0);
    // Right internal rotation: the anterior axis turns medially (−Z on the right).
    const Quat internal = rot(Vec3::UnitY(), 15);
    EXPECT_LT((internal * Vec3::UnitX()).z(), 0.0);
    expectAngles(anglesOf(internal, Joint::Knee, Side::Right), 0, 0, 15);
    // On the left, lateral and medial are −Z and +Z: the same rotations are adduction and external rotation.
    expectAngles(anglesOf(abducted, Joint::Knee, Side::Left), 0, -10, 0);
    expectAngles(anglesOf(internal, Joint::Knee, Side::Left), 0, 0, -15);
}

TEST(JointAngles, CombinedRotationsReconstructTheRelativeRotation) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const double flex = 60 * u(rng) + 40, abd = 25 * u(rng), rotation = 30 * u(rng);
        for (Joint joint : {Joint::Knee, Joint::Hip, Joint::Ankle, Joint::Trunk})
            for (Side side : {Side::Right, Side::Left}) {
                // Built by hand from the Grood & Suntay axes: proximal Z, floating X, distal Y.
                const double fs = (joint == Joint::Knee || joint == Joint::Trunk) ? -1 : 1;
                const double as = joint == Joint::Trunk ? 1 : (side == Side::Right ? -1 : 1);
                const double rs = joint == Joint::Trunk ? 1 : (side == Side::Right ? 1 : -1);
                const Quat relative =
                    rot(Vec3::UnitZ(), fs * flex) * rot(Vec3::UnitX(), as * abd) * rot(Vec3::UnitY(), rs * rotation);
                EXPECT_LT(relativeFromAnatomical({flex * kDeg, abd * kDeg, rotation * kDeg}, joint, side)
                              .angularDistance(relative),
                          1e-12);
                // Through arbitrary sensor orientations and mounts.
                JointAngles::Params p;
                p.joint = joint;
                p.side = side;
                p.proximalMount = math::quatFromRotationVector(Vec3(u(rng), u(rng), u(rng)) * 2.0);
                p.distalMount = math::quatFromRotationVector(Vec3(u(rng), u(rng), u(rng)) * 2.0);
                const Quat proximalSegment = math::quatFromRotationVector(Vec3(u(rng), u(rng), u(rng)) * 3.0);
                const Quat proximalSensor = proximalSegment * p.proximalMount.conjugate();
                const Quat distalSensor = proximalSegment * relative * p.distalMount.conjugate();
                const JointAngles::Sample s = JointAngles(p).update(proximalSensor, distalSensor);
                expectAngles(s.angles, flex, abd, rotation, 1e-8);
                EXPECT_LT(s.relative.angularDistance(relative), 1e-9);
            }
    }
}

// The batch (blocks of vectorised acos/atan2) gives the rows of update() to a few ULP, including a
// length that is not a multiple of the block, a heading offset, gaps and unnormalised inputs.
TEST(JointAngles, BatchRowsEqualPerSampleUpdate) {
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (Side side : {Side::Right, Side::Left}) {
        JointAngles::Params p;
        p.joint = Joint::Hip;
        p.side = side;
        p.proximalMount = math::quatFromRotationVector(Vec3(u(rng), u(rng), u(rng)));
        p.distalMount = math::quatFromRotationVector(Vec3(u(rng), u(rng), u(rng)));
        p.headingOffset = 0.7;
        const std::size_t n = 1000;
        std::vector<Quat> proximal(n), distal(n);
        for (std::size_t k = 0; k < n; ++k) {
            proximal[k] = math::quatFromRotationVector(Vec3(u(rng), u(rng), u(rng)) * 3.0);
            distal[k] = math::quatFromRotationVector(Vec3(u(rng), u(rng), u(rng)) * 3.0);
        }
        proximal[5].coeffs() *= 1.001;  // a stored quaternion slightly off unit length
        const double nan = std::numeric_limits<double>::quiet_NaN();
        proximal[300] = Quat(nan, nan, nan, nan);
        distal[999] = Quat(nan, 0, 0, 0);
        const JointAngles joint(p);
        const std::vector<double> rows = joint.updateBatch(proximal, distal);
        ASSERT_EQ(rows.size(), n * JointAngles::kColumns);
        for (std::size_t k = 0; k < n; ++k) {
            const double* row = &rows[k * JointAngles::kColumns];
            if (k == 300 || k == 999) {
                for (std::size_t c = 0; c < JointAngles::kColumns; ++c) EXPECT_TRUE(std::isnan(row[c]));
                continue;
            }
            const JointAngles::Sample s = joint.update(proximal[k], distal[k]);
            const double expected[] = {s.angles.flexion, s.angles.abduction,    s.angles.rotation,
                                       s.longAxisAngle,  s.proximalInclination, s.distalInclination};
            for (std::size_t c = 0; c < JointAngles::kColumns; ++c)
                EXPECT_NEAR(row[c], expected[c], 1e-12) << "sample " << k << " column " << c;
        }
    }
}

TEST(JointAngles, LeftSideIsTheMirrorImage) {
    for (Joint joint : {Joint::Knee, Joint::Hip, Joint::Ankle}) {
        const Quat right = relativeFromAnatomical({40 * kDeg, 8 * kDeg, 12 * kDeg}, joint, Side::Right);
        // The same anatomical posture on the left leg is the reflection of the right one.
        expectAngles(anglesOf(mirror(right), joint, Side::Left), 40, 8, 12);
        expectAngles(anglesOf(right, joint, Side::Right), 40, 8, 12);
        // Reading a right-side rotation as left keeps flexion and flips the other two.
        expectAngles(anglesOf(right, joint, Side::Left), 40, -8, -12);
    }
}

TEST(JointAngles, HeadingOffsetOfIndependentEarthFrames) {
    // Two 6D filters: the distal sensor's earth frame is turned by −37° about the vertical.
    JointAngles::Params p;
    p.proximalMount = rot(Vec3(1, 2, 3), 70);
    p.distalMount = rot(Vec3(-2, 1, 0.5), 110);
    const Quat upright = rot(Vec3::UnitX(), 90);  // ISB segment frame standing, facing East
    std::vector<Quat> proximal, distal;
    for (int k = 0; k < 50; ++k) {
        const Quat facing = math::headingRotation(0.3 + 0.01 * k) * upright;
        const Quat knee = relativeFromAnatomical({(20 + k) * kDeg, 0, 0}, Joint::Knee, Side::Right);
        proximal.push_back(facing * p.proximalMount.conjugate());
        distal.push_back(math::headingRotation(-37 * kDeg) * facing * knee * p.distalMount.conjugate());
    }
    const double offset = JointAngles::estimateHeadingOffset(proximal, distal, p.proximalMount, p.distalMount);
    EXPECT_NEAR(offset / kDeg, 37, 1e-9);
    // Uncorrected, the offset shows mostly as axial rotation (not exactly: the shank is tilted).
    EXPECT_GT(std::abs(JointAngles(p).update(proximal[10], distal[10]).angles.rotation / kDeg), 25);
    p.headingOffset = offset;
    expectAngles(JointAngles(p).update(proximal[10], distal[10]).angles, 30, 0, 0, 1e-8);
}

TEST(JointAngles, SlerpOntoOtherTimesAndParsing) {
    const std::vector<double> ts{0.0, 1.0, 2.0};
    const std::vector<Quat> qs{Quat::Identity(), rot(Vec3::UnitZ(), 40), rot(Vec3::UnitZ(), 80)};
    const std::vector<double> t{-0.5, 0.25, 1.0, 1.5, 2.5};
    const std::vector<Quat> at = slerpAt(ts, qs, t);
    EXPECT_FALSE(at[0].coeffs().allFinite());
    EXPECT_LT(at[1].angularDistance(rot(Vec3::UnitZ(), 10)), 1e-12);
    EXPECT_LT(at[2].angularDistance(qs[1]), 1e-12);
    EXPECT_LT(at[3].angularDistance(rot(Vec3::UnitZ(), 60)), 1e-12);
    EXPECT_FALSE(at[4].coeffs().allFinite());

    auto q = parseQuaternion("0.5, 0.5 0.5;0.5", "distal_mount");
    ASSERT_TRUE(q.ok());
    EXPECT_NEAR(q->w(), 0.5, 1e-15);
    auto bad = parseQuaternion("1,0,0", "distal_mount");
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("distal_mount"));
    EXPECT_FALSE(parseQuaternion("1,0,x,0", "proximal_mount").ok());
    EXPECT_FALSE(parseQuaternion("0,0,0,0", "proximal_mount").ok());
    EXPECT_FALSE(parseJoint("elbow").ok());
}

namespace {

struct AngleRmse {
    Vec3 rmse = Vec3::Zero();  // deg: flexion, abduction, rotation
    long long count = 0;
};

Expected<AngleRmse> compare(const Project& project, const QString& estimate, const QString& reference) {
    auto e = project.stream(estimate)->data();
    auto r = project.stream(reference)->data();
    if (!e || !r) return makeError(QStringLiteral("cannot read"));
    const StreamData& a = **e;
    const StreamData& b = **r;
    if (a.t != b.t) return makeError(QStringLiteral("time bases differ"));
    AngleRmse out;
    for (std::size_t k = 0; k < a.rows(); ++k) {
        for (int i = 0; i < 3; ++i) out.rmse[i] += std::pow(math::wrapAngle(a.at(k, i) - b.at(k, i)), 2);
        ++out.count;
    }
    out.rmse = (out.rmse / double(out.count)).cwiseSqrt() / kDeg;
    return out;
}

Status run(Project& project, const Processor& p, QStringList inputs, QString output, QVariantMap params = {}) {
    auto outcome = runProcessor(project, p, RunRequest{p.id(), inputs, output, params});
    return outcome ? Status() : Status(outcome.error());
}

}  // namespace

// End to end with the processors: simulated IMUs (bias, noise) → 6D VQF-class orientation on each →
// joint angles with the known mounts. Bound 1.5° RMSE per angle: the VQF-class filter's inclination
// error on such data is a few tenths of a degree per sensor and the heading alignment adds the
// residual 6D heading drift over ~45 s (measured: ≤ 0.5°, docs/validation/joint-angles.md), so 1.5°
// leaves a 3× margin while a wrong sign, axis or mount would cost tens of degrees. Without the mounts
// (identity) or without heading alignment the error is large.
TEST(JointAnglesValidation, SimulatedKneeAndHipEndToEnd) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath("j.athlos"));
    ASSERT_TRUE(project);
    const SimulateLimbProcessor sim;
    const OrientationProcessor orientation;
    const JointAnglesProcessor joints;
    for (const QString& side : {QStringLiteral("right"), QStringLiteral("left")}) {
        const QString rec = side + QStringLiteral("/imu");
        ASSERT_TRUE(run(*project, sim, {}, rec, {{"seed", side == "right" ? 5 : 6}, {"side", side}}).ok());
        for (const char* s : {"", "-shank", "-pelvis"}) {
            const QString in = rec + QLatin1String(s);
            const Status st = run(*project, orientation, {in}, in + "-orientation", {{"mode", "6d"}});
            ASSERT_TRUE(st.ok()) << st.message().toStdString();
        }
        const QString thigh = rec + "-orientation", shank = rec + "-shank-orientation",
                      pelvis = rec + "-pelvis-orientation";
        Status st =
            run(*project, joints, {thigh, shank, rec + "-mounts"}, side + "/knee", {{"joint", "knee"}, {"side", side}});
        ASSERT_TRUE(st.ok()) << st.message().toStdString();
        st = run(*project, joints, {pelvis, thigh, rec + "-mounts"}, side + "/hip", {{"joint", "hip"}, {"side", side}});
        ASSERT_TRUE(st.ok()) << st.message().toStdString();
        st = run(*project, joints, {thigh, shank}, side + "/knee-uncalibrated", {{"joint", "knee"}, {"side", side}});
        ASSERT_TRUE(st.ok()) << st.message().toStdString();
        st = run(*project, joints, {thigh, shank, rec + "-mounts"}, side + "/knee-unaligned",
                 {{"joint", "knee"}, {"side", side}, {"heading", "none"}});
        ASSERT_TRUE(st.ok()) << st.message().toStdString();

        const auto knee = compare(*project, side + "/knee", rec + "-knee-reference");
        const auto hip = compare(*project, side + "/hip", rec + "-hip-reference");
        const auto raw = compare(*project, side + "/knee-uncalibrated", rec + "-knee-reference");
        const auto unaligned = compare(*project, side + "/knee-unaligned", rec + "-knee-reference");
        ASSERT_TRUE(knee.ok() && hip.ok() && raw.ok() && unaligned.ok());
        std::cout << side.toStdString() << " knee RMSE flex/abd/rot [deg]: " << knee->rmse.transpose()
                  << "  hip: " << hip->rmse.transpose() << "  knee without mounts: " << raw->rmse.transpose()
                  << "  knee without heading alignment: " << unaligned->rmse.transpose() << "\n";
        for (int i = 0; i < 3; ++i) {
            EXPECT_LT(knee->rmse[i], 1.5);
            EXPECT_LT(hip->rmse[i], 1.5);
        }
        EXPECT_GT(raw->rmse.maxCoeff(), 20.0);
        EXPECT_GT(unaligned->rmse.maxCoeff(), 5.0);
    }
    // Errors name what is wrong.
    auto bad = runProcessor(*project, joints,
                            RunRequest{"joint-angles",
                                       {"right/imu-orientation", "right/imu-shank-orientation"},
                                       "right/bad",
                                       {{"distal_mount", "1,2"}}});
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("distal_mount")) << bad.message().toStdString();
    bad = runProcessor(*project, joints,
                       RunRequest{"joint-angles",
                                  {"right/imu-orientation", "right/imu-shank-orientation", "right/imu-mounts"},
                                  "right/bad",
                                  {{"joint", "ankle"}}});
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("foot")) << bad.message().toStdString();
}

// Functional calibration (spec §4): upright standing + squats give mounts close to the true ones, and
// joint angles with them track the reference; a wrong first-rotation sign would flip Z and X (180°).
TEST(JointAnglesValidation, FunctionalSegmentCalibration) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath("c.athlos"));
    ASSERT_TRUE(project);
    const SimulateLimbProcessor sim;
    const SegmentCalibrationProcessor calibration;
    const OrientationProcessor orientation;
    const JointAnglesProcessor joints;
    ASSERT_TRUE(run(*project, sim, {}, "c/imu", {{"seed", 9}}).ok());
    const QJsonObject attrs = project->stream("c/imu")->info().attributes;
    const double squatBegin = attrs.value("squat_begin").toDouble(), squatEnd = attrs.value("squat_end").toDouble();
    Status st = run(*project, calibration, {"c/imu", "c/imu-shank", "c/imu-pelvis"}, "c/calibration",
                    {{"segments", "thigh,shank,pelvis"},
                     {"static_begin", 0.5},
                     {"static_end", 2.5},
                     {"movement_begin", squatBegin},
                     {"movement_end", squatEnd}});
    ASSERT_TRUE(st.ok()) << st.message().toStdString();
    const Table* estimated = project->table("c/calibration");
    const Table* truth = project->table("c/imu-mounts");
    ASSERT_TRUE(estimated && truth);
    for (const char* segment : {"thigh", "shank", "pelvis"}) {
        const auto e = segmentMount(*estimated, "c/calibration", segment);
        const auto t = segmentMount(*truth, "c/imu-mounts", segment);
        ASSERT_TRUE(e.ok() && t.ok());
        const double error = e->angularDistance(*t) / kDeg;
        std::cout << segment << " mount error " << error << " deg\n";
        // The squat is not a pure rotation about Z: the shank also turns with the knee's coupled
        // rotation/abduction and the hip's (≈ 9° off-axis against 30° of shank pitch), which tilts its
        // principal axis by several degrees — the thesis' dispersion for the shank is ~5°.
        EXPECT_LT(error, std::string(segment) == "shank" ? 10.0 : 2.0) << segment;
    }
    for (const char* s : {"", "-shank"}) {
        const QString in = QStringLiteral("c/imu") + QLatin1String(s);
        ASSERT_TRUE(run(*project, orientation, {in}, in + "-orientation", {{"mode", "6d"}}).ok());
    }
    st = run(*project, joints, {"c/imu-orientation", "c/imu-shank-orientation", "c/calibration"}, "c/knee",
             {{"joint", "knee"}});
    ASSERT_TRUE(st.ok()) << st.message().toStdString();
    const auto knee = compare(*project, "c/knee", "c/imu-knee-reference");
    ASSERT_TRUE(knee.ok());
    std::cout << "knee RMSE with functional calibration flex/abd/rot [deg]: " << knee->rmse.transpose() << "\n";
    EXPECT_LT(knee->rmse[0], 3.0);
    EXPECT_LT(knee->rmse[1], 5.0);
    EXPECT_LT(knee->rmse[2], 5.0);
    // A window without rest is refused with a message naming the input.
    auto bad = runProcessor(*project, calibration,
                            RunRequest{"segment-calibration",
                                       {"c/imu"},
                                       "c/bad",
                                       {{"segments", "thigh"},
                                        {"static_begin", squatBegin},
                                        {"static_end", squatBegin + 1.0},
                                        {"movement_begin", 0.5},
                                        {"movement_end", 2.5}}});
    EXPECT_FALSE(bad.ok());
}
