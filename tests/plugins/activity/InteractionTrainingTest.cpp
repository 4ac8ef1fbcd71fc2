// Multi-athlete interaction features through the training path of `athlos train --interaction` (seed 000
// §5.1.2; issue #14 item 2): simulate-rugby matches in a project, every player's IMU stream a source,
// tackle candidates (events:tackle) with and without the torso pitch and k-nearest-opponent features,
// leave-one-athlete-out. The simulated falls and contacts look like tackles to the player's own IMU,
// so the interaction features must raise the balanced accuracy; the stored model must predict the
// same after reopening, record the other athletes' streams in the run's provenance and refuse a
// session whose positions are missing, naming the stream.
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/ClassifyActionsProcessor.h"
#include "plugins/activity/SimulateRugbyProcessor.h"

#include "core/processing/PipelineProvenance.h"
#include "core/processing/ProcessorRunner.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::activity;

namespace {

void simulateMatch(Project& project, const QString& rec, int seed) {
    SimulateRugbyProcessor simulate;
    auto run = runProcessor(project, simulate,
                            RunRequest{simulate.id(),
                                       {},
                                       rec + QStringLiteral("/sim"),
                                       {{QStringLiteral("seed"), seed},
                                        {QStringLiteral("duration"), 390.0},
                                        {QStringLiteral("scrums"), 0},
                                        {QStringLiteral("tackles"), 6},
                                        {QStringLiteral("contacts"), 5},
                                        {QStringLiteral("falls"), 3}}});
    ASSERT_TRUE(run.ok()) << qPrintable(run.message());
}

TrainingOptions tackleOptions(bool interaction) {
    TrainingOptions options;
    options.window = 4.0;  // the thesis's 4 s centred on the candidate
    options.step = 1.0;
    options.classes = {QStringLiteral("tackle"), QStringLiteral("null")};
    options.segmentation = *Segmentation::parse(QStringLiteral("events:tackle"));
    options.classifier.trees = 60;
    if (interaction) options.interaction = *InteractionOptions::parse(QStringLiteral("k=3"));
    return options;
}

class InteractionTrainingTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        path_ = dir_.filePath(QStringLiteral("p.athlos"));
        project_ = Project::create(path_);
        for (int m = 1; m <= 3; ++m) simulateMatch(*project_, QStringLiteral("m%1").arg(m), 40 + m);
    }
    Expected<Evaluation> crossValidated(const TrainingOptions& options) {
        auto sources = trainingSources(*project_, QStringLiteral("sim-imu-*"), {});
        if (!sources) return sources.error();
        if (options.interaction)
            if (Status s = attachInteraction(*project_, *sources, *options.interaction); !s) return s.error();
        auto dataset = buildDataset(*sources, options);
        if (!dataset) return dataset.error();
        windows_ = int(dataset->labels.size());
        features_ = dataset->features;
        auto groups = foldGroups(*dataset, *sources, options);
        if (!groups) return groups.error();
        return crossValidate(*dataset, *groups, options);
    }
    QTemporaryDir dir_;
    QString path_;
    std::unique_ptr<Project> project_;
    int windows_ = 0;
    QStringList features_;
};

}  // namespace

TEST_F(InteractionTrainingTest, InteractionFeaturesBeatTheImuAloneLeaveOneAthleteOut) {
    auto sources = trainingSources(*project_, QStringLiteral("sim-imu-*"), {});
    ASSERT_TRUE(sources.ok()) << qPrintable(sources.message());
    ASSERT_EQ(sources->size(), 42u);                         // 14 players × 3 matches, one source per player stream
    EXPECT_EQ((*sources)[0].athlete, QStringLiteral("A1"));  // the stream's athlete attribute

    auto without = crossValidated(tackleOptions(false));
    ASSERT_TRUE(without.ok()) << qPrintable(without.message());
    const QStringList imuOnly = features_;
    auto with = crossValidated(tackleOptions(true));
    ASSERT_TRUE(with.ok()) << qPrintable(with.message());
    EXPECT_EQ(features_.size(), imuOnly.size() + 11);  // own pitch and speed, 3 × (distance, speed, pitch)
    EXPECT_EQ(features_.last(), QStringLiteral("opp3_pitch"));
    std::printf("tackle candidates %d, balanced accuracy (leave-one-athlete-out): IMU %.3f, IMU + interaction %.3f\n",
                windows_, without->balancedAccuracy, with->balancedAccuracy);
    EXPECT_GE(windows_, 40);
    EXPECT_GE(with->balancedAccuracy, 0.9);
    EXPECT_GT(with->balancedAccuracy, without->balancedAccuracy + 0.03);
}

