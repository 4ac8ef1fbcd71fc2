// Functional calibration protocol (spec §4): on the body simulator with the whole protocol (upright,
// squats, trunk rotations, hip ab/adduction per leg) every movement is found at its true time, the
// mounts of all eight segments are recovered against the simulator's true mounts, and recordings
// that lack a movement a segment needs are refused with the reason.
#include "core/math/Angles.h"
#include "core/model/Project.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/inertial/BodySimulator.h"
#include "plugins/inertial/FunctionalCalibration.h"
#include "plugins/inertial/FunctionalCalibrationProcessor.h"
#include "plugins/inertial/SegmentMounts.h"
#include "plugins/inertial/SimulateBodyProcessor.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>
#include <iostream>

using namespace athlos;
using namespace athlos::inertial;
using math::kDeg;

namespace {

BodySimulatorParams protocol(std::uint64_t seed) {
    BodySimulatorParams p;
    p.seed = seed;
    p.scenario = BodyScenario::Squats;
    p.trunkRotations = 3;
    p.hipAbductions = 3;
    p.standDuration = 2.0;
    p.motionDuration = 1.0;  // the squats scenario stands still for it
    return p;
}

std::vector<FunctionalCalibration::Segment> segmentsOf(const BodySimulation& sim) {
    std::vector<FunctionalCalibration::Segment> out;
    for (int s = 0; s < kBodySegments; ++s) {
        FunctionalCalibration::Segment seg;
        seg.name = bodySegmentName(static_cast<BodySegment>(s));
        seg.t = sim.t;
        seg.acc = sim.sensors[s].acc;
        seg.gyr = sim.sensors[s].gyr;
        out.push_back(std::move(seg));
    }
    return out;
}

// The true interval of a movement in the simulation.
TimeInterval truth(const BodySimulation& sim, CalibrationMovement m) {
    switch (m) {
        case CalibrationMovement::Squats:
            return {sim.squatBegin, sim.squatEnd};
        case CalibrationMovement::TrunkRotations:
            return {sim.trunkBegin, sim.trunkEnd};
        case CalibrationMovement::RightAbduction:
            return {sim.rightAbductionBegin, sim.rightAbductionEnd};
        case CalibrationMovement::LeftAbduction:
            return {sim.leftAbductionBegin, sim.leftAbductionEnd};
        default:
            return {0.0, sim.uprightEnd};
    }
}

}  // namespace

TEST(FunctionalCalibration, FindsEveryMovementAndRecoversTheMounts) {
    const BodySimulation sim = simulateBody(protocol(3));
    const auto segments = segmentsOf(sim);
    const auto result = FunctionalCalibration().calibrate(segments);
    ASSERT_TRUE(result.ok()) << result.message().toStdString();
    // Every movement but the optional arm swings (no arm sensors here: tests/plugins/body/UpperBodyCalibrationTest).
    ASSERT_EQ(result->movements.size(), std::size_t(kCalibrationMovements - 1));
    for (const auto& m : result->movements) {
        const TimeInterval t = truth(sim, m.movement);
        std::cout << calibrationMovementName(m.movement).toStdString() << " found " << m.interval.begin << "–"
                  << m.interval.end << " s (true " << t.begin << "–" << t.end << "), " << m.repetitions.size()
                  << " repetitions\n";
        // Inside the true interval up to the smoothing and the slow starts of each repetition.
        EXPECT_GT(m.interval.begin, t.begin - 0.5);
        EXPECT_LT(m.interval.end, t.end + 0.5);
        if (m.movement == CalibrationMovement::Upright) {
            EXPECT_GT(m.interval.end - m.interval.begin, 8.0);
            continue;
        }
        EXPECT_GT(m.interval.end - m.interval.begin, 0.8 * (t.end - t.begin));
        EXPECT_EQ(m.repetitions.size(), 3u) << calibrationMovementName(m.movement).toStdString();
    }
    ASSERT_EQ(result->segments.size(), std::size_t(kBodySegments));
    for (int s = 0; s < kBodySegments; ++s) {
        const auto& r = result->segments[std::size_t(s)];
        const double error = r.mount.angularDistance(sim.sensors[s].mount) / kDeg;
        std::cout << r.name.toStdString() << ": mount error " << error << "°, χ " << r.dispersion / kDeg
                  << "°, orthogonality " << r.orthogonality / kDeg << "°, cross " << r.crossOrthogonality / kDeg
                  << "°, CMC " << r.cmc << "\n";
        EXPECT_LT(error, 3.0) << r.name.toStdString();
        EXPECT_LT(r.dispersion, 3.0 * kDeg) << r.name.toStdString();
        EXPECT_GT(r.cmc, 0.9) << r.name.toStdString();
    }
}

