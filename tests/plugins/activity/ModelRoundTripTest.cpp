// A trained model survives save/reopen and a copy of the project and predicts the same afterwards;
// classify-actions refuses models that do not fit the stream, naming the parameter.
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/ClassifyActionsProcessor.h"

#include "core/processing/ProcessorRunner.h"
#include "tests/plugins/activity/SimulatedProject.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::activity;
using namespace athlos::activity::test;

namespace {

class ModelRoundTripTest : public ::testing::TestWithParam<const char*> {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        path_ = dir_.filePath(QStringLiteral("p.athlos"));
        project_ = Project::create(path_);
        for (unsigned person = 1; person <= 3; ++person)
            addSimulated(*project_, QStringLiteral("r%1").arg(person), person, 7, true);
        addSimulated(*project_, QStringLiteral("new"), 50, 7, false);
    }
    Expected<RunOutcome> classify(Project& project, const QString& model, const QString& rec = QStringLiteral("new")) {
        ClassifyActionsProcessor processor;
        return runProcessor(project, processor,
                            RunRequest{processor.id(),
                                       {rec + QStringLiteral("/imu")},
                                       rec + QStringLiteral("/actions"),
                                       {{QStringLiteral("model"), model}}});
    }
    void train(const QString& kind) {
        TrainingOptions options;
        options.classifier.kind = kind;
        options.classifier.trees = 30;
        auto sources = trainingSources(*project_, QStringLiteral("imu"), {});
        ASSERT_TRUE(sources.ok()) << qPrintable(sources.message());
        auto dataset = buildDataset(*sources, options);
        ASSERT_TRUE(dataset.ok()) << qPrintable(dataset.message());
        auto model = trainModel(*dataset, options);
        ASSERT_TRUE(model.ok()) << qPrintable(model.message());
        auto stored = model->toStored(QStringLiteral("m"));
        ASSERT_TRUE(stored.ok()) << qPrintable(stored.message());
        project_->models()[QStringLiteral("m")] = *stored;
    }
    QTemporaryDir dir_;
    QString path_;
    std::unique_ptr<Project> project_;
};

}  // namespace

TEST_P(ModelRoundTripTest, SameModelAndPredictionsAfterReopen) {
    train(QString::fromLatin1(GetParam()));
    auto first = classify(*project_, QStringLiteral("m"));
    ASSERT_TRUE(first.ok()) << qPrintable(first.message());
    const Annotations before = project_->recording(QStringLiteral("new"))->annotations;
    ASSERT_FALSE(before.empty());
    ASSERT_TRUE(project_->save().ok());
    const TrainedModel original = *project_->model(QStringLiteral("m"));

    auto reopened = Project::open(path_);
    ASSERT_TRUE(reopened.ok()) << qPrintable(reopened.message());
    ASSERT_NE((*reopened)->model(QStringLiteral("m")), nullptr);
    EXPECT_EQ(*(*reopened)->model(QStringLiteral("m")), original);
    (*reopened)->recording(QStringLiteral("new"))->annotations.clear();
    auto again = classify(**reopened, QStringLiteral("m"));
    ASSERT_TRUE(again.ok()) << qPrintable(again.message());
    EXPECT_EQ((*reopened)->recording(QStringLiteral("new"))->annotations, before);

    // A copy (save as) and a second save of the reopened project keep the model (streams are copied
    // unloaded, models always come along).
    const QString copy = dir_.filePath(QStringLiteral("copy.athlos"));
    ASSERT_TRUE((*reopened)->saveAs(copy).ok());
    auto copied = Project::open(copy);
    ASSERT_TRUE(copied.ok()) << qPrintable(copied.message());
    ASSERT_NE((*copied)->model(QStringLiteral("m")), nullptr);
    EXPECT_EQ(*(*copied)->model(QStringLiteral("m")), original);
}

INSTANTIATE_TEST_SUITE_P(Classifiers, ModelRoundTripTest,
                         ::testing::Values("random-forest", "svm", "knn", "boosted-trees", "normal-bayes",
                                           "decision-tree", "mlp", "logistic-regression", "vote"));

TEST(ClassifyActionsTest, RefusesAModelThatDoesNotFitTheStream) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    for (unsigned person = 1; person <= 2; ++person)
        addSimulated(*project, QStringLiteral("r%1").arg(person), person, 7, true);
    TrainingOptions options;
    options.classifier.trees = 10;
    auto sources = trainingSources(*project, QStringLiteral("imu"), {});
    ASSERT_TRUE(sources.ok());
    auto dataset = buildDataset(*sources, options);
    ASSERT_TRUE(dataset.ok());
    auto model = trainModel(*dataset, options);
    ASSERT_TRUE(model.ok());
    project->models()[QStringLiteral("m")] = *model->toStored(QStringLiteral("m"));

    // An accelerometer-only stream.
    StreamData acc(300, 3);
    for (std::size_t i = 0; i < 300; ++i) {
        acc.t[i] = double(i) / 50.0;
        acc.at(i, 2) = 9.81;
    }
    project->putStream(
        QStringLiteral("wrist/imu"),
        outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                     columnsOf({QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z")},
                               {QStringLiteral("m/s^2"), QStringLiteral("m/s^2"), QStringLiteral("m/s^2")}),
                     std::move(acc)));
    ClassifyActionsProcessor processor;
    auto run = [&](const QString& model) {
        return runProcessor(*project, processor,
                            RunRequest{processor.id(),
                                       {QStringLiteral("wrist/imu")},
                                       QStringLiteral("wrist/actions"),
                                       {{QStringLiteral("model"), model}}});
    };
    auto refused = run(QStringLiteral("m"));
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains(QStringLiteral("model: 'm' does not fit input 'wrist/imu'")))
        << qPrintable(refused.message());
    EXPECT_TRUE(refused.message().contains(QStringLiteral("gyr_x"))) << qPrintable(refused.message());
    auto unknown = run(QStringLiteral("nope"));
    ASSERT_FALSE(unknown.ok());
    EXPECT_TRUE(unknown.message().contains(QStringLiteral("model: the project has no model 'nope' (models: m")))
        << qPrintable(unknown.message());
    EXPECT_TRUE(project->recording(QStringLiteral("wrist"))->annotations.empty());

    // A model whose description was tampered with is refused, not run.
    TrainedModel broken = *project->model(QStringLiteral("m"));
    broken.name = QStringLiteral("broken");
    broken.definition = "%YAML:1.0\nclassifier: { kind: \"random-forest\", class_count: 7 }\n";
    project->models()[QStringLiteral("broken")] = broken;
    auto damaged = runProcessor(*project, processor,
                                RunRequest{processor.id(),
                                           {QStringLiteral("r1/imu")},
                                           QStringLiteral("r1/actions"),
                                           {{QStringLiteral("model"), QStringLiteral("broken")}}});
    ASSERT_FALSE(damaged.ok());
    EXPECT_TRUE(damaged.message().contains(QStringLiteral("model: model 'broken'"))) << qPrintable(damaged.message());
}
