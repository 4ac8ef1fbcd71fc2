// athlos-eval-body-com: centre-of-mass error of body-com on the simulated skiing run (issue #18, thesis ch. 7:
// 25.7 mm with arms vs Vicon), with true, uncorrected (6D, headings aligned at the start) and drift-reduced
// orientations, for both anthropometric tables. Usage: athlos-eval-body-com [seeds=3] [motion_duration_s=120]
#include "tools/eval/BodyComEvaluation.h"

#include <cstdio>
#include <cstdlib>

using namespace athlos;
using namespace athlos::eval;

int main(int argc, char** argv) {
    const int seeds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    const double duration = argc > 2 ? std::atof(argv[2]) : 120.0;
    struct Case {
        const char* name;
        ComOrientations o;
        ComVectors v;
        bool trueMounts;
    };
    const Case cases[] = {
        {"true orientations, true vectors", ComOrientations::True, ComVectors::True, true},
        {"6D uncorrected, true vectors", ComOrientations::Uncorrected, ComVectors::True, false},
        {"drift-reduced, true vectors", ComOrientations::Corrected, ComVectors::True, false},
        {"drift-reduced, true vectors, true mounts", ComOrientations::Corrected, ComVectors::True, true},
        {"drift-reduced, estimated vectors", ComOrientations::Corrected, ComVectors::Estimated, false},
        {"drift-reduced, table lengths only", ComOrientations::Corrected, ComVectors::Model, false}};
    for (body::BspTable table : {body::BspTable::Dumas2007, body::BspTable::DeLeva1996}) {
        std::printf(
            "\n%s, skiing %.0f s, mean of %d seeds (mm; CoM relative to the lumbar joint centre, pelvis heading "
            "frame)\n",
            qUtf8Printable(body::tableName(table)), duration, seeds);
        std::printf(
            "| orientations | RMSE | mean |e| | bias fwd/left/up | SD fwd/left/up | fore-aft RMSE | CoM / ankle RMSE "
            "in the pelvis frame | "
            "absolute RMSE | speed error (m/s) |\n|---|---|---|---|---|---|---|---|---|\n");
        for (const Case& c : cases) {
            BodyComEvaluation sum;
            for (int s = 1; s <= seeds; ++s) {
                BodyComEvaluationOptions o;
                o.simulation.table = table;
                o.simulation.body.seed = static_cast<std::uint64_t>(s);
                o.simulation.body.motionDuration = duration;
                o.orientations = c.o;
                o.vectors = c.v;
                o.trueMounts = c.trueMounts;
                const BodyComEvaluation e = evaluateBodyCom(o);
                sum.rmse += e.rmse / seeds;
                sum.meanError += e.meanError / seeds;
                sum.bias += e.bias / seeds;
                sum.sd += e.sd / seeds;
                sum.foreAftRmse += e.foreAftRmse / seeds;
                sum.ankleRmse += e.ankleRmse / seeds;
                sum.pelvisFrameRmse += e.pelvisFrameRmse / seeds;
                sum.absoluteRmse += e.absoluteRmse / seeds;
                sum.speedBias += e.speedBias / seeds;
                sum.speedSd += e.speedSd / seeds;
                for (int j = 0; j < 7; ++j) sum.vectorError[j] += e.vectorError[j] / seeds;
            }
            std::printf(
                "| %s | %.1f | %.1f | %.1f/%.1f/%.1f | %.1f/%.1f/%.1f | %.1f | %.1f / %.1f | %.0f | %+.3f ± %.3f |\n",
                c.name, 1e3 * sum.rmse, 1e3 * sum.meanError, 1e3 * sum.bias.x(), 1e3 * sum.bias.y(), 1e3 * sum.bias.z(),
                1e3 * sum.sd.x(), 1e3 * sum.sd.y(), 1e3 * sum.sd.z(), 1e3 * sum.foreAftRmse, 1e3 * sum.pelvisFrameRmse,
                1e3 * sum.ankleRmse, 1e3 * sum.absoluteRmse, sum.speedBias, sum.speedSd);
            if (c.v == ComVectors::Estimated)
                std::printf(
                    "|  (drift-reduction's sensor-to-joint vectors vs truth, mm: lumbar %.0f, hips %.0f/%.0f, knees "
                    "%.0f/%.0f, ankles %.0f/%.0f) |\n",
                    1e3 * sum.vectorError[0], 1e3 * sum.vectorError[1], 1e3 * sum.vectorError[4],
                    1e3 * sum.vectorError[2], 1e3 * sum.vectorError[5], 1e3 * sum.vectorError[3],
                    1e3 * sum.vectorError[6]);
            std::fflush(stdout);
        }
    }
    return 0;
}
