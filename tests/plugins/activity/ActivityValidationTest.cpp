// Train on simulated people, classify held-out people: sample-wise balanced accuracy ≥ 0.9 (the
// judged path of issue #14: athlos train + classify-actions on unseen subjects).
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/ClassifyActionsProcessor.h"

#include "core/processing/ProcessorRunner.h"
#include "tests/plugins/activity/SimulatedProject.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::activity;
using namespace athlos::activity::test;

TEST(ActivityValidationTest, HeldOutPeopleAreClassified) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    for (unsigned person = 1; person <= 8; ++person)
        addSimulated(*project, QStringLiteral("train%1").arg(person), person, 14, true);
    std::vector<SimulatedRecording> tests;
    for (unsigned person = 101; person <= 104; ++person)
        tests.push_back(addSimulated(*project, QStringLiteral("test%1").arg(person), person, 14, false));

    TrainingOptions options;
    auto sources = trainingSources(*project, QStringLiteral("imu"), {});
    ASSERT_TRUE(sources.ok()) << qPrintable(sources.message());
    ASSERT_EQ(sources->size(), 8u);  // the unlabelled recordings are not training sources
    auto dataset = buildDataset(*sources, options);
    ASSERT_TRUE(dataset.ok()) << qPrintable(dataset.message());
    EXPECT_EQ(dataset->classes.size(), 7);
    auto model = trainModel(*dataset, options);
    ASSERT_TRUE(model.ok()) << qPrintable(model.message());
    auto stored = model->toStored(QStringLiteral("m"));
    ASSERT_TRUE(stored.ok()) << qPrintable(stored.message());
    project->models()[QStringLiteral("m")] = *stored;

    ClassifyActionsProcessor processor;
    double worst = 1.0, sum = 0.0;
    for (std::size_t i = 0; i < tests.size(); ++i) {
        const QString rec = QStringLiteral("test%1").arg(101 + i);
        auto outcome = runProcessor(*project, processor,
                                    RunRequest{processor.id(),
                                               {rec + QStringLiteral("/imu")},
                                               rec + QStringLiteral("/actions"),
                                               {{QStringLiteral("model"), QStringLiteral("m")}}});
        ASSERT_TRUE(outcome.ok()) << qPrintable(outcome.message());
        const Annotations& predicted = project->recording(rec)->annotations;
        ASSERT_FALSE(predicted.empty());
        // The intervals tile the whole stream.
        EXPECT_LE(predicted.front().tStart, tests[i].imu.t.front());
        EXPECT_GE(predicted.back().tEnd, tests[i].imu.t.back());
        for (std::size_t k = 1; k < predicted.size(); ++k) EXPECT_DOUBLE_EQ(predicted[k].tStart, predicted[k - 1].tEnd);
        const double score = sampleBalancedAccuracy(tests[i].imu.t, tests[i].labels, predicted);
        std::printf("held-out person %zu: sample-wise balanced accuracy %.3f\n", 101 + i, score);
        worst = std::min(worst, score);
        sum += score;
    }
    EXPECT_GE(sum / double(tests.size()), 0.9);
    EXPECT_GE(worst, 0.8);
}

TEST(ActivityValidationTest, CrossValidationLeavesPeopleOut) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    for (unsigned person = 1; person <= 4; ++person)
        addSimulated(*project, QStringLiteral("r%1").arg(person), person, 7, true);
    auto sources = trainingSources(*project, QStringLiteral("imu"), {});
    ASSERT_TRUE(sources.ok());
    TrainingOptions options;
    options.classifier.trees = 50;
    auto dataset = buildDataset(*sources, options);
    ASSERT_TRUE(dataset.ok());
    auto groups = foldGroups(*dataset, *sources, options);
    ASSERT_TRUE(groups.ok());
    EXPECT_EQ(std::set<int>(groups->begin(), groups->end()).size(), 4u);
    auto evaluation = crossValidate(*dataset, *groups, options);
    ASSERT_TRUE(evaluation.ok()) << qPrintable(evaluation.message());
    long long total = 0;
    for (const auto& row : evaluation->confusion)
        for (long long v : row) total += v;
    EXPECT_EQ(total, (long long)dataset->labels.size());  // every window predicted once, by a model that never saw it
    EXPECT_GE(evaluation->balancedAccuracy, 0.8);
}
