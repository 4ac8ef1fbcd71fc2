// Mutual-information feature ranking and selection (issue #14 item 2): the estimate against analytic
// values (a feature equal to the class has I = H(C); a binary channel with flip probability q has
// I = 1 − H_b(q)), pure noise near zero, the informative features selected, the ranking done inside each
// cross-validation training fold (selecting on all windows would score noise above chance), and a model
// trained with selection round-trips through the project and predicts the same after reopening.
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/ClassifyActionsProcessor.h"
#include "plugins/activity/FeatureSelection.h"

#include "core/processing/ProcessorRunner.h"
#include "tests/plugins/activity/SimulatedProject.h"

#include <QJsonArray>
#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace athlos;
using namespace athlos::activity;
using namespace athlos::activity::test;

namespace {

double binaryEntropy(double q) { return q <= 0 || q >= 1 ? 0.0 : -q * std::log2(q) - (1 - q) * std::log2(1 - q); }

QStringList columnNames(int count) {
    QStringList out;
    for (int j = 0; j < count; ++j) out << QStringLiteral("f%1").arg(j);
    return out;
}

}  // namespace

TEST(MutualInformation, FeatureEqualToTheClassHasTheClassEntropy) {
    // Three classes with shares 0.5, 0.3, 0.2 in shuffled order; column 0 = the class index, column 1 =
    // the class index mapped through a monotone function (the estimate depends on ranks only).
    std::mt19937 rng(5);
    std::vector<int> labels;
    for (int i = 0; i < 1000; ++i) labels.push_back(i < 500 ? 0 : (i < 800 ? 1 : 2));
    std::shuffle(labels.begin(), labels.end(), rng);
    cv::Mat samples(1000, 2, CV_32F);
    for (int i = 0; i < 1000; ++i) {
        samples.at<float>(i, 0) = float(labels[std::size_t(i)]);
        samples.at<float>(i, 1) = std::exp(3.0f * float(labels[std::size_t(i)])) - 7.0f;
    }
    const double h = -(0.5 * std::log2(0.5) + 0.3 * std::log2(0.3) + 0.2 * std::log2(0.2));  // 1.4855 bits
    for (int bins : {3, 10, 25}) {
        const auto mi = mutualInformation(samples, labels, 3, bins);
        EXPECT_NEAR(mi[0], h, 1e-9) << bins << " bins";
        EXPECT_NEAR(mi[1], h, 1e-9) << bins << " bins";
    }
}

TEST(MutualInformation, BinaryChannelAndNoise) {
    // Balanced binary class; column 0 = class flipped with probability q = 0.1: I = 1 − H_b(0.1) = 0.531 bits;
    // column 1 = Gaussian noise: I = 0 (plug-in bias ≈ (B − 1)(K − 1) / (2 N ln 2) = 0.0003 bits here);
    // column 2 = class + N(0, 1) noise: between the two.
    const int n = 20000;
    std::mt19937 rng(9);
    std::bernoulli_distribution flip(0.1), coin(0.5);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    std::vector<int> labels(static_cast<std::size_t>(n));
    cv::Mat samples(n, 3, CV_32F);
    for (int i = 0; i < n; ++i) {
        const int c = coin(rng) ? 1 : 0;
        labels[std::size_t(i)] = c;
        samples.at<float>(i, 0) = float(flip(rng) ? 1 - c : c);
        samples.at<float>(i, 1) = gauss(rng);
        samples.at<float>(i, 2) = float(c) + gauss(rng);
    }
    const auto mi = mutualInformation(samples, labels, 2, 10);
    EXPECT_NEAR(mi[0], 1.0 - binaryEntropy(0.1), 0.01);
    EXPECT_LT(mi[1], 0.002);
    EXPECT_GT(mi[2], 0.1);
    EXPECT_LT(mi[2], mi[0]);
}

