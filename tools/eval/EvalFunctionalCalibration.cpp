// athlos-eval-functional-calibration [seeds=10] [noise scale=1]
// The functional calibration protocol (FunctionalCalibration, spec §4) on the body simulator with the
// whole protocol (10 s upright, 3 squats, 3 trunk rotations, 3 hip ab/adductions per leg; BodySimulator's
// default sensor errors, gyroscope and accelerometer noise scaled by the second argument): how often every
// movement is found with its 3 repetitions, and per segment the mount error against the true mount (the
// angle of m̂ m*; mean and worst over the seeds) and the quality figures the processor stores (dispersion χ,
// orthogonality, CMC). Then the joint angles of the seven joints from the TRUE sensor orientations with
// the estimated mounts against the reference angles over the whole recording (RMSE flexion/abduction/
// rotation): what the mount errors alone cost. Last the whole body (body::simulateWholeBody in its
// calibration posture, the same protocol plus 3 arm swings): the 14 segments with head, upper back, upper
// arms and forearms. The figures of docs/validation/functional-calibration.md.
#include "core/math/Angles.h"
#include "plugins/body/WholeBodySimulator.h"
#include "plugins/inertial/BodySimulator.h"
#include "plugins/inertial/FunctionalCalibration.h"
#include "plugins/inertial/JointAngles.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace athlos;
using namespace athlos::inertial;
using math::kDeg;

namespace {

struct Sum {
    double error = 0, worst = 0, chi = 0, ortho = 0, cross = 0, cmc = 0;
    int crossCount = 0;
    void add(const FunctionalCalibration::SegmentResult& r, const math::Quat& truth) {
        const double e = r.mount.angularDistance(truth) / kDeg;
        error += e;
        worst = std::max(worst, e);
        chi += r.dispersion / kDeg;
        ortho += r.orthogonality / kDeg;
        cmc += r.cmc;
        if (std::isfinite(r.crossOrthogonality)) {
            cross += r.crossOrthogonality / kDeg;
            ++crossCount;
        }
    }
};

void printTable(const std::vector<QString>& names, const std::vector<Sum>& sums, int calibrated) {
    std::printf("| segment | mount error mean [°] | worst [°] | χ [°] | orthogonality [°] | second axis [°] | CMC |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    for (std::size_t k = 0; k < names.size(); ++k) {
        const Sum& x = sums[k];
        const double n = calibrated;
        char cross[32] = "–";
        if (x.crossCount > 0) std::snprintf(cross, sizeof cross, "%.2f", x.cross / x.crossCount);
        std::printf("| %s | %.2f | %.2f | %.3f | %.2f | %s | %.3f |\n", qUtf8Printable(names[k]), x.error / n, x.worst,
                    x.chi / n, x.ortho / n, cross, x.cmc / n);
    }
}

// The protocol of both parts (the arm swings only where there are arms).
BodySimulatorParams protocol(int seed, double noise, int armSwings) {
    BodySimulatorParams p;
    p.seed = static_cast<std::uint64_t>(seed);
    p.scenario = BodyScenario::Squats;
    p.motionDuration = 1.0;
    p.standDuration = 2.0;
    p.trunkRotations = 3;
    p.hipAbductions = 3;
    p.armSwings = armSwings;
    p.gyrNoise *= noise;
    p.accNoise *= noise;
    return p;
}

// How many movements were found with 3 repetitions (the upright counts as found).
int foundWithThree(const FunctionalCalibration::Result& r) {
    int found = 0;
    for (const auto& m : r.movements)
        found += m.movement == CalibrationMovement::Upright || m.repetitions.size() == 3 ? 1 : 0;
    return found;
}

// The whole body: the eight body sensors and the six upper ones, with the arm swings.
void wholeBody(int seeds, double noise) {
    std::vector<QString> names;
    for (int k = 0; k < kBodySegments; ++k) names.push_back(bodySegmentName(static_cast<BodySegment>(k)));
    for (int k = 0; k < body::kUpperSensors; ++k)
        names.push_back(body::upperSensorName(static_cast<body::UpperSensor>(k)));
    std::vector<Sum> sums(names.size());
    int calibrated = 0, allFound = 0;
    for (int s = 1; s <= seeds; ++s) {
        body::WholeBodyParams w;
        w.calibrationPosture = true;
        w.body = protocol(s, noise, 3);
        const body::WholeBodySimulation sim = body::simulateWholeBody(w);
        std::vector<FunctionalCalibration::Segment> segments;
        std::vector<const BodySensor*> truth;
        for (int k = 0; k < kBodySegments; ++k) truth.push_back(&sim.body.sensors[std::size_t(k)]);
        for (int k = 0; k < body::kUpperSensors; ++k) truth.push_back(&sim.sensors[std::size_t(k)]);
        for (std::size_t k = 0; k < names.size(); ++k)
            segments.push_back({names[k], sim.body.t, truth[k]->acc, truth[k]->gyr});
        const auto result = FunctionalCalibration().calibrate(segments);
        if (!result) {
            std::printf("whole body, seed %d refused: %s\n", s, qUtf8Printable(result.message()));
            continue;
        }
        ++calibrated;
        allFound += foundWithThree(*result) == kCalibrationMovements ? 1 : 0;
        for (std::size_t k = 0; k < names.size(); ++k) sums[k].add(result->segments[k], truth[k]->mount);
    }
    std::printf(
        "\nwhole body with arm swings, seeds %d, noise x%.2f: calibrated %d, all %d movements with 3 "
        "repetitions found in %d\n",
        seeds, noise, calibrated, kCalibrationMovements, allFound);
    if (calibrated > 0) printTable(names, sums, calibrated);
}

}  // namespace

