// The random forest as parallel sub-forests (ParallelForest): every part trains on a stratified subsample
// (all classes in their shares), the model does not depend on the number of threads, it round-trips,
// its probabilities are the tree-weighted average of the parts' votes, models stored as one RTrees
// still load, and on a simulated problem it is as accurate as one OpenCV forest on all rows.
#include "plugins/activity/Classifier.h"
#include "plugins/activity/ParallelForest.h"

#include <gtest/gtest.h>
#include <cstdio>
#include <random>
#include <set>

using namespace athlos;
using namespace athlos::activity;

namespace {

// Overlapping Gaussian classes: class c has mean m_c (drawn once per problem) in F features, unit-free
// noise σ = 1.6 so that no classifier is perfect; class c has weights[c] of the rows.
struct Problem {
    cv::Mat x;
    std::vector<int> y;
};

Problem gaussianClasses(const std::vector<double>& weights, int rows, unsigned seed) {
    const int features = 12;
    std::mt19937 means(42);  // the same classes for training and test sets
    std::normal_distribution<float> unit(0.0f, 1.0f);
    cv::Mat centre(int(weights.size()), features, CV_32F);
    for (int c = 0; c < centre.rows; ++c)
        for (int f = 0; f < features; ++f) centre.at<float>(c, f) = unit(means);
    std::mt19937 rng(seed);
    std::discrete_distribution<int> pick(weights.begin(), weights.end());
    Problem p{cv::Mat(rows, features, CV_32F), {}};
    for (int i = 0; i < rows; ++i) {
        const int c = pick(rng);
        p.y.push_back(c);
        for (int f = 0; f < features; ++f) p.x.at<float>(i, f) = centre.at<float>(c, f) + 1.6f * unit(rng);
    }
    return p;
}

double balancedAccuracy(const Classifier& classifier, const Problem& test) {
    cv::Mat p;
    classifier.probabilities(test.x, p);
    std::vector<double> correct(std::size_t(p.cols), 0), total(std::size_t(p.cols), 0);
    for (int i = 0; i < p.rows; ++i) {
        const float* row = p.ptr<float>(i);
        const int predicted = int(std::max_element(row, row + p.cols) - row);
        total[std::size_t(test.y[std::size_t(i)])] += 1;
        correct[std::size_t(test.y[std::size_t(i)])] += predicted == test.y[std::size_t(i)];
    }
    double sum = 0;
    int present = 0;
    for (std::size_t c = 0; c < total.size(); ++c)
        if (total[c] > 0) {
            sum += correct[c] / total[c];
            ++present;
        }
    return sum / present;
}

std::string serialised(const Classifier& c) {
    cv::FileStorage fs(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
    fs << "classifier"
       << "{";
    c.write(fs);
    fs << "}";
    return fs.releaseAndGetString();
}

Classifier reread(const std::string& yaml, int classCount) {
    cv::FileStorage fs(yaml, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    auto c = Classifier::read(fs["classifier"], classCount);
    EXPECT_TRUE(c.ok()) << qPrintable(c.message());
    return *c;
}

const std::vector<double> kWeights{0.4, 0.25, 0.15, 0.1, 0.07, 0.03};

ClassifierOptions forestOptions(int maxRows, int threads) {
    ClassifierOptions o;
    o.trees = 40;
    o.forestTreesPerPart = 10;
    o.forestMaxRows = maxRows;
    o.threads = threads;
    return o;
}

}  // namespace

TEST(ParallelForest, PartsAreStratifiedSubsamplesOfTheirOwn) {
    std::vector<int> labels;
    for (int c = 0; c < 3; ++c) labels.insert(labels.end(), std::size_t(c == 0 ? 3000 : c == 1 ? 600 : 30), c);
    ParallelForest::Params params;
    params.maxRows = 1000;
    const auto a = ParallelForest::partRows(labels, 3, 0, params);
    const auto b = ParallelForest::partRows(labels, 3, 1, params);
    EXPECT_EQ(a, ParallelForest::partRows(labels, 3, 0, params));  // a part's rows depend on its seed only
    EXPECT_NE(a, b);
    for (const auto& rows : {a, b}) {
        EXPECT_EQ(std::set<int>(rows.begin(), rows.end()).size(), rows.size()) << "drawn without replacement";
        std::vector<int> perClass(3, 0);
        for (int r : rows) perClass[std::size_t(labels[std::size_t(r)])]++;
        // round(1000 · n_c / 3630): 826, 165, 8 — every class in its share, the smallest one included.
        EXPECT_EQ(perClass, (std::vector<int>{826, 165, 8}));
    }
    // At most maxRows rows: every row, in a shuffled order of the part's own.
    params.maxRows = 0;
    const auto all = ParallelForest::partRows(labels, 3, 2, params);
    EXPECT_EQ(std::set<int>(all.begin(), all.end()).size(), labels.size());
    EXPECT_FALSE(std::is_sorted(all.begin(), all.end()));
    params.trees = 95;
    params.treesPerPart = 10;
    EXPECT_EQ(ParallelForest::partCount(params), 10);
}

TEST(ParallelForest, SameModelWithAnyNumberOfThreadsAndAfterReading) {
    const Problem train = gaussianClasses(kWeights, 3000, 1);
    const Problem test = gaussianClasses(kWeights, 1000, 2);
    auto one = Classifier::train(train.x, train.y, 6, forestOptions(1200, 1));
    auto four = Classifier::train(train.x, train.y, 6, forestOptions(1200, 4));
    ASSERT_TRUE(one.ok()) << qPrintable(one.message());
    ASSERT_TRUE(four.ok()) << qPrintable(four.message());
    const std::string yaml = serialised(*one);
    EXPECT_TRUE(yaml == serialised(*four));  // (EXPECT_EQ would print a diff of megabytes)
    const Classifier back = reread(yaml, 6);
    cv::Mat before, after;
    one->probabilities(test.x, before);
    back.probabilities(test.x, after);
    EXPECT_EQ(cv::norm(before, after, cv::NORM_INF), 0.0);
    EXPECT_TRUE(serialised(back) == yaml);
}

TEST(ParallelForest, ProbabilitiesAreTheTreeWeightedMeanOfTheParts) {
    const Problem train = gaussianClasses(kWeights, 2000, 3);
    const Problem test = gaussianClasses(kWeights, 500, 4);
    ClassifierOptions options = forestOptions(800, 2);
    options.trees = 25;  // parts of 10, 10 and 5 trees
    auto forest = Classifier::train(train.x, train.y, 6, options);
    ASSERT_TRUE(forest.ok()) << qPrintable(forest.message());
    cv::Mat p;
    forest->probabilities(test.x, p);

    // The parts, read back as plain OpenCV forests, and their vote counts summed by hand.
    cv::FileStorage fs(serialised(*forest), cv::FileStorage::READ | cv::FileStorage::MEMORY);
    cv::Mat expected = cv::Mat::zeros(test.x.rows, 6, CV_32F);
    int parts = 0, trees = 0;
    for (const cv::FileNode& node : fs["classifier"]["models"]) {
        auto part = cv::ml::RTrees::create();
        part->read(node);
        ASSERT_TRUE(part->isTrained());
        cv::Mat votes;
        part->getVotes(test.x, votes, 0);
        int partTrees = 0;
        for (int j = 0; j < votes.cols; ++j) partTrees += votes.at<int>(1, j);
        EXPECT_EQ(partTrees, parts < 2 ? 10 : 5);
        trees += partTrees;
        for (int j = 0; j < votes.cols; ++j)
            for (int i = 0; i < test.x.rows; ++i)
                expected.at<float>(i, votes.at<int>(0, j)) += float(votes.at<int>(i + 1, j));
        ++parts;
    }
    EXPECT_EQ(parts, 3);
    EXPECT_EQ(trees, 25);
    expected /= float(trees);
    EXPECT_LT(cv::norm(p, expected, cv::NORM_INF), 1e-6);
}

TEST(ParallelForest, ModelsStoredAsOneOpenCvForestStillLoad) {
    const Problem train = gaussianClasses(kWeights, 1500, 5);
    const Problem test = gaussianClasses(kWeights, 500, 6);
    auto single = cv::ml::RTrees::create();
    single->setMaxDepth(20);
    single->setMinSampleCount(2);
    single->setTermCriteria({cv::TermCriteria::MAX_ITER, 20, 0});
    cv::Mat y(int(train.y.size()), 1, CV_32S, const_cast<int*>(train.y.data()));
    single->train(cv::ml::TrainData::create(train.x, cv::ml::ROW_SAMPLE, y));
    // The layout Classifier::write used before the parts: kind, class count and one model.
    cv::FileStorage out(".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
    out << "classifier"
        << "{"
        << "kind"
        << "random-forest"
        << "class_count" << 6 << "neighbours" << 7 << "models"
        << "["
        << "{";
    single->write(out);
    out << "}"
        << "]"
        << "}";
    const Classifier old = reread(out.releaseAndGetString(), 6);
    cv::Mat p, votes;
    old.probabilities(test.x, p);
    single->getVotes(test.x, votes, 0);
    for (int i = 0; i < test.x.rows; ++i)
        for (int j = 0; j < votes.cols; ++j)
            EXPECT_FLOAT_EQ(p.at<float>(i, votes.at<int>(0, j)), float(votes.at<int>(i + 1, j)) / 20.0f);
}

TEST(ParallelForest, AsAccurateAsOneForestOnEveryRow) {
    const Problem train = gaussianClasses(kWeights, 6000, 7);
    const Problem test = gaussianClasses(kWeights, 6000, 8);
    // One OpenCV forest of every tree on every (class-balanced) row, as before the parts.
    ClassifierOptions whole = forestOptions(0, 1);
    whole.forestTreesPerPart = whole.trees;
    auto reference = Classifier::train(train.x, train.y, 6, whole);
    // Parts of 10 trees, each on a subsample of 2000 of the ~14 000 balanced rows.
    auto parallel = Classifier::train(train.x, train.y, 6, forestOptions(2000, 2));
    ASSERT_TRUE(reference.ok() && parallel.ok());
    const double before = balancedAccuracy(*reference, test), after = balancedAccuracy(*parallel, test);
    std::printf("balanced accuracy: one forest on every row %.3f, parts on subsamples %.3f\n", before, after);
    EXPECT_GT(before, 0.6);  // the problem is learnable but not trivial
    EXPECT_LT(before, 0.95);
    EXPECT_GE(after, before - 0.02) << "whole forest " << before << ", parts " << after;
}

TEST(ParallelForest, CancelStopsTraining) {
    const Problem train = gaussianClasses(kWeights, 1000, 9);
    CancelToken token;
    token.cancel();
    auto forest = Classifier::train(train.x, train.y, 6, forestOptions(0, 2), Progress({}, token));
    ASSERT_FALSE(forest.ok());
    EXPECT_EQ(forest.message(), QStringLiteral("cancelled"));
}