TEST(FunctionalCalibration, GivenIntervalsAreUsed) {
    const BodySimulation sim = simulateBody(protocol(4));
    FunctionalCalibration::Movement squats;
    squats.movement = CalibrationMovement::Squats;
    squats.interval = {sim.squatBegin, sim.squatEnd};
    const auto result = FunctionalCalibration().detect(segmentsOf(sim), {squats});
    ASSERT_TRUE(result.ok()) << result.message().toStdString();
    bool seen = false;
    for (const auto& m : *result)
        if (m.movement == CalibrationMovement::Squats) {
            seen = true;
            EXPECT_TRUE(m.given);
            EXPECT_DOUBLE_EQ(m.interval.begin, sim.squatBegin);
            EXPECT_EQ(m.repetitions.size(), 3u);
        }
    EXPECT_TRUE(seen);
}

TEST(FunctionalCalibration, RefusesARecordingWithoutSquats) {
    BodySimulatorParams p = protocol(5);
    p.squats = 0;
    const BodySimulation sim = simulateBody(p);
    const auto result = FunctionalCalibration().calibrate(segmentsOf(sim));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(result.message().contains("no squats")) << result.message().toStdString();
    EXPECT_TRUE(result.message().contains("sacrum")) << result.message().toStdString();
}

TEST(FunctionalCalibration, RefusesFeetWithoutAbduction) {
    BodySimulatorParams p = protocol(6);
    p.hipAbductions = 0;
    const BodySimulation sim = simulateBody(p);
    const auto result = FunctionalCalibration().calibrate(segmentsOf(sim));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(result.message().contains("right-foot")) << result.message().toStdString();
    EXPECT_TRUE(result.message().contains("right-abduction")) << result.message().toStdString();
}

TEST(FunctionalCalibration, RefusesARecordingWithoutUprightStanding) {
    BodySimulatorParams p = protocol(7);
    p.uprightDuration = 2.0;
    p.calibrationPause = 1.0;
    p.standDuration = 1.0;
    const BodySimulation sim = simulateBody(p);
    const auto result = FunctionalCalibration().calibrate(segmentsOf(sim));
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(result.message().contains("upright")) << result.message().toStdString();
}

TEST(FunctionalCalibration, MultipleCorrelationOfIdenticalCurvesIsOne) {
    // Not public: checked through a segment whose repetitions are identical (ideal sensors).
    BodySimulatorParams p = protocol(8);
    p.gyrBias = p.gyrDrift = p.gyrNoise = p.gyrScale = p.gSensitivity = 0.0;
    p.accBias = p.accNoise = p.accScale = 0.0;
    const BodySimulation sim = simulateBody(p);
    const auto result = FunctionalCalibration().calibrate(segmentsOf(sim));
    ASSERT_TRUE(result.ok()) << result.message().toStdString();
    for (const auto& s : result->segments) {
        if (s.name == QLatin1String("sacrum")) {
            EXPECT_GT(s.cmc, 0.99);
        }
    }
}