int main(int argc, char** argv) {
    const int seeds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 10;
    const double noise = argc > 2 ? std::max(0.0, std::atof(argv[2])) : 1.0;
    std::vector<Sum> sums(kBodySegments);
    std::array<std::array<double, 3>, kBodyJoints> jointRmse{};
    int calibrated = 0, allFound = 0;
    for (int s = 1; s <= seeds; ++s) {
        const BodySimulation sim = simulateBody(protocol(s, noise, 0));
        std::vector<FunctionalCalibration::Segment> segments;
        for (int k = 0; k < kBodySegments; ++k)
            segments.push_back(
                {bodySegmentName(static_cast<BodySegment>(k)), sim.t, sim.sensors[k].acc, sim.sensors[k].gyr});
        const auto result = FunctionalCalibration().calibrate(segments);
        if (!result) {
            std::printf("seed %d refused: %s\n", s, qUtf8Printable(result.message()));
            continue;
        }
        ++calibrated;
        // Every movement but the optional arm swings (no arm sensors on this body).
        allFound += foundWithThree(*result) == kCalibrationMovements - 1 ? 1 : 0;
        for (int k = 0; k < kBodySegments; ++k)
            sums[std::size_t(k)].add(result->segments[std::size_t(k)], sim.sensors[k].mount);
        for (int j = 0; j < kBodyJoints; ++j) {
            const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
            const int pi = static_cast<int>(info.proximal), di = static_cast<int>(info.distal);
            JointAngles::Params jp;
            jp.joint = info.joint;
            jp.side = info.side;
            jp.proximalMount = result->segments[std::size_t(pi)].mount;
            jp.distalMount = result->segments[std::size_t(di)].mount;
            const auto rows = JointAngles(jp).updateBatch(sim.sensors[pi].sensor, sim.sensors[di].sensor);
            const std::size_t count = rows.size() / JointAngles::kColumns;
            std::array<double, 3> sq{};
            for (std::size_t k = 0; k < count; ++k) {
                const math::Vec3 d = math::Vec3(rows[k * JointAngles::kColumns], rows[k * JointAngles::kColumns + 1],
                                                rows[k * JointAngles::kColumns + 2]) -
                                     sim.joints[j].angles[k].vector();
                for (int i = 0; i < 3; ++i) sq[i] += d[i] * d[i];
            }
            for (int i = 0; i < 3; ++i) jointRmse[j][i] += std::sqrt(sq[i] / double(count)) / kDeg;
        }
    }
    std::printf("seeds %d, noise x%.2f: calibrated %d, all 5 movements with 3 repetitions found in %d\n", seeds, noise,
                calibrated, allFound);
    if (calibrated == 0) return 1;
    std::vector<QString> names;
    for (int k = 0; k < kBodySegments; ++k) names.push_back(bodySegmentName(static_cast<BodySegment>(k)));
    printTable(names, sums, calibrated);
    std::printf("\n| joint | RMSE flexion [°] | abduction [°] | rotation [°] |\n|---|---|---|---|\n");
    for (int j = 0; j < kBodyJoints; ++j)
        std::printf("| %s | %.2f | %.2f | %.2f |\n", qUtf8Printable(bodyJointName(static_cast<BodyJoint>(j))),
                    jointRmse[j][0] / calibrated, jointRmse[j][1] / calibrated, jointRmse[j][2] / calibrated);
    wholeBody(seeds, noise);
    return 0;
}
