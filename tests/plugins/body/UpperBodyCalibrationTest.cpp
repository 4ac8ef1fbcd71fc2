// The functional calibration of the upper body (issue #17 item 4; spec §4, Fasel §6.2.3 and §7.2.2) on the
// whole-body simulator in its calibration posture: the head, upper-back and arm IMUs follow BodySimulator's
// IMU model (their gyroscope integrates to the true orientation, their accelerometer reads gravity at rest),
// the arm-swing block is found at its true time with its three swings, the mount of every one of the 14
// segments is recovered against the simulator's true mounts, and an arm sensor without arm swings is
// refused with the segment and the missing movement named.
#include "core/math/Angles.h"
#include "core/model/Project.h"
#include "core/processing/OutputStreams.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/body/WholeBodySimulator.h"
#include "plugins/inertial/FunctionalCalibration.h"
#include "plugins/inertial/FunctionalCalibrationProcessor.h"
#include "plugins/inertial/SegmentMounts.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <iostream>

using namespace athlos;
using namespace athlos::body;
using namespace athlos::inertial;
using math::kDeg;

namespace {

WholeBodyParams protocol(std::uint64_t seed, int armSwings = 3) {
    WholeBodyParams p;
    p.calibrationPosture = true;
    p.body.seed = seed;
    p.body.scenario = BodyScenario::Squats;
    p.body.trunkRotations = 3;
    p.body.hipAbductions = 3;
    p.body.armSwings = armSwings;
    p.body.standDuration = 2.0;
    p.body.motionDuration = 1.0;
    return p;
}

struct Named {
    QString name;
    const BodySensor* sensor;
};
std::vector<Named> sensorsOf(const WholeBodySimulation& w) {
    std::vector<Named> out;
    for (int s = 0; s < kBodySegments; ++s)
        out.push_back({bodySegmentName(static_cast<BodySegment>(s)), &w.body.sensors[std::size_t(s)]});
    for (int s = 0; s < kUpperSensors; ++s)
        out.push_back({upperSensorName(static_cast<UpperSensor>(s)), &w.sensors[std::size_t(s)]});
    return out;
}
std::vector<FunctionalCalibration::Segment> segmentsOf(const WholeBodySimulation& w, const std::vector<Named>& all) {
    std::vector<FunctionalCalibration::Segment> out;
    for (const Named& n : all) out.push_back({n.name, w.body.t, n.sensor->acc, n.sensor->gyr});
    return out;
}

}  // namespace

// Error-free sensors: the gyroscope integrates to the true sensor orientation through the arm swings and
// the accelerometer reads gravity while standing: the upper sensors use the same construction as the body's.
TEST(UpperBodySimulator, IdealImuMatchesTheTruth) {
    WholeBodyParams p = protocol(21);
    BodySimulatorParams& b = p.body;
    b.gyrBias = b.gyrDrift = b.gyrNoise = b.gyrScale = b.gSensitivity = 0.0;
    b.accBias = b.accNoise = b.accScale = 0.0;
    const WholeBodySimulation w = simulateWholeBody(p);
    const std::size_t n = w.body.t.size();
    ASSERT_GT(w.body.armSwingEnd, w.body.armSwingBegin + 11.0);
    const double dt = 1.0 / b.rate;
    for (const BodySensor& s : w.sensors) {
        ASSERT_EQ(s.gyr.size(), n);
        // Upright (t = 5 s): specific force = gravity in sensor coordinates.
        const std::size_t rest = std::size_t(5.0 * b.rate);
        const math::Vec3 g = s.sensor[rest].conjugate() * math::Vec3(0.0, 0.0, b.gravity);
        EXPECT_LT((s.acc[rest] - g).norm(), 1e-3);
        // Strapdown over the arm-swing block from the true start.
        const auto k0 = std::size_t(std::floor((w.body.armSwingBegin - 4.0) * b.rate));
        const auto k1 = std::size_t(std::floor((w.body.armSwingEnd + 4.0) * b.rate));
        math::Quat q = s.sensor[k0];
        for (std::size_t k = k0 + 1; k <= k1; ++k) q = (q * math::quatFromRotationVector(s.gyr[k] * dt)).normalized();
        EXPECT_LT(q.angularDistance(s.sensor[k1]) / kDeg, 0.1);
        // The segment frame carries the sensor at its mount.
        EXPECT_LT((s.segment[k1] * s.mount.conjugate()).angularDistance(s.sensor[k1]), 1e-9);
    }
    // The arms swing, the head stays on the thorax outside the squats: the forearm turns by the swing
    // amplitude and the grip (90° pronation) between the upright and the top of the first swing.
    const BodySensor& fore = w[UpperSensor::RightForearm];
    const auto top = std::size_t((w.body.armSwingBegin + 0.5 * b.armSwingDuration) * b.rate);
    // R_z(90°) R_y(90°) turns by 120° (the 2° abduction adds at most as much).
    EXPECT_NEAR(fore.segment[top].angularDistance(fore.segment[100]) / kDeg, 120.0, 3.0);
}