TEST(FeatureSelection, KeepsTheInformativeFeatures) {
    // 4 classes; features 3, 7 and 12 shift with the class, the other 17 are noise.
    const int n = 2000, f = 20;
    std::mt19937 rng(2);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    std::vector<int> labels(static_cast<std::size_t>(n));
    cv::Mat samples(n, f, CV_32F);
    for (int i = 0; i < n; ++i) {
        const int c = i % 4;
        labels[std::size_t(i)] = c;
        for (int j = 0; j < f; ++j) samples.at<float>(i, j) = gauss(rng);
        samples.at<float>(i, 3) += 2.0f * float(c);
        samples.at<float>(i, 7) -= 1.0f * float(c);
        samples.at<float>(i, 12) += 3.0f * float(c == 2);
    }
    const QStringList names = columnNames(f);
    const FeatureSelection s = FeatureSelection::fit(samples, labels, 4, 3, names, 10);
    ASSERT_EQ(s.size(), 3);
    std::vector<int> columns = s.columns;
    std::sort(columns.begin(), columns.end());
    EXPECT_EQ(columns, (std::vector<int>{3, 7, 12}));
    EXPECT_EQ(s.columns.front(), 3);  // the strongest shift first
    EXPECT_GE(s.bits[0], s.bits[1]);
    EXPECT_GE(s.bits[1], s.bits[2]);
    EXPECT_EQ(s.names.front(), QStringLiteral("f3"));
    const cv::Mat selected = s.apply(samples);
    ASSERT_EQ(selected.cols, 3);
    EXPECT_EQ(selected.at<float>(17, 0), samples.at<float>(17, 3));
    // Through the description and back.
    auto back = FeatureSelection::fromJson(s.toJson(), names);
    ASSERT_TRUE(back.ok()) << qPrintable(back.message());
    EXPECT_EQ(back->columns, s.columns);
    auto refused = FeatureSelection::fromJson(s.toJson(), columnNames(5));
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains(QStringLiteral("'f12'"))) << qPrintable(refused.message());
    // k ≤ 0 or beyond the feature count: every feature, ranked.
    EXPECT_EQ(FeatureSelection::fit(samples, labels, 4, 0, names, 10).size(), f);
    EXPECT_EQ(FeatureSelection::fit(samples, labels, 4, 50, names, 10).size(), f);
}

TEST(FeatureSelection, RankedInsideEachCrossValidationFold) {
    // Labels independent of 2000 noise features on 120 windows: honest cross-validation is at chance,
    // while selecting the top 10 on all windows first (the test folds choosing their features) scores
    // well above it — the gap this test would catch.
    const int n = 120, f = 2000;
    std::mt19937 rng(4);
    std::normal_distribution<float> gauss(0.0f, 1.0f);
    Dataset d;
    d.samples = cv::Mat(n, f, CV_32F);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < f; ++j) d.samples.at<float>(i, j) = gauss(rng);
    for (int i = 0; i < n; ++i) {
        d.labels.push_back(i % 2);
        d.source.push_back(i % 4);
    }
    std::shuffle(d.labels.begin(), d.labels.end(), rng);
    d.classes = {QStringLiteral("a"), QStringLiteral("b")};
    d.features = columnNames(f);
    TrainingOptions options;
    options.classifier.kind = QStringLiteral("knn");
    options.miBins = 4;
    options.selectFeatures = 10;
    const std::vector<int> groups = d.source;
    auto honest = crossValidate(d, groups, options);
    ASSERT_TRUE(honest.ok()) << qPrintable(honest.message());

    Dataset leaky = d;
    const FeatureSelection all = FeatureSelection::fit(d.samples, d.labels, 2, 10, d.features, 4);
    leaky.samples = all.apply(d.samples);
    leaky.features = all.names;
    TrainingOptions none = options;
    none.selectFeatures = 0;
    auto cheated = crossValidate(leaky, groups, none);
    ASSERT_TRUE(cheated.ok());
    std::printf("balanced accuracy: honest %.3f, selected on all windows %.3f\n", honest->balancedAccuracy,
                cheated->balancedAccuracy);
    EXPECT_LT(honest->balancedAccuracy, 0.65);
    EXPECT_GT(cheated->balancedAccuracy, honest->balancedAccuracy + 0.1)
        << "leaky " << cheated->balancedAccuracy << ", honest " << honest->balancedAccuracy;
}

