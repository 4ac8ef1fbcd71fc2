// Per-instant ToA fixes from two-way ranges and the merging of anchors that report at different times.
#include "plugins/lps/RangeSolver.h"
#include "plugins/lps/RangeStream.h"

#include <gtest/gtest.h>

#include <random>

using namespace athlos::lps;

namespace {

BeaconLayout layout() {
    BeaconLayout l;
    l.ids = {"a", "b", "c", "d", "e", "f"};
    l.positions = {{0, 0, 3}, {30, 0, 5}, {30, 20, 3}, {0, 20, 6}, {15, -5, 8}, {15, 25, 2}};
    return l;
}

RangeFixInput rangesTo(const Vector3& m, const BeaconLayout& l, double sigma = 0.0, std::uint64_t seed = 1) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma > 0 ? sigma : 1.0);
    TdoaEpoch epoch{0.5, {}};
    for (int b = 0; b < l.size(); ++b)
        epoch.readings.push_back({b, (m - l.positions[std::size_t(b)]).norm() + (sigma > 0 ? noise(rng) : 0.0)});
    RangeFixInput input;
    input.assign(epoch, l);
    return input;
}

}  // namespace

TEST(RangeSolver, NoiseFreeFixIsExactPlanarAndSpatial) {
    const BeaconLayout l = layout();
    RangeSolver::Params p;
    p.tagHeight = 1.1;
    RangeSolver planar(p);
    const Vector3 truth(12.3, 7.7, 1.1);
    const TagFix f = planar.solve(rangesTo(truth, l));
    ASSERT_TRUE(f.valid);
    EXPECT_LT((f.position - truth).norm(), 1e-6);
    EXPECT_EQ(f.beaconsUsed, 6);
    p.geometry = RangeSolver::Geometry::Spatial;
    RangeSolver spatial(p);
    const Vector3 high(20.0, 4.0, 2.5);
    const TagFix g = spatial.solve(rangesTo(high, l));
    ASSERT_TRUE(g.valid);
    EXPECT_LT((g.position - high).norm(), 1e-6);
}

TEST(RangeSolver, IrlsRejectsAnNlosRange) {
    const BeaconLayout l = layout();
    RangeSolver::Params p;
    p.tagHeight = 1.0;
    const Vector3 truth(8.0, 14.0, 1.0);
    RangeFixInput input = rangesTo(truth, l, 0.05, 3);
    input.ranges[2] += 3.0;  // beacon c through a wall
    p.selection = RangeSolver::Selection::All;
    const TagFix all = RangeSolver(p).solve(input);
    p.selection = RangeSolver::Selection::Irls;
    const TagFix irls = RangeSolver(p).solve(input);
    ASSERT_TRUE(all.valid && irls.valid);
    EXPECT_GT((all.position - truth).norm(), 0.5);
    EXPECT_LT((irls.position - truth).norm(), 0.15);
    EXPECT_EQ(irls.beaconsUsed, 5);
}

TEST(RangeSolver, TooFewRangesOrInconsistentRangesGiveNoFix) {
    const BeaconLayout l = layout();
    RangeSolver solver;
    RangeFixInput two = rangesTo({5, 5, 1}, l);
    two.beacons.resize(2);
    two.ranges.resize(2);
    two.index.resize(2);
    two.weights.resize(2);
    EXPECT_FALSE(solver.solve(two).valid);
    RangeFixInput wild = rangesTo({5, 5, 1}, l);
    for (std::size_t i = 0; i < wild.ranges.size(); ++i) wild.ranges[i] = 1.0 + 40.0 * double(i % 2);
    EXPECT_FALSE(solver.solve(wild).valid);
}

TEST(RangeEpochs, NewestFreshRangePerAnchorNeverExtrapolated) {
    std::vector<RangeReading> r = {{0.00, 0, 5.0}, {0.03, 1, 6.0}, {0.06, 2, 7.0}, {0.11, 0, 5.1},
                                   {0.13, 1, 6.1}, {0.45, 0, 5.4}, {0.47, 1, 6.4}, {0.48, 2, 7.4}};
    const auto epochs = mergeRangeEpochs(r, 3, 0.1, 0.15, 3);
    // 0.1: a 5.0 (0.10 old), b 6.0, c 7.0; 0.2: a 5.1, b 6.1, c 7.0 (0.14 old); 0.3: c is 0.24 old → dropped;
    // 0.5: all three fresh again.
    ASSERT_EQ(epochs.size(), 3u);
    EXPECT_NEAR(epochs[0].t, 0.1, 1e-12);
    EXPECT_NEAR(epochs[1].t, 0.2, 1e-12);
    EXPECT_NEAR(epochs[1].readings[0].dt, 5.1, 1e-12);
    EXPECT_NEAR(epochs[1].readings[2].dt, 7.0, 1e-12);
    EXPECT_NEAR(epochs[2].t, 0.5, 1e-12);
    EXPECT_NEAR(epochs[2].readings[1].dt, 6.4, 1e-12);
    EXPECT_EQ(mergeRangeEpochs(r, 3, 0.1, 0.15, 4).size(), 0u);
}
