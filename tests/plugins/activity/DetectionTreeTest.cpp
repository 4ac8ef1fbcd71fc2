// The cost-sensitive detection tree behind the impact detector (seed 000 §5.2): a larger FN:FP cost
// keeps more relevant candidates, the grid search picks the smallest cost reaching the target recall
// with subjects left out, the tree survives its JSON, and on simulated beach volleyball the detector
// with the tree still finds ≥ 99 % of the actions while dropping most Null candidates, also when it is
// stored in a model and re-read.
#include "plugins/activity/DetectionTree.h"
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/EventDetectors.h"
#include "plugins/activity/EventSimulator.h"

#include "core/processing/OutputStreams.h"

#include <gtest/gtest.h>
#include <random>

using namespace athlos;
using namespace athlos::activity;

namespace {

// Two overlapping clouds: relevant candidates hit and swing harder than Null ones.
std::vector<DetectionTree::Sample> clouds(unsigned seed, int perClass, int groups, double sd = 2.0) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sd);
    std::vector<DetectionTree::Sample> out;
    for (int i = 0; i < perClass; ++i) {
        out.push_back({10.0 + noise(rng), 8.0 + noise(rng), true, i % groups});
        out.push_back({7.0 + noise(rng), 5.0 + noise(rng), false, i % groups});
    }
    return out;
}

double recallOf(const DetectionTree& tree, const std::vector<DetectionTree::Sample>& samples, bool relevant) {
    int n = 0, kept = 0;
    for (const auto& s : samples)
        if (s.relevant == relevant) {
            ++n;
            kept += tree.keep(s.impact, s.swing);
        }
    return double(kept) / double(n);
}

}  // namespace

TEST(DetectionTreeTest, HigherCostKeepsMoreRelevantCandidates) {
    const auto train = clouds(1, 400, 5), test = clouds(2, 400, 5);
    DetectionTree::Params params;
    params.targetRecall = 0.01;  // the first cost of each grid is taken
    params.costRatios = {1};
    auto even = DetectionTree::train(train, params);
    params.costRatios = {50};
    auto costly = DetectionTree::train(train, params);
    ASSERT_TRUE(even.ok() && costly.ok());
    const double recallEven = recallOf(*even, test, true), recallCostly = recallOf(*costly, test, true);
    std::printf("cost 1: recall %.3f, null kept %.3f; cost 50: recall %.3f, null kept %.3f\n", recallEven,
                recallOf(*even, test, false), recallCostly, recallOf(*costly, test, false));
    // Equal costs split the clouds near the middle (≈ 85 % each side); a missed action costing 50 false
    // alarms keeps more of them, and more Null candidates with them.
    EXPECT_LT(recallEven, 0.93);
    EXPECT_GT(recallCostly, recallEven + 0.04);
    EXPECT_GT(recallOf(*costly, test, false), recallOf(*even, test, false));
}

TEST(DetectionTreeTest, GridSearchPicksTheSmallestCostReachingTheTarget) {
    const auto samples = clouds(3, 500, 6, 1.0);
    DetectionTree::Params params;  // target 0.99, the thesis's grid
    auto tree = DetectionTree::train(samples, params);
    ASSERT_TRUE(tree.ok()) << qPrintable(tree.message());
    const DetectionTree::Fit& fit = tree->fit();
    std::printf("chosen cost %g: held-out recall %.4f, null rejected %.3f, %d folds\n", fit.costRatio, fit.recall,
                fit.nullRejected, fit.groups);
    EXPECT_TRUE(fit.targetReached);
    EXPECT_GE(fit.recall, 0.99);
    EXPECT_GT(fit.nullRejected, 0.2);  // the tree still rejects something
    EXPECT_EQ(fit.groups, 6);
    // The next smaller cost of the grid does not reach the target.
    const auto it = std::find(params.costRatios.begin(), params.costRatios.end(), fit.costRatio);
    ASSERT_NE(it, params.costRatios.end());
    ASSERT_NE(it, params.costRatios.begin());
    DetectionTree::Params below = params;
    below.costRatios.assign(params.costRatios.begin(), it);
    auto smaller = DetectionTree::train(samples, below);
    ASSERT_TRUE(smaller.ok());
    EXPECT_FALSE(smaller->fit().targetReached);
    EXPECT_LT(smaller->fit().recall, 0.99);
    EXPECT_TRUE(smaller->keep(0.0, 0.0));  // below the target: no tree, everything kept
}

