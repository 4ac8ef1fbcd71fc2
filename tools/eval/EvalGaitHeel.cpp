// athlos-eval-gait-heel <imu_sample.csv> <mocap_sample.csv> <stride_borders_sample.csv> [--param k=v …]
// gait-parameters (defaults, or --param) on both feet of a gaitmap walk against its heel marker, the
// figures of docs/validation/gait-parameters.md ("Real data with a heel marker"): reference strides
// matched once, mean absolute stride-length error over the reference strides (heel displacement over
// each), over the straight ones, and between the estimated strides' own mid-stances; then gait-summary's
// steady-state mean stride length, its CV and the symmetry index against the heel's.
#include "tools/eval/HeelEvaluation.h"

#include <QCoreApplication>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace athlos;
using namespace athlos::events;

namespace {
void line(const char* name, const std::vector<double>& e) {
    double sum = 0.0, abs = 0.0, worst = 0.0;
    for (double x : e) {
        sum += x;
        abs += std::abs(x);
        worst = std::max(worst, std::abs(x));
    }
    const double n = double(std::max<std::size_t>(e.size(), 1));
    std::printf("%-34s %2zu strides: mean |error| %.2f %%, mean %+.2f %%, worst %.2f %%\n", name, e.size(),
                100.0 * abs / n, 100.0 * sum / n, 100.0 * worst);
}
}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    QStringList files;
    QVariantMap parameters;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--param") && i + 1 < argc) {
            const QString kv = QString::fromLocal8Bit(argv[++i]);
            parameters.insert(kv.section(QLatin1Char('='), 0, 0), kv.section(QLatin1Char('='), 1));
        } else {
            files << QString::fromLocal8Bit(argv[i]);
        }
    }
    if (files.size() != 3) {
        std::fprintf(stderr,
                     "usage: athlos-eval-gait-heel <imu.csv> <mocap.csv> <stride_borders.csv> [--param k=v …]\n");
        return 2;
    }
    auto score = evaluateGaitParametersAgainstHeel(files[0], files[1], files[2], parameters);
    if (!score) {
        std::fprintf(stderr, "athlos-eval-gait-heel: %s\n", qPrintable(score.message()));
        return 1;
    }
    std::printf("reference strides matched once: %d/%d\n", score->matchedOnce, score->reference);
    line("reference strides", score->error);
    line("reference strides, |turn| < 0.3 rad", score->straightError);
    line("own borders (heel moved > 0.2 m)", score->ownError);
    std::printf("steady state (gait-summary, stride length against the heel over the same strides):\n");
    for (const SteadyLength& s : score->steady)
        std::printf("  %-5s %2d strides: mean %.3f m (heel %.3f m, %+.2f %%), CV %.2f %% (heel %.2f %%)%s\n",
                    qPrintable(s.foot), s.used, s.estimatedMean, s.heelMean,
                    100.0 * (s.estimatedMean / s.heelMean - 1.0), s.estimatedCv, s.heelCv,
                    s.foot == QLatin1String("both") ? qPrintable(QStringLiteral(", symmetry index %1 % (heel %2 %)")
                                                                     .arg(s.estimatedSi, 0, 'f', 2)
                                                                     .arg(s.heelSi, 0, 'f', 2))
                                                    : "");
    return 0;
}