TEST(UpperBodyCalibration, FindsTheArmSwingsAndRecoversEveryMount) {
    const WholeBodySimulation w = simulateWholeBody(protocol(3));
    const auto all = sensorsOf(w);
    const auto result = FunctionalCalibration().calibrate(segmentsOf(w, all));
    ASSERT_TRUE(result.ok()) << result.message().toStdString();
    ASSERT_EQ(result->movements.size(), std::size_t(kCalibrationMovements));
    bool swings = false;
    for (const auto& m : result->movements) {
        EXPECT_TRUE(m.movement == CalibrationMovement::Upright || m.repetitions.size() == 3u)
            << calibrationMovementName(m.movement).toStdString();
        if (m.movement != CalibrationMovement::ArmSwings) continue;
        swings = true;
        std::cout << "arm-swings found " << m.interval.begin << "–" << m.interval.end << " s (true "
                  << w.body.armSwingBegin << "–" << w.body.armSwingEnd << ")\n";
        EXPECT_GT(m.interval.begin, w.body.armSwingBegin - 0.5);
        EXPECT_LT(m.interval.end, w.body.armSwingEnd + 0.5);
        EXPECT_GT(m.interval.end - m.interval.begin, 0.8 * (w.body.armSwingEnd - w.body.armSwingBegin));
    }
    EXPECT_TRUE(swings);
    ASSERT_EQ(result->segments.size(), all.size());
    for (std::size_t s = 0; s < all.size(); ++s) {
        const auto& r = result->segments[s];
        ASSERT_EQ(r.name, all[s].name);
        const double error = r.mount.angularDistance(all[s].sensor->mount) / kDeg;
        std::cout << r.name.toStdString() << " (" << calibrationMovementName(r.movement).toStdString()
                  << "): mount error " << error << "°, χ " << r.dispersion / kDeg << "°, orthogonality "
                  << r.orthogonality / kDeg << "°, cross " << r.crossOrthogonality / kDeg << "°, CMC " << r.cmc << "\n";
        EXPECT_LT(error, 3.0) << r.name.toStdString();
        EXPECT_LT(r.dispersion, 3.0 * kDeg) << r.name.toStdString();
        EXPECT_GT(r.cmc, 0.9) << r.name.toStdString();
    }
    const auto movementOf = [&](const char* name) {
        for (const auto& r : result->segments)
            if (r.name == QLatin1String(name)) return r.movement;
        return CalibrationMovement::Upright;
    };
    EXPECT_EQ(movementOf("head"), CalibrationMovement::Squats);
    EXPECT_EQ(movementOf("upper-back"), CalibrationMovement::Squats);
    EXPECT_EQ(movementOf("left-upper-arm"), CalibrationMovement::ArmSwings);
    EXPECT_EQ(movementOf("right-forearm"), CalibrationMovement::ArmSwings);
}

// Only the upper body (no leg sensors: the squats need a leg, so they are given as an interval) with the
// arm swings given by hand too.
TEST(UpperBodyCalibration, GivenIntervalsWithoutLegs) {
    const WholeBodySimulation w = simulateWholeBody(protocol(4));
    std::vector<Named> upper;
    for (int s = 0; s < kUpperSensors; ++s)
        upper.push_back({upperSensorName(static_cast<UpperSensor>(s)), &w.sensors[std::size_t(s)]});
    FunctionalCalibration::Movement squats, swings;
    squats.movement = CalibrationMovement::Squats;
    squats.interval = {w.body.squatBegin, w.body.squatEnd};
    swings.movement = CalibrationMovement::ArmSwings;
    swings.interval = {w.body.armSwingBegin, w.body.armSwingEnd};
    const auto result = FunctionalCalibration().calibrate(segmentsOf(w, upper), {squats, swings});
    ASSERT_TRUE(result.ok()) << result.message().toStdString();
    for (std::size_t s = 0; s < upper.size(); ++s) {
        const auto& r = result->segments[s];
        EXPECT_LT(r.mount.angularDistance(upper[s].sensor->mount) / kDeg, 3.0) << r.name.toStdString();
    }
    for (const auto& m : result->movements)
        if (m.movement == CalibrationMovement::ArmSwings) {
            EXPECT_TRUE(m.given);
            EXPECT_DOUBLE_EQ(m.interval.begin, w.body.armSwingBegin);
            EXPECT_EQ(m.repetitions.size(), 3u);
        }
}

TEST(UpperBodyCalibration, RefusesAnArmWithoutArmSwings) {
    const WholeBodySimulation w = simulateWholeBody(protocol(5, 0));
    EXPECT_EQ(w.body.armSwingBegin, w.body.armSwingEnd);
    auto all = sensorsOf(w);
    // The trunk and head still calibrate without arm swings (they are optional) …
    std::vector<Named> noArms(all.begin(), all.begin() + kBodySegments + 2);
    const auto ok = FunctionalCalibration().calibrate(segmentsOf(w, noArms));
    ASSERT_TRUE(ok.ok()) << ok.message().toStdString();
    for (std::size_t s = kBodySegments; s < noArms.size(); ++s)
        EXPECT_LT(ok->segments[s].mount.angularDistance(noArms[s].sensor->mount) / kDeg, 3.0);
    // … an arm sensor does not.
    const auto result = FunctionalCalibration().calibrate(segmentsOf(w, all));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(result.message().contains("right-upper-arm")) << result.message().toStdString();
    EXPECT_TRUE(result.message().contains("no arm-swings")) << result.message().toStdString();
}