TEST(DetectionTreeTest, RoundTripsThroughJson) {
    auto tree = DetectionTree::train(clouds(4, 300, 4), {});
    ASSERT_TRUE(tree.ok());
    auto reread = DetectionTree::fromJson(tree->toJson());
    ASSERT_TRUE(reread.ok()) << qPrintable(reread.message());
    EXPECT_EQ(reread->fit().costRatio, tree->fit().costRatio);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(0.0, 16.0);
    for (int i = 0; i < 2000; ++i) {
        const double a = u(rng), b = u(rng);
        ASSERT_EQ(reread->keep(a, b), tree->keep(a, b)) << a << ", " << b;
    }
    QJsonObject broken = tree->toJson();
    broken[QStringLiteral("opencv_dtrees")] = QStringLiteral("%YAML:1.0\n---\ntree: 3\n");
    EXPECT_FALSE(DetectionTree::fromJson(broken).ok());
}

TEST(DetectionTreeTest, RefusesWithoutRelevantCandidatesAndKeepsAllWithoutNull) {
    auto samples = clouds(5, 50, 2);
    std::erase_if(samples, [](const auto& s) { return s.relevant; });
    EXPECT_FALSE(DetectionTree::train(samples, {}).ok());
    samples = clouds(5, 50, 2);
    std::erase_if(samples, [](const auto& s) { return !s.relevant; });
    auto tree = DetectionTree::train(samples, {});
    ASSERT_TRUE(tree.ok());
    EXPECT_TRUE(tree->keep(0.0, 0.0));
}

TEST(DetectionTreeTest, VolleyballDetectorWithTreeKeepsNinetyNinePercent) {
    StreamInfo info;
    info.name = info.kind = QStringLiteral("imu");
    info.columns = columnsOf({QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z")},
                             {QStringLiteral("m/s^2"), QStringLiteral("m/s^2"), QStringLiteral("m/s^2")});
    std::vector<TrainingSource> sources;
    for (unsigned p = 1; p <= 6; ++p) {
        SimulatedEvents sim = EventSimulator::volleyball(p, 50, 400 + p);
        TrainingSource s;
        s.recording = s.athlete = QStringLiteral("player%1").arg(p);
        s.info = info;
        s.annotations = sim.annotations;
        s.data = std::make_shared<const StreamData>(std::move(sim.imu));
        sources.push_back(std::move(s));
    }
    TrainingOptions options;
    options.window = 4.0;
    options.sensors = {QStringLiteral("acc")};
    options.segmentation = *Segmentation::parse(QStringLiteral("events:impact"));
    auto with = fitSegmentation(sources, options, {});
    ASSERT_TRUE(with.ok()) << qPrintable(with.message());
    ASSERT_TRUE(with->detectionTree.has_value());
    const DetectionTree::Fit& fit = with->detectionTree->fit();
    std::printf("volleyball: cost %g, held-out recall %.4f of %d, null rejected %.3f of %d\n", fit.costRatio,
                fit.recall, fit.relevant, fit.nullRejected, fit.nulls);
    EXPECT_GE(fit.recall, 0.99);
    EXPECT_GT(fit.nullRejected, 0.5);

    // The stored segmentation cuts fewer windows, and the same ones after re-reading.
    auto reread = Segmentation::fromJson(with->toJson());
    ASSERT_TRUE(reread.ok()) << qPrintable(reread.message());
    options.segmentation.useDetectionTree = false;
    auto without = fitSegmentation(sources, options, {});
    ASSERT_TRUE(without.ok());
    EXPECT_FALSE(without->detectionTree.has_value());
    std::size_t all = 0, kept = 0, keptReread = 0, found = 0, actions = 0;
    for (const TrainingSource& s : sources) {
        auto a = without->detect(s.info, *s.data), b = with->detect(s.info, *s.data),
             c = reread->detect(s.info, *s.data);
        ASSERT_TRUE(a.ok() && b.ok() && c.ok());
        all += a->size();
        kept += b->size();
        keptReread += c->size();
        found += std::size_t(std::llround(eventRecall(*b, s.annotations, -0.25) * double(s.annotations.size())));
        actions += s.annotations.size();
    }
    EXPECT_LT(kept, all);
    EXPECT_EQ(keptReread, kept);
    // Trained on these players, the tree keeps at least what it kept held out.
    EXPECT_GE(double(found), 0.99 * double(actions));
}
