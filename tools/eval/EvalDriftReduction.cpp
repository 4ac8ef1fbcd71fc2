// athlos-eval-drift-reduction [seeds=3] [algorithm=vqf|strapdown|offline] [scenario=skiing|walking]
//                             [mounts=calibrated|true] [gyr_drift °/s = 0.15] [estimator=wahba|markley]
//                             [rate=HZ] [estimation_rate=HZ] [static_correction=true|false]
// (the last three anywhere, as key=value: the simulated sampling rate, default 100 Hz;
// DriftReduction::Params::estimationRate, 0 = every sample; the static correction, default as the
// processor's auto: on for strapdown only)
// Joint-angle RMSE on the body simulator (BodySimulator: 8 IMUs, 2-minute skiing run, turns 27 m apart
// at 20 m/s, gyroscope drift 0.15°/s, vibration, impacts) after 6D orientation, functional calibration
// (upright + squats) and joint angles, WITHOUT and WITH drift reduction (DriftReduction, Fasel 2017
// ch. 2, 5, 6), side by side: the figures of docs/validation/drift-reduction.md.
#include "core/math/Angles.h"
#include "tools/eval/DriftEvaluation.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace athlos;
using namespace athlos::inertial;

int main(int rawArgc, char** rawArgv) {
    // key=value options first; the rest are positional.
    std::vector<char*> positional;
    double rate = 0.0, estimationRate = -1.0;
    int staticCorrection = -1;  // -1 = auto (the processor's rule)
    for (int i = 0; i < rawArgc; ++i) {
        if (!std::strncmp(rawArgv[i], "rate=", 5))
            rate = std::atof(rawArgv[i] + 5);
        else if (!std::strncmp(rawArgv[i], "estimation_rate=", 16))
            estimationRate = std::atof(rawArgv[i] + 16);
        else if (!std::strncmp(rawArgv[i], "static_correction=", 18))
            staticCorrection = std::strcmp(rawArgv[i] + 18, "true") == 0 ? 1 : 0;
        else
            positional.push_back(rawArgv[i]);
    }
    const int argc = static_cast<int>(positional.size());
    char** argv = positional.data();
    const int seeds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    eval::DriftEvaluationOptions options;
    if (argc > 2) {
        if (!std::strcmp(argv[2], "strapdown")) {
            options.orientation.algorithm = OrientationAlgorithm::Strapdown;
        } else if (!std::strcmp(argv[2], "offline")) {
            options.orientation.offline = true;
        } else if (std::strcmp(argv[2], "vqf")) {
            std::fprintf(stderr, "algorithm: use vqf, strapdown or offline\n");
            return 2;
        }
    }
    if (argc > 3) {
        auto scenario = parseBodyScenario(QString::fromUtf8(argv[3]));
        if (!scenario) {
            std::fprintf(stderr, "%s\n", qUtf8Printable(scenario.error().message));
            return 2;
        }
        options.simulation.scenario = *scenario;
    }
    options.trueMounts = argc > 4 && !std::strcmp(argv[4], "true");
    if (argc > 5) options.simulation.gyrDrift = std::atof(argv[5]) * math::kDeg;
    if (options.simulation.scenario == BodyScenario::Walking) options.reduction = DriftReduction::indoor();
    if (argc > 6 && !std::strcmp(argv[6], "markley"))
        options.reduction.estimator = DriftReduction::Params::Estimator::Markley;
    if (rate > 0.0) options.simulation.rate = rate;
    if (estimationRate >= 0.0) options.reduction.estimationRate = estimationRate;
    if (staticCorrection >= 0) {
        options.staticCorrectionAuto = false;
        options.reduction.staticCorrection = staticCorrection == 1;
    }

    std::array<std::array<std::array<double, 3>, kBodyJoints>, 2> sum{};
    std::array<double, kBodySegments> calibration{}, inclination0{}, inclination1{};
    double seconds = 0.0;
    for (int s = 1; s <= seeds; ++s) {
        options.simulation.seed = static_cast<std::uint64_t>(s);
        for (int on = 0; on < 2; ++on) {
            options.driftReduction = on == 1;
            const eval::DriftEvaluation e = eval::evaluateDriftReduction(options);
            for (int j = 0; j < kBodyJoints; ++j)
                for (int i = 0; i < 3; ++i) sum[on][j][i] += e.joints[j].rmse[i] / seeds;
            for (int k = 0; k < kBodySegments; ++k) {
                if (on == 0) calibration[k] += e.calibrationAxisError[k] / seeds;
                (on == 0 ? inclination0 : inclination1)[k] += e.orientationError[k] / seeds;
            }
            seconds += e.seconds / seeds;
        }
        std::fprintf(stderr, "seed %d done\n", s);
    }
    std::printf("Joint-angle RMSE (deg) over the motion phase, mean of %d seeds; without → with drift reduction\n\n",
                seeds);
    std::printf("| joint | flexion | ab/adduction | rotation |\n|---|---|---|---|\n");
    for (int j = 0; j < kBodyJoints; ++j) {
        std::printf("| %s |", qUtf8Printable(bodyJointName(static_cast<BodyJoint>(j))));
        for (int i = 0; i < 3; ++i)
            std::printf(" %.2f → **%.2f** |", sum[0][j][i] / math::kDeg, sum[1][j][i] / math::kDeg);
        std::printf("\n");
    }
    std::printf("\n| sensor | calibration error (deg) | inclination error without → with (deg) |\n|---|---|---|\n");
    for (int k = 0; k < kBodySegments; ++k)
        std::printf("| %s | %s | %.2f → %.2f |\n", qUtf8Printable(bodySegmentName(static_cast<BodySegment>(k))),
                    std::isnan(calibration[k]) ? "true mount"
                                               : qUtf8Printable(QString::number(calibration[k] / math::kDeg, 'f', 2)),
                    inclination0[k] / math::kDeg, inclination1[k] / math::kDeg);
    std::printf("\nDrift reduction time: %.3f s per run (8 sensors, %.0f Hz)\n", seconds, options.simulation.rate);
    return 0;
}
