// athlos-eval-velocity-reset [--seeds N] [--cycles N] [--no-bridge] [--gaitmap <folder> [--param k=v …]]
// (--no-bridge: gyro_bridge=false everywhere; --param: velocity-reset parameters for the gaitmap runs)
// Velocity resets (velocity-reset, plugins/inertial/VelocityReset.h) on 6D VQF orientation, the figures
// of docs/validation/drift-reduction.md ("Velocity resets"):
//  - cross-country diagonal stride on SkiingSimulator (xc-ski mode): thrusts found, thrust start/end,
//    cycle speed and length against the truth, instantaneous speed RMSE with and without resets;
//  - level walking on FootMotionSimulator (foot mode): stances found, stride length against the truth,
//    with the simulator's biases and with a 0.3 m/s² accelerometer bias added; without resets for
//    comparison;
//  - gaitmap's real walk and stairs (foot mode, through the processors): stance phases per motion-capture
//    stride, stride length and height against gait-parameters (the data has no distance reference).
#include "tools/eval/VelocityEvaluation.h"

#include <QCoreApplication>
#include <QDir>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace athlos;
using namespace athlos::inertial;

namespace {
void line(const char* name, const ErrorStat& s, double scale, const char* unit) {
    std::printf("    %-28s %+8.4f ± %7.4f %s (mean |e| %.4f, max |e| %.4f, n = %zu)\n", name, scale * s.mean(),
                scale * s.sd(), unit, scale * s.meanAbs(), scale * s.maxAbs(), s.v.size());
}
}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    int seeds = 5, cycles = 40;
    QString gaitmap;
    QVariantMap footParameters;
    bool bridge = true;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--seeds") && i + 1 < argc) {
            seeds = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--cycles") && i + 1 < argc) {
            cycles = std::atoi(argv[++i]);
        } else if (!std::strcmp(argv[i], "--no-bridge")) {
            bridge = false;
            footParameters.insert(QStringLiteral("gyro_bridge"), QStringLiteral("false"));
        } else if (!std::strcmp(argv[i], "--param") && i + 1 < argc) {
            const QString kv = QString::fromLocal8Bit(argv[++i]);
            footParameters.insert(kv.section(QLatin1Char('='), 0, 0), kv.section(QLatin1Char('='), 1));
        } else if (!std::strcmp(argv[i], "--gaitmap") && i + 1 < argc) {
            gaitmap = QString::fromLocal8Bit(argv[++i]);
        } else {
            std::fprintf(stderr,
                         "usage: athlos-eval-velocity-reset [--seeds N] [--cycles N] [--no-bridge] [--gaitmap <folder> "
                         "[--param k=v …]]\n");
            return 2;
        }
    }

    VelocityReset::Params xc = VelocityReset::crossCountrySki(), foot = VelocityReset::foot();
    xc.gyroBridge = foot.gyroBridge = bridge;
    for (const bool strapdown : {false, true}) {
        SkiVelocityScore ski;
        for (int s = 0; s < seeds; ++s) ski.add(evaluateSkiVelocity(unsigned(101 + s), cycles, xc, strapdown));
        std::printf("cross-country diagonal stride (SkiingSimulator, %d seeds × %d cycles, 200 Hz), mode xc-ski, %s\n",
                    seeds, cycles, strapdown ? "strap-down orientation" : "6D VQF orientation");
        std::printf("    thrusts matched              %d / %d (extra phases %d)\n", ski.matchedThrusts,
                    ski.truthThrusts, ski.extraPhases);
        line("thrust start", ski.thrustStart, 1000.0, "ms");
        line("thrust end", ski.thrustEnd, 1000.0, "ms");
        line("cycle speed", ski.cycleSpeed, 1.0, "m/s");
        line("cycle speed (%)", ski.cycleSpeedPct, 1.0, "%");
        line("cycle length", ski.cycleLength, 1.0, "m");
        std::printf("    speed RMSE per sample        %.4f m/s with resets, %.2f m/s without\n", ski.speedRmse,
                    ski.speedRmseNoReset);
    }

    for (const double bias : {0.0, 0.3}) {
        FootVelocityScore walk;
        for (int s = 0; s < seeds; ++s) {
            events::SimConfig c = footWalkConfig(unsigned(11 + s));
            c.accBias += Eigen::Vector3d(bias, -bias, 0.5 * bias);
            walk.add(evaluateFootVelocity(c, foot));
        }
        std::printf(
            "level walking (FootMotionSimulator, %d seeds × 12 strides, 102.4 Hz), mode foot, accelerometer "
            "bias +%.1f m/s²\n",
            seeds, bias);
        std::printf("    stances matched once         %d / %d (extra phases %d)\n", walk.matchedStances,
                    walk.truthStrides, walk.extraPhases);
        line("stride length", walk.strideLength, 1.0, "m");
        line("stride length (%)", walk.strideLengthPct, 1.0, "%");
        line("stride length, no resets (%)", walk.strideLengthNoResetPct, 1.0, "%");
    }

    if (!gaitmap.isEmpty()) {
        const QDir dir(gaitmap);
        struct File {
            const char* imu;
            const char* borders;
        };
        for (const File f :
             {File{"imu_sample_ic_stride.csv", "stride_borders_sample_ic_stride.csv"},
              File{"imu_sample_healthy_stair_up.csv", ""}, File{"imu_sample_healthy_stair_down.csv", ""}}) {
            auto score = evaluateGaitmapVelocity(dir.filePath(QLatin1String(f.imu)),
                                                 *f.borders ? dir.filePath(QLatin1String(f.borders)) : QString(),
                                                 footParameters);
            if (!score) {
                std::fprintf(stderr, "%s\n", qPrintable(score.message()));
                return 1;
            }
            std::printf("gaitmap %s (both feet), mode foot\n", f.imu);
            if (*f.borders)
                std::printf("    mocap strides with one stance %d / %d (at least one: %d)\n", score->oneStance,
                            score->referenceStrides, score->someStance);
            std::printf("    strides compared             %d\n", score->strides);
            line("length − gait-parameters (%)", score->lengthDiffPct, 1.0, "%");
            line("height − gait-parameters", score->heightDiff, 1.0, "m");
            std::printf("    horizontal speed mid-swing   %.2f m/s (mean)\n", score->speedAtMidSwing.mean());
        }
    }
    return 0;
}
