// athlos-eval-anchor-smoother [seeds=5] [key=value …]
// The anchor-point smoother (Fasel thesis ch. 9) on simulated giant-slalom runs (GateRunSimulator:
// 24 gates ~26 m apart, 15–25 m/s, sacrum IMU with gyroscope drift 0.15 °/s, magnets at the gates):
// orientation (vqf) → gate detection → two-pass smoother, against the truth between the first and
// the last gate. Prints one line per seed and the mean, for each condition:
//   anchors      the judged setup (thesis: position 0.238 m, speed −0.004 ± 0.204 m/s)
//   every-2nd    only every second gate as anchor (thesis's simulated super-G)
//   every-3rd    only every third gate (simulated downhill)
//   no-anchors   ZUPT at start and finish only (passes=0): what the anchors remove
// Keys: mode=9d|6d, start=1|0 (start position given), passes=N, anchor_sigma2=…, acc_sigma=….
#include "tools/eval/AnchorEvaluation.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace athlos;
using namespace athlos::positioning;

int main(int argc, char** argv) {
    const int seeds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    AnchorEvalOptions base;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        const auto eq = a.find('=');
        if (eq == std::string::npos) {
            std::fprintf(stderr, "expected key=value, got %s\n", argv[i]);
            return 2;
        }
        const std::string key = a.substr(0, eq), value = a.substr(eq + 1);
        const double x = std::atof(value.c_str());
        if (key == "mode")
            base.useMagnetometer = value != "6d";
        else if (key == "orientation") {
            base.truthOrientation = value == "truth";
            base.offlineOrientation = value == "offline";
        } else if (key == "tau_acc")
            base.tauAcc = x;
        else if (key == "restaligned")
            base.pipeline.restAligned = x != 0.0;
        else if (key == "start")
            base.giveStart = x != 0.0;
        else if (key == "passes")
            base.pipeline.smoother.passes = int(x);
        else if (key == "anchor_sigma2")
            base.pipeline.smoother.anchorSigma2 = x;
        else if (key == "acc_sigma")
            base.pipeline.smoother.accSigma = x;
        else if (key == "jerk")
            base.pipeline.smoother.jerkBase = x;
        else if (key == "walk")
            base.pipeline.smoother.accOffsetWalk = x;
        else if (key == "height")
            base.pipeline.smoother.sacrumHeight = x;
        else {
            std::fprintf(stderr, "unknown key %s\n", key.c_str());
            return 2;
        }
    }
    struct Condition {
        const char* name;
        int every;
        int passes;
    };
    const Condition conditions[] = {{"anchors", 1, base.pipeline.smoother.passes},
                                    {"every-2nd", 2, base.pipeline.smoother.passes},
                                    {"every-3rd", 3, base.pipeline.smoother.passes},
                                    {"no-anchors", 1, 0}};
    int failures = 0;
    std::printf("%-10s %4s %8s %9s %9s %8s %8s %5s %5s %8s\n", "condition", "seed", "pos_rmse", "speed_mu", "speed_sd",
                "tilt_deg", "head_deg", "gates", "match", "psi_deg");
    for (const auto& c : conditions) {
        double p = 0.0, m = 0.0, s = 0.0;
        int ok = 0;
        for (int seed = 1; seed <= seeds; ++seed) {
            AnchorEvalOptions o = base;
            o.simulation.seed = std::uint64_t(seed);
            o.keepEveryGate = c.every;
            o.pipeline.smoother.passes = c.passes;
            const auto score = evaluateAnchorRun(o);
            if (!score) {
                std::printf("%-10s %4d failed: %s\n", c.name, seed, qUtf8Printable(score.error().message));
                ++failures;
                continue;
            }
            std::printf("%-10s %4d %8.3f %9.3f %9.3f %8.2f %8.2f %5d %5d %8.2f\n", c.name, seed, score->positionRmse,
                        score->speedMean, score->speedSd, score->tiltRmse, score->headingRmse, score->gates,
                        score->matched, score->azimuthOffset * 180.0 / 3.141592653589793);
            p += score->positionRmse;
            m += score->speedMean;
            s += score->speedSd;
            ++ok;
        }
        if (ok > 0) std::printf("%-10s mean %8.3f %9.3f %9.3f\n", c.name, p / ok, m / ok, s / ok);
    }
    // GNSS-free gates (thesis ch. 10): 5 runs per course, one course per seed.
    std::printf("\ngnss-free gates (5 runs per course): horizontal gate error after aligning first/last gate\n");
    std::printf("%4s %12s %14s %13s\n", "seed", "single_mean", "averaged_mean", "averaged_max");
    for (int seed = 1; seed <= seeds; ++seed) {
        const auto g = evaluateGateAveraging(base, 5, std::uint64_t(100 * seed));
        if (!g) {
            std::printf("%4d failed: %s\n", seed, qUtf8Printable(g.error().message));
            ++failures;
            continue;
        }
        std::printf("%4d %12.3f %14.3f %13.3f\n", seed, g->singleMean, g->averagedMean, g->averagedMax);
    }
    return failures > 0 ? 1 : 0;
}