// Squats or trunk rotations marked as arm swings: the arms turn with the trunk about an axis that is
// not theirs, and the refusal names the arm and the reason.
TEST(UpperBodyCalibration, RefusesTrunkRotationsMarkedAsArmSwings) {
    const WholeBodySimulation w = simulateWholeBody(protocol(6));
    FunctionalCalibration::Movement wrong;
    wrong.movement = CalibrationMovement::ArmSwings;
    wrong.interval = {w.body.trunkBegin, w.body.trunkEnd};
    const std::vector<Named> arm{{QStringLiteral("left-forearm"), &w[UpperSensor::LeftForearm]}};
    const auto result = FunctionalCalibration().calibrate(segmentsOf(w, arm), {wrong});
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(result.message().contains("left-forearm")) << result.message().toStdString();
    EXPECT_TRUE(result.message().contains("gravity")) << result.message().toStdString();
}

// Without the calibration posture (the centre-of-mass set-up) the arms swing from the start: the
// simulator still delivers the upper sensors, with the body's sensors as they were.
TEST(UpperBodySimulator, PostureOffKeepsTheBody) {
    WholeBodyParams p;
    p.body.seed = 7;
    p.body.motionDuration = 8.0;
    const WholeBodySimulation w = simulateWholeBody(p);
    const BodySimulation b = simulateBody(p.body);
    ASSERT_EQ(w.body.t.size(), b.t.size());
    for (int s = 0; s < kBodySegments; ++s) {
        EXPECT_EQ(w.body.sensors[std::size_t(s)].gyr, b.sensors[std::size_t(s)].gyr);
        EXPECT_EQ(w.body.sensors[std::size_t(s)].acc, b.sensors[std::size_t(s)].acc);
    }
    for (const BodySensor& s : w.sensors) EXPECT_EQ(s.acc.size(), b.t.size());
}

// The processor with all 14 IMUs under body-model's segment names: the main table holds every mount
// within 3° of the truth, the per-side tables carry head, upper-arm and forearm, the quality table one
// row per segment, and the movements table the arm swings.
TEST(UpperBodyCalibrationProcessor, FourteenImusUnderBodyModelNames) {
    const WholeBodySimulation w = simulateWholeBody(protocol(8));
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath("u.athlos"));
    ASSERT_TRUE(project);
    const auto all = sensorsOf(w);
    QStringList inputs, names;
    for (const Named& n : all) {
        StreamData d(w.body.t.size(), 6);
        d.t = w.body.t;
        for (std::size_t k = 0; k < w.body.t.size(); ++k)
            for (int i = 0; i < 3; ++i) {
                d.at(k, i) = n.sensor->acc[k][i];
                d.at(k, 3 + i) = n.sensor->gyr[k][i];
            }
        const QString path = QStringLiteral("cal/imu-%1").arg(n.name);
        project->putStream(path, outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                                              columnsOf({"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"},
                                                        {"m/s^2", "m/s^2", "m/s^2", "rad/s", "rad/s", "rad/s"}),
                                              std::move(d)));
        inputs << path;
        names << n.name;
    }
    const FunctionalCalibrationProcessor calibration;
    auto done = runProcessor(*project, calibration,
                             RunRequest{calibration.id(), inputs, "cal/fc", {{"segments", names.join(',')}}});
    ASSERT_TRUE(done.ok()) << done.message().toStdString();
    const Table* mounts = project->table("cal/fc");
    ASSERT_TRUE(mounts);
    for (const Named& n : all) {
        const auto m = segmentMount(*mounts, "cal/fc", n.name);
        ASSERT_TRUE(m.ok()) << m.message().toStdString();
        EXPECT_LT(m->angularDistance(n.sensor->mount) / kDeg, 3.0) << n.name.toStdString();
    }
    for (const char* side : {"right", "left"}) {
        const QString path = QStringLiteral("cal/fc-%1").arg(QLatin1String(side));
        const Table* t = project->table(path);
        ASSERT_TRUE(t);
        for (const char* segment : {"pelvis", "thorax", "head", "upper-arm", "forearm"})
            EXPECT_TRUE(segmentMount(*t, path, segment).ok()) << side << " " << segment;
    }
    const auto rightArm = segmentMount(*project->table("cal/fc-right"), "cal/fc-right", "upper-arm");
    ASSERT_TRUE(rightArm.ok());
    EXPECT_LT(rightArm->angularDistance(w[UpperSensor::RightUpperArm].mount) / kDeg, 3.0);
    const Table* quality = project->table("cal/fc-quality");
    ASSERT_TRUE(quality);
    EXPECT_EQ(quality->rows(), static_cast<long long>(all.size()));
    const Table* movements = project->table("cal/fc-movements");
    ASSERT_TRUE(movements && movements->column("movement"));
    EXPECT_TRUE(movements->column("movement")->texts.contains("arm-swings"));
}