TEST(FeatureSelection, ModelWithSelectionRoundTripsAndPredictsTheSame) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.athlos"));
    auto project = Project::create(path);
    for (unsigned person = 1; person <= 3; ++person)
        addSimulated(*project, QStringLiteral("r%1").arg(person), person, 7, true);
    addSimulated(*project, QStringLiteral("new"), 50, 7, false);
    TrainingOptions options;
    options.classifier.trees = 30;
    options.selectFeatures = 15;
    auto sources = trainingSources(*project, QStringLiteral("imu"), {});
    ASSERT_TRUE(sources.ok()) << qPrintable(sources.message());
    auto dataset = buildDataset(*sources, options);
    ASSERT_TRUE(dataset.ok()) << qPrintable(dataset.message());
    auto model = trainModel(*dataset, options);
    ASSERT_TRUE(model.ok()) << qPrintable(model.message());
    ASSERT_TRUE(model->selection);
    EXPECT_EQ(model->selection->size(), 15);
    EXPECT_EQ(int(model->scaling.centre.size()), 15);
    // The stored selection is the top of the ranking on all windows.
    const FeatureSelection ranking = rankFeatures(*dataset, options);
    for (int i = 0; i < 15; ++i) EXPECT_EQ(model->selection->names[i], ranking.names[i]);
    auto stored = model->toStored(QStringLiteral("m"));
    ASSERT_TRUE(stored.ok()) << qPrintable(stored.message());
    const QJsonObject selection = stored->description.value(QStringLiteral("feature_selection")).toObject();
    EXPECT_EQ(selection.value(QStringLiteral("features")).toArray().size(), 15);
    EXPECT_EQ(selection.value(QStringLiteral("mi_bits")).toArray().size(), 15);
    EXPECT_GT(selection.value(QStringLiteral("mi_bits")).toArray().at(0).toDouble(), 0.5);
    project->models()[QStringLiteral("m")] = *stored;

    ClassifyActionsProcessor processor;
    const auto classify = [&](Project& p) {
        return runProcessor(p, processor,
                            RunRequest{processor.id(),
                                       {QStringLiteral("new/imu")},
                                       QStringLiteral("new/actions"),
                                       {{QStringLiteral("model"), QStringLiteral("m")}}});
    };
    auto first = classify(*project);
    ASSERT_TRUE(first.ok()) << qPrintable(first.message());
    const Annotations before = project->recording(QStringLiteral("new"))->annotations;
    ASSERT_FALSE(before.empty());
    ASSERT_TRUE(project->save().ok());

    auto reopened = Project::open(path);
    ASSERT_TRUE(reopened.ok()) << qPrintable(reopened.message());
    auto parsed = ActivityModel::fromStored(*(*reopened)->model(QStringLiteral("m")));
    ASSERT_TRUE(parsed.ok()) << qPrintable(parsed.message());
    ASSERT_TRUE(parsed->selection);
    EXPECT_EQ(parsed->selection->columns, model->selection->columns);
    (*reopened)->recording(QStringLiteral("new"))->annotations.clear();
    auto again = classify(**reopened);
    ASSERT_TRUE(again.ok()) << qPrintable(again.message());
    EXPECT_EQ((*reopened)->recording(QStringLiteral("new"))->annotations, before);

    // A selection naming a feature the model does not have is refused, not run.
    TrainedModel broken = *stored;
    QJsonObject d = broken.description;
    QJsonObject s = d.value(QStringLiteral("feature_selection")).toObject();
    QJsonArray names = s.value(QStringLiteral("features")).toArray();
    names[0] = QStringLiteral("acc_banana");
    s[QStringLiteral("features")] = names;
    d[QStringLiteral("feature_selection")] = s;
    broken.description = d;
    auto refused = ActivityModel::fromStored(broken);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains(QStringLiteral("acc_banana"))) << qPrintable(refused.message());
}