TEST_F(InteractionTrainingTest, ClassifyActionsGathersTheSessionAndReproducesAfterReopen) {
    const TrainingOptions options = tackleOptions(true);
    auto sources =
        trainingSources(*project_, QStringLiteral("sim-imu-*"), {QStringLiteral("m1"), QStringLiteral("m2")});
    ASSERT_TRUE(sources.ok()) << qPrintable(sources.message());
    ASSERT_TRUE(attachInteraction(*project_, *sources, *options.interaction).ok());
    auto dataset = buildDataset(*sources, options);
    ASSERT_TRUE(dataset.ok()) << qPrintable(dataset.message());
    auto model = trainModel(*dataset, options);
    ASSERT_TRUE(model.ok()) << qPrintable(model.message());
    auto stored = model->toStored(QStringLiteral("tackles"));
    ASSERT_TRUE(stored.ok()) << qPrintable(stored.message());
    ASSERT_TRUE(stored->description.contains(QStringLiteral("interaction")));
    project_->models()[QStringLiteral("tackles")] = *stored;

    ClassifyActionsProcessor classify;
    const auto request = [&](const QString& player) {
        return RunRequest{classify.id(),
                          {QStringLiteral("m3/sim-imu-") + player},
                          QStringLiteral("m3/tackles-") + player,
                          {{QStringLiteral("model"), QStringLiteral("tackles")}}};
    };
    const QStringList players{QStringLiteral("home-01"), QStringLiteral("home-04"), QStringLiteral("away-02"),
                              QStringLiteral("away-06")};
    for (const QString& player : players) {
        auto run = runProcessor(*project_, classify, request(player));
        ASSERT_TRUE(run.ok()) << qPrintable(run.message());
    }
    Annotations before;
    for (const Annotation& a : project_->recording(QStringLiteral("m3"))->annotations)
        if (a.source == u"classify-actions") before.push_back(a);
    // The other athletes' streams are in the run's provenance: 14 IMU + 14 positions streams.
    const QJsonObject runs =
        project_->recording(QStringLiteral("m3"))->metadata.value(QStringLiteral("annotation_provenance")).toObject();
    const Provenance provenance = Provenance::fromJson(runs.value(QStringLiteral("m3/tackles-home-01")).toObject());
    EXPECT_EQ(provenance.inputs.size(), 28u);
    EXPECT_EQ(provenance.inputs.front().name, QStringLiteral("m3/sim-imu-home-01"));
    ASSERT_TRUE(project_->save().ok());

    auto reopened = Project::open(path_);
    ASSERT_TRUE(reopened.ok()) << qPrintable(reopened.message());
    Recording& m3 = *(*reopened)->recording(QStringLiteral("m3"));
    std::erase_if(m3.annotations, [](const Annotation& a) { return a.source == u"classify-actions"; });
    for (const QString& player : players) {
        auto run = runProcessor(**reopened, classify, request(player));
        ASSERT_TRUE(run.ok()) << qPrintable(run.message());
    }
    Annotations after;
    for (const Annotation& a : m3.annotations)
        if (a.source == u"classify-actions") after.push_back(a);
    EXPECT_EQ(after, before);

    // Another athlete's positions changed: a batch re-run sees the step as not done.
    const QJsonObject pipeline{
        {QStringLiteral("steps"),
         QJsonArray{QJsonObject{
             {QStringLiteral("processor"), classify.id()},
             {QStringLiteral("input"), QStringLiteral("m3/sim-imu-home-01")},
             {QStringLiteral("output"), QStringLiteral("m3/tackles-home-01")},
             {QStringLiteral("params"), QJsonObject{{QStringLiteral("model"), QStringLiteral("tackles")}}}}}}};
    auto done = checkPipelineDone(**reopened, pipeline);
    ASSERT_TRUE(done.ok()) << qPrintable(done.message());
    EXPECT_TRUE(done->done) << qPrintable(done->reason);
    Stream& pos = m3.streams.at(QStringLiteral("sim-pos-away-05"));
    auto data = pos.data();
    ASSERT_TRUE(data.ok());
    StreamData moved = **data;
    moved.at(0, 0) += 1.0;
    (*reopened)->putStream(QStringLiteral("m3/sim-pos-away-05"), Stream(pos.info(), std::move(moved)));
    done = checkPipelineDone(**reopened, pipeline);
    ASSERT_TRUE(done.ok()) << qPrintable(done.message());
    EXPECT_FALSE(done->done);
    EXPECT_TRUE(done->reason.contains(QStringLiteral("m3/sim-pos-away-05"))) << qPrintable(done->reason);

    // Without an athlete's positions the model is refused, naming the athlete's IMU stream.
    m3.streams.erase(QStringLiteral("sim-pos-away-05"));
    auto refused = runProcessor(**reopened, classify, request(QStringLiteral("home-01")));
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains(QStringLiteral("m3/sim-imu-away-05"))) << qPrintable(refused.message());
    EXPECT_TRUE(refused.message().contains(QStringLiteral("no positions stream"))) << qPrintable(refused.message());
}
