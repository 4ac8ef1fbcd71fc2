// Tackle classification with and without the multi-athlete interaction features (seed 000 §5.1,
// Table 5.1; digest §7) on simulated rugby sevens matches: tackle-candidate detector, then a random
// forest on 4 s windows trained on some matches and tested on others. Figures:
// docs/validation/activity.md.
//
//   build/bin/athlos-eval-tackles [--train N] [--test M] [--duration S] [--trees T]
#include "tools/eval/TackleEvaluation.h"

#include <QCoreApplication>
#include <QStringList>
#include <cstdio>

using namespace athlos::activity;

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const QStringList args = app.arguments();
    auto option = [&](const char* name, double fallback) {
        const int i = int(args.indexOf(QLatin1String(name)));
        return i >= 0 && i + 1 < args.size() ? args[i + 1].toDouble() : fallback;
    };
    const int train = int(option("--train", 5)), test = int(option("--test", 5));
    const auto r = compareTackleFeatures(train, test, option("--duration", 600.0), int(option("--trees", 100)));
    std::printf(
        "tackle detector: threshold %.2f m/s² (fitted on %d training matches); test matches: %d of %d player "
        "tackles found, %d candidates (%d tackles); training: %d candidates (%d tackles)\n",
        r.threshold, train, r.testFound, r.testPlayerTackles, r.testCandidates, r.testPositives, r.trainCandidates,
        r.trainTackles);
    std::printf("%-28s %8s %12s %12s %18s\n", "features", "count", "sensitivity", "specificity", "balanced accuracy");
    for (const auto& row : r.rows)
        std::printf("%-28s %8d %12.3f %12.3f %18.3f\n", qPrintable(row.features), row.featureCount, row.sensitivity,
                    row.specificity, row.balancedAccuracy);
    return r.rows.empty() ? 1 : 0;
}