TEST(FunctionalCalibration, RefusesAnAxisAlongGravity) {
    // Trunk rotations marked as squats: the sternum turns about its long axis, which cannot be its
    // medio-lateral axis.
    const BodySimulation sim = simulateBody(protocol(9));
    FunctionalCalibration::Movement wrong;
    wrong.movement = CalibrationMovement::Squats;
    wrong.interval = {sim.trunkBegin, sim.trunkEnd};
    auto segments = segmentsOf(sim);
    segments.erase(segments.begin() + 2, segments.end());
    segments.erase(segments.begin());
    const auto result = FunctionalCalibration().calibrate(segments, {wrong});
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(result.message().contains("sternum")) << result.message().toStdString();
    EXPECT_TRUE(result.message().contains("gravity")) << result.message().toStdString();
}

// The processor: simulate-body → functional-calibration with an annotation marking the squats (taken
// as given), the per-side tables hold the true mounts under joint-angles' names, and the quality
// and movements tables are filled.
TEST(FunctionalCalibrationProcessor, WritesMountsQualityAndMovements) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath("f.athlos"));
    ASSERT_TRUE(project);
    const SimulateBodyProcessor sim;
    const FunctionalCalibrationProcessor calibration;
    auto simulated = runProcessor(*project, sim,
                                  RunRequest{sim.id(),
                                             {},
                                             "cal/imu",
                                             {{"scenario", "squats"},
                                              {"motion_duration", 4.0},
                                              {"trunk_rotations", 3},
                                              {"hip_abductions", 3},
                                              {"seed", 12}}});
    ASSERT_TRUE(simulated.ok()) << simulated.message().toStdString();
    const QJsonObject attrs = project->stream("cal/imu")->info().attributes;
    Annotation squats;
    squats.label = "squats";
    squats.tStart = attrs.value("squat_begin").toDouble();
    squats.tEnd = attrs.value("squat_end").toDouble();
    project->recording("cal")->annotations.push_back(squats);
    QStringList inputs{"cal/imu"};
    for (const char* s :
         {"sternum", "right-thigh", "right-shank", "right-foot", "left-thigh", "left-shank", "left-foot"})
        inputs << QStringLiteral("cal/imu-%1").arg(QLatin1String(s));
    auto done = runProcessor(*project, calibration, RunRequest{calibration.id(), inputs, "cal/fc", {}});
    ASSERT_TRUE(done.ok()) << done.message().toStdString();
    for (const char* side : {"right", "left"}) {
        const QString estimated = QStringLiteral("cal/fc-%1").arg(QLatin1String(side));
        const QString truth = QStringLiteral("cal/imu-%1-mounts").arg(QLatin1String(side));
        ASSERT_TRUE(project->table(estimated) && project->table(truth));
        for (const char* segment : {"pelvis", "thorax", "thigh", "shank", "foot"}) {
            const auto e = segmentMount(*project->table(estimated), estimated, segment);
            const auto t = segmentMount(*project->table(truth), truth, segment);
            ASSERT_TRUE(e.ok() && t.ok()) << segment;
            EXPECT_LT(e->angularDistance(*t) / kDeg, 3.0) << side << " " << segment;
        }
    }
    const Table* quality = project->table("cal/fc-quality");
    ASSERT_TRUE(quality);
    EXPECT_EQ(quality->rows(), 8);
    ASSERT_TRUE(quality->column("cmc") && quality->column("dispersion"));
    const Table* movements = project->table("cal/fc-movements");
    ASSERT_TRUE(movements);
    const TableColumn* name = movements->column("movement");
    const TableColumn* given = movements->column("given");
    const TableColumn* begin = movements->column("begin");
    ASSERT_TRUE(name && given && begin);
    int whole = 0;
    for (int r = 0; r < int(name->size()); ++r) {
        if (name->texts.at(r) != "squats") continue;
        EXPECT_EQ(given->numbers[std::size_t(r)], 1.0);
        whole += begin->numbers[std::size_t(r)] == squats.tStart ? 1 : 0;
    }
    EXPECT_GE(whole, 1);  // the annotation's interval, as given
}
