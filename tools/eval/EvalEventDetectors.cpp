// Event detectors on the simulated studies (seed 000 §5.1, §5.2; digest §7, §8): recall of the
// beach-volleyball impact detector and of the rugby tackle-candidate detector (threshold fitted on
// half of the players, applied to the other half), candidates per annotated action, and the
// classifiers on the detected volleyball events with leave-one-player-out cross-validation.
// --export-windows DIR writes the volleyball event windows (4 s, raw) for scripts/train_cnn.py.
// Figures: docs/validation/activity.md.
//
//   build/bin/athlos-eval-event-detectors [--players N] [--actions A] [--classifiers C1,C2] [--export-windows DIR]
//                                         [--select-features K1,K2]   (a row per classifier and number of
//                                         features kept by mutual information, ranked inside each fold; 0: all)
//                                         [--detection-recall R]   (the cost-sensitive detection tree's target
//                                         recall, default 0.99; 0: no tree)
#include "plugins/activity/ActivityTraining.h"
#include "tools/eval/ClassifierComparison.h"
#include "plugins/activity/CnnTraining.h"
#include "plugins/activity/EventDetectors.h"
#include "plugins/activity/EventSimulator.h"

#include "core/processing/OutputStreams.h"

#include <QCoreApplication>
#include <cmath>
#include <cstdio>

using namespace athlos;
using namespace athlos::activity;

