#include "tools/eval/ClassifierComparison.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cstdio>

namespace athlos::activity {

int printClassifierComparison(const Dataset& dataset, const std::vector<TrainingSource>& sources,
                              const TrainingOptions& options, const QStringList& classifiers,
                              const std::vector<int>& selections, const char* accuracyHeader) {
    const auto groups = foldGroups(dataset, sources, options);
    if (!groups) {
        std::fprintf(stderr, "%s\n", qPrintable(groups.message()));
        return 1;
    }
    if (selections.empty())
        std::printf("| classifier | %s | accuracy | time (s) |\n|---|---|---|---|\n", accuracyHeader);
    else
        std::printf(
            "| classifier | features (top K by MI; 0: all) | %s | accuracy | time (s) |\n"
            "|---|---|---|---|---|\n",
            accuracyHeader);
    const std::vector<int> ks = selections.empty() ? std::vector<int>{-1} : selections;  // -1: no column
    const long long all = dataset.samples.cols;
    for (const QString& kind : classifiers)
        for (int k : ks) {
            TrainingOptions o = options;
            o.classifier.kind = kind;
            o.selectFeatures = std::max(0, k);
            QElapsedTimer timer;
            timer.start();
            const auto e = crossValidate(dataset, *groups, o);
            const double seconds = double(timer.elapsed()) / 1000.0;
            const QString features = k > 0 && k < all ? QString::number(k) : QStringLiteral("all %1").arg(all);
            const QString lead = k < 0 ? kind : kind + QStringLiteral(" | ") + features;
            if (!e)
                std::printf("| %s | failed: %s | | |\n", qPrintable(lead), qPrintable(e.message()));
            else
                std::printf("| %s | %.3f | %.3f | %.1f |\n", qPrintable(lead), e->balancedAccuracy, e->accuracy,
                            seconds);
            std::fflush(stdout);
        }
    return 0;
}

}  // namespace athlos::activity
