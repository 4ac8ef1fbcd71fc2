// The event detectors on simulated beach volleyball and rugby (seed 000 §5.1, §5.2): recall of the
// annotated actions ≥ 99 %, the tackle threshold fitted on some players and applied to others, and
// training + classify-actions with --segmentation events:impact / events:tackle end to end.
#include "plugins/activity/EventDetectors.h"
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/ClassifyActionsProcessor.h"
#include "plugins/activity/EventSimulator.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/ProcessorRunner.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::activity;

namespace {

StreamInfo infoOf(const QStringList& columns) {
    StreamInfo info;
    info.name = QStringLiteral("imu");
    info.kind = QStringLiteral("imu");
    QStringList units;
    for (const QString& c : columns)
        units << (c.startsWith(u"acc") ? QStringLiteral("m/s^2") : QStringLiteral("rad/s"));
    info.columns = columnsOf(columns, units);
    return info;
}

StreamInfo accInfo() { return infoOf({QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z")}); }

void addRecording(Project& project, const QString& rec, const StreamInfo& info, const SimulatedEvents& sim,
                  const QString& athlete, bool labels) {
    StreamData data = sim.imu;
    project.putStream(rec + QStringLiteral("/imu"),
                      outputStream(QStringLiteral("imu"), QStringLiteral("sensor"), info.columns, std::move(data)));
    Recording& r = *project.recording(rec);
    r.metadata[QStringLiteral("athlete")] = athlete;
    if (labels) r.annotations = sim.annotations;
}

}  // namespace

TEST(EventDetectorsTest, ImpactDetectorFindsEveryVolleyballAction) {
    long long actions = 0, found = 0, candidates = 0;
    for (unsigned player = 1; player <= 8; ++player) {
        const SimulatedEvents sim = EventSimulator::volleyball(player, 40, 100 + player);
        auto events = ImpactDetector::detect(accInfo(), sim.imu, {});
        ASSERT_TRUE(events.ok()) << qPrintable(events.message());
        // The event must be the contact: within 0.25 s of it (its annotation spans ±0.5 s).
        const double recall = eventRecall(*events, sim.annotations, -0.25);
        actions += (long long)sim.annotations.size();
        found += std::llround(recall * double(sim.annotations.size()));
        candidates += (long long)events->size();
    }
    const double recall = double(found) / double(actions);
    std::printf("impact detector: recall %.4f (%lld of %lld actions), %lld candidates\n", recall, found, actions,
                candidates);
    EXPECT_GE(recall, 0.99);
    EXPECT_LT(candidates, 3 * actions);  // the Null motions give some false alarms, not a flood
}

TEST(EventDetectorsTest, TackleThresholdFittedOnSomePlayersDetectsTheOthers) {
    const StreamInfo info = infoOf(EventSimulator::rugbyColumns());
    TackleDetector::Params params;
    std::vector<double> peaks;
    for (unsigned player = 1; player <= 4; ++player) {
        const SimulatedEvents sim = EventSimulator::rugby(player, 25, 10 + player);
        auto signal = TackleDetector::signal(info, sim.imu, params);
        ASSERT_TRUE(signal.ok()) << qPrintable(signal.message());
        const auto p = TackleDetector::annotationPeaks(sim.imu, *signal, sim.annotations);
        peaks.insert(peaks.end(), p.begin(), p.end());
    }
    auto threshold = TackleDetector::fitThreshold(peaks, params);
    ASSERT_TRUE(threshold.ok()) << qPrintable(threshold.message());
    params.threshold = *threshold;
    EXPECT_GT(params.threshold, 9.81);  // above gravity alone
    long long tackles = 0, found = 0, candidates = 0;
    for (unsigned player = 5; player <= 10; ++player) {
        const SimulatedEvents sim = EventSimulator::rugby(player, 25, 10 + player);
        auto events = TackleDetector::detect(info, sim.imu, params);
        ASSERT_TRUE(events.ok()) << qPrintable(events.message());
        const double recall = eventRecall(*events, sim.annotations, 0.0);
        tackles += (long long)sim.annotations.size();
        found += std::llround(recall * double(sim.annotations.size()));
        candidates += (long long)events->size();
    }
    const double recall = double(found) / double(tackles);
    std::printf("tackle detector: threshold %.2f m/s², recall %.4f (%lld of %lld), %lld candidates\n", params.threshold,
                recall, found, tackles, candidates);
    EXPECT_GE(recall, 0.99);
    // A threshold fitted for a lower recall is higher.
    params.targetRecall = 0.5;
    EXPECT_GT(*TackleDetector::fitThreshold(peaks, params), *threshold);
}

TEST(EventDetectorsTest, TrainAndClassifyVolleyballActions) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    for (unsigned player = 1; player <= 5; ++player)
        addRecording(*project, QStringLiteral("p%1").arg(player), accInfo(),
                     EventSimulator::volleyball(player, 60, 200 + player), QStringLiteral("player %1").arg(player),
                     true);
    const SimulatedEvents fresh = EventSimulator::volleyball(77, 40, 977);
    addRecording(*project, QStringLiteral("new"), accInfo(), fresh, QStringLiteral("new"), false);
    TrainingOptions options;
    options.window = 4.0;  // 2 s before to 2 s after the peak (seed 000 §5.2)
    options.sensors = {QStringLiteral("acc")};
    options.classifier.trees = 60;
    options.segmentation = *Segmentation::parse(QStringLiteral("events:impact"));
    auto sources = trainingSources(*project, QStringLiteral("imu"), {});
    ASSERT_TRUE(sources.ok()) << qPrintable(sources.message());
    auto dataset = buildDataset(*sources, options);
    ASSERT_TRUE(dataset.ok()) << qPrintable(dataset.message());
    EXPECT_TRUE(dataset->classes.contains(QStringLiteral("null")));
    EXPECT_EQ(dataset->classes.size(), 10);  // nine actions and null, as the thesis
    auto groups = foldGroups(*dataset, *sources, options);
    ASSERT_TRUE(groups.ok());
    auto evaluation = crossValidate(*dataset, *groups, options);
    ASSERT_TRUE(evaluation.ok()) << qPrintable(evaluation.message());
    std::printf("events:impact, random forest, leave-one-player-out:\n%s", qPrintable(evaluation->toText()));
    EXPECT_GT(evaluation->balancedAccuracy, 0.6);

    auto model = trainModel(*dataset, options);
    ASSERT_TRUE(model.ok()) << qPrintable(model.message());
    auto stored = model->toStored(QStringLiteral("m"));
    ASSERT_TRUE(stored.ok());
    project->models()[QStringLiteral("m")] = *stored;
    auto reread = ActivityModel::fromStored(*stored);
    ASSERT_TRUE(reread.ok()) << qPrintable(reread.message());
    EXPECT_EQ(reread->segmentation.kind, QStringLiteral("events:impact"));

    ClassifyActionsProcessor processor;
    auto run = runProcessor(*project, processor,
                            RunRequest{processor.id(),
                                       {QStringLiteral("new/imu")},
                                       QStringLiteral("new/actions"),
                                       {{QStringLiteral("model"), QStringLiteral("m")}}});
    ASSERT_TRUE(run.ok()) << qPrintable(run.message());
    const Annotations& predicted = project->recording(QStringLiteral("new"))->annotations;
    // Every action gets one predicted annotation at its contact; most with the right class.
    long long found = 0, right = 0;
    for (const Annotation& truth : fresh.annotations) {
        const double t = 0.5 * (truth.tStart + truth.tEnd);
        for (const Annotation& p : predicted)
            if (std::abs(0.5 * (p.tStart + p.tEnd) - t) < 0.3) {
                ++found;
                right += p.label == truth.label;
                break;
            }
    }
    std::printf("new player: %lld of %zu actions found, %lld with the right class; %zu annotations\n", found,
                fresh.annotations.size(), right, predicted.size());
    EXPECT_GE(double(found), 0.9 * double(fresh.annotations.size()));
    EXPECT_GE(double(right), 0.5 * double(fresh.annotations.size()));
}

TEST(EventDetectorsTest, TackleModelStoresItsFittedThreshold) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    const StreamInfo info = infoOf(EventSimulator::rugbyColumns());
    for (unsigned player = 1; player <= 3; ++player)
        addRecording(*project, QStringLiteral("p%1").arg(player), info, EventSimulator::rugby(player, 15, 30 + player),
                     QStringLiteral("player %1").arg(player), true);
    TrainingOptions options;
    options.window = 4.0;
    options.classifier.trees = 30;
    options.segmentation = *Segmentation::parse(QStringLiteral("events:tackle"));
    auto sources = trainingSources(*project, QStringLiteral("imu"), {});
    ASSERT_TRUE(sources.ok());
    auto dataset = buildDataset(*sources, options);
    ASSERT_TRUE(dataset.ok()) << qPrintable(dataset.message());
    EXPECT_GT(dataset->segmentation.tackle.threshold, 9.81);
    EXPECT_EQ(dataset->classes, (QStringList{QStringLiteral("null"), QStringLiteral("tackle")}));
    auto model = trainModel(*dataset, options);
    ASSERT_TRUE(model.ok());
    auto reread = ActivityModel::fromStored(*model->toStored(QStringLiteral("t")));
    ASSERT_TRUE(reread.ok()) << qPrintable(reread.message());
    EXPECT_DOUBLE_EQ(reread->segmentation.tackle.threshold, dataset->segmentation.tackle.threshold);
}