namespace {
StreamInfo infoOf(const QStringList& columns) {
    StreamInfo info;
    info.name = info.kind = QStringLiteral("imu");
    QStringList units;
    for (const QString& c : columns)
        units << (c.startsWith(u"acc") ? QStringLiteral("m/s^2") : QStringLiteral("rad/s"));
    info.columns = columnsOf(columns, units);
    return info;
}
}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    int players = 10, actions = 60;
    QString exportDir;
    QStringList classifiers = Classifier::kinds();
    std::vector<int> selections;  // empty: the classifier table with every feature
    double detectionRecall = 0.99;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i + 1 < args.size(); i += 2) {
        if (args[i] == u"--players") players = args[i + 1].toInt();
        if (args[i] == u"--actions") actions = args[i + 1].toInt();
        if (args[i] == u"--export-windows") exportDir = args[i + 1];
        if (args[i] == u"--detection-recall") detectionRecall = args[i + 1].toDouble();
        if (args[i] == u"--classifiers") classifiers = args[i + 1].split(QLatin1Char(','), Qt::SkipEmptyParts);
        if (args[i] == u"--select-features")
            for (const QString& k : args[i + 1].split(QLatin1Char(','), Qt::SkipEmptyParts))
                selections.push_back(k.toInt());
    }
    const StreamInfo acc = infoOf({QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z")});

    // Beach volleyball: impact detector.
    std::vector<TrainingSource> sources;
    long long annotated = 0, found = 0, candidates = 0;
    for (int p = 1; p <= players; ++p) {
        SimulatedEvents sim = EventSimulator::volleyball(unsigned(p), actions, 100u + unsigned(p));
        auto events = ImpactDetector::detect(acc, sim.imu, {});
        if (!events) return std::fprintf(stderr, "%s\n", qPrintable(events.message())), 1;
        annotated += (long long)sim.annotations.size();
        found += std::llround(eventRecall(*events, sim.annotations, -0.25) * double(sim.annotations.size()));
        candidates += (long long)events->size();
        TrainingSource s;
        s.recording = s.athlete = QStringLiteral("player%1").arg(p);
        s.info = acc;
        s.annotations = sim.annotations;
        s.data = std::make_shared<const StreamData>(std::move(sim.imu));
        sources.push_back(std::move(s));
    }
    std::printf(
        "impact detector (8 Hz HP, L1, 3 Hz LP, 5.1 m/s²): %d players, %lld actions, recall %.4f, %.2f "
        "candidates per action\n",
        players, annotated, double(found) / double(annotated), double(candidates) / double(annotated));

    // Rugby: tackle detector, fitted on the first half of the players.
    const StreamInfo back = infoOf(EventSimulator::rugbyColumns());
    TackleDetector::Params tackle;
    std::vector<double> peaks;
    std::vector<SimulatedEvents> rugby;
    for (int p = 1; p <= players; ++p) rugby.push_back(EventSimulator::rugby(unsigned(p), 25, 10u + unsigned(p)));
    for (int p = 0; p < players / 2; ++p) {
        auto signal = TackleDetector::signal(back, rugby[std::size_t(p)].imu, tackle);
        if (!signal) return 1;
        auto v = TackleDetector::annotationPeaks(rugby[std::size_t(p)].imu, *signal, rugby[std::size_t(p)].annotations);
        peaks.insert(peaks.end(), v.begin(), v.end());
    }
    tackle.threshold = *TackleDetector::fitThreshold(peaks, tackle);
    long long tackles = 0, tacklesFound = 0, tackleCandidates = 0;
    for (int p = players / 2; p < players; ++p) {
        auto events = TackleDetector::detect(back, rugby[std::size_t(p)].imu, tackle);
        if (!events) return 1;
        const auto& a = rugby[std::size_t(p)].annotations;
        tackles += (long long)a.size();
        tacklesFound += std::llround(eventRecall(*events, a, 0.0) * double(a.size()));
        tackleCandidates += (long long)events->size();
    }
    std::printf(
        "tackle detector (1 Hz LP, norm; threshold %.2f m/s² fitted on %d players for recall 1): "
        "%lld tackles of %d other players, recall %.4f, %.2f candidates per tackle\n\n",
        tackle.threshold, players / 2, tackles, players - players / 2, double(tacklesFound) / double(tackles),
        double(tackleCandidates) / double(tackles));

    // Classifiers on the detected volleyball events (4 s windows centred on the peak, seed 000 §5.2).
    TrainingOptions options;
    options.window = 4.0;
    options.sensors = {QStringLiteral("acc")};
    options.segmentation = *Segmentation::parse(QStringLiteral("events:impact"));
    options.segmentation.useDetectionTree = detectionRecall > 0;
    if (detectionRecall > 0) options.segmentation.detection.targetRecall = detectionRecall;
    options.validation = QStringLiteral("leave-one-recording-out");
    if (!exportDir.isEmpty()) {
        auto raw = buildRawDataset(sources, options);
        if (!raw) return std::fprintf(stderr, "%s\n", qPrintable(raw.message())), 1;
        if (Status s = exportWindows(*raw, sources, options, exportDir); !s)
            return std::fprintf(stderr, "%s\n", qPrintable(s.message())), 1;
        std::printf("exported %zu windows (%d samples) to %s\n", raw->labels.size(), raw->length,
                    qPrintable(exportDir));
        return 0;
    }
    auto dataset = buildDataset(sources, options);
    if (!dataset) return std::fprintf(stderr, "%s\n", qPrintable(dataset.message())), 1;
    if (const auto& tree = dataset->segmentation.detectionTree; tree) {
        // The tree's figures are its grid search's: each player's candidates judged by the tree trained on
        // the others. Recall of the annotated actions end to end: detector × tree.
        const DetectionTree::Fit& f = tree->fit();
        const double detector = double(found) / double(annotated);
        std::printf(
            "detection tree (impact, swing indicators; cost-sensitive CART, target recall %.2f): FN:FP cost %g, "
            "leave-one-player-out: keeps %.4f of %d candidates in actions, drops %.4f of %d null candidates; "
            "detector × tree recall %.4f, %.2f candidates per action\n",
            detectionRecall, f.costRatio, f.recall, f.relevant, f.nullRejected, f.nulls, detector * f.recall,
            (f.recall * f.relevant + (1.0 - f.nullRejected) * f.nulls) / double(annotated));
    }
    std::printf("%zu event windows, %lld classes, leave-one-player-out:\n\n", dataset->labels.size(),
                qlonglong(dataset->classes.size()));
    return printClassifierComparison(*dataset, sources, options, classifiers, selections, "balanced accuracy");
}
