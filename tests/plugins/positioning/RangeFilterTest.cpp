// Tightly coupled range filtering against simulated truth: a tag walking a 30 × 12 m loop beside a
// compact group of four anchors (the outdoor UWB dataset's geometry, scaled), asynchronous 10 Hz
// ranges per anchor with 0.1 m noise, two anchors with constant offsets, and NLOS bursts.
#include "plugins/positioning/RangeFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace athlos::positioning;

namespace {

struct Scenario {
    RangeMeasurements ranges;
    std::vector<double> truthT;
    std::vector<Eigen::Vector2d> truth;
};

Eigen::Vector2d pathAt(double t) {
    // Stadium-shaped loop, 1.4 m/s, starting 4 m from the anchors.
    const double perimeter = 2 * 30.0 + std::numbers::pi * 12.0;
    double s = std::fmod(1.4 * t, perimeter);
    if (s < 30.0) return {4.0 + s, -6.0};
    s -= 30.0;
    if (s < std::numbers::pi * 6.0) {
        const double a = -std::numbers::pi / 2 + s / 6.0;
        return {34.0 + 6.0 * std::cos(a), 6.0 * std::sin(a)};
    }
    s -= std::numbers::pi * 6.0;
    if (s < 30.0) return {34.0 - s, 6.0};
    s -= 30.0;
    const double a = std::numbers::pi / 2 + s / 6.0;
    return {4.0 + 6.0 * std::cos(a), 6.0 * std::sin(a)};
}

Scenario simulate(std::uint64_t seed, std::vector<double> offsets, double nlosShare, double duration = 120.0) {
    Scenario s;
    s.ranges.beacons = {{0.7, 0.9, 0.5}, {2.6, 0.9, 2.0}, {2.6, -0.9, 2.0}, {2.6, -0.9, 0.5}};
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double tagHeight = 1.0;
    // Each anchor reports at 10 Hz with its own phase (not synchronised).
    struct Event {
        double t;
        int beacon;
    };
    std::vector<Event> events;
    for (int b = 0; b < 4; ++b)
        for (double t = 0.013 * (b + 1); t < duration; t += 0.1) events.push_back({t, b});
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
    for (const auto& e : events) {
        const Eigen::Vector2d p = pathAt(e.t);
        double d = (Eigen::Vector3d(p.x(), p.y(), tagHeight) - s.ranges.beacons[std::size_t(e.beacon)]).norm();
        d += offsets[std::size_t(e.beacon)] + noise(rng);
        if (unit(rng) < nlosShare) d += 1.0 + 3.0 * unit(rng);  // NLOS: always longer
        s.ranges.t.push_back(e.t);
        s.ranges.y.push_back({d, e.beacon});
    }
    for (double t = 0.1; t < duration - 0.1; t += 0.1) {
        s.truthT.push_back(t);
        s.truth.push_back(pathAt(t));
    }
    return s;
}

RangeFilter::Params params() {
    RangeFilter::Params p;
    p.model = ModelKind::ConstantVelocity;
    p.noise.qAccelCv = 0.3;
    p.rRange = 0.01;
    p.noise.gate = 9.0;
    p.tagHeight = 1.0;
    p.biasSigma = 0.1;
    return p;
}

double rmse(const Scenario& s, const RangeFilter::Result& r) {
    double sum = 0.0;
    for (std::size_t k = 0; k < s.truth.size(); ++k) {
        const Kinematics& e = r.filtered.states[k];
        sum += (Eigen::Vector2d(e.x, e.y) - s.truth[k]).squaredNorm();
    }
    return std::sqrt(sum / double(s.truth.size()));
}

}  // namespace

TEST(RangeFilter, InitialPositionFromTheFirstSecond) {
    const Scenario s = simulate(1, {0, 0, 0, 0}, 0.0);
    const auto start = RangeFilter::initialPosition(s.ranges, 1.0);
    ASSERT_TRUE(start.has_value());
    EXPECT_LT((*start - pathAt(0.5)).norm(), 0.6);
    RangeMeasurements two = s.ranges;
    for (auto& y : two.y) y.beacon = y.beacon % 2;  // only two anchors report
    EXPECT_FALSE(RangeFilter::initialPosition(two, 1.0).has_value());
    EXPECT_FALSE(RangeFilter(params()).run(two, {}).ok());
}

TEST(RangeFilter, FollowsTheTrackAndEstimatesRelativeOffsets) {
    const Scenario s = simulate(2, {0.06, 0.06, -0.06, -0.06}, 0.0);
    RangeFilter::Params p = params();
    p.offsets = false;
    const auto without = RangeFilter(p).run(s.ranges, s.truthT);
    ASSERT_TRUE(without.ok());
    p.offsets = true;
    const auto with = RangeFilter(p).run(s.ranges, s.truthT);
    ASSERT_TRUE(with.ok());
    const double eWithout = rmse(s, *without), eWith = rmse(s, *with);
    // The offsets split 2:2 across the anchor group rotate every far fix (≈ 0.12 m / 1.8 m ≈ 3.8°).
    EXPECT_GT(eWithout, 0.5);
    EXPECT_LT(eWith, 0.35);
    ASSERT_EQ(with->offsets.size(), 4u);
    const double mean = 0.25 * (with->offsets[0] + with->offsets[1] + with->offsets[2] + with->offsets[3]);
    EXPECT_NEAR(with->offsets[0] - mean, 0.06, 0.03);
    EXPECT_NEAR(with->offsets[2] - mean, -0.06, 0.03);
}

TEST(RangeFilter, GatesNlosRangesOneByOne) {
    const Scenario clean = simulate(3, {0, 0, 0, 0}, 0.0);
    const Scenario nlos = simulate(3, {0, 0, 0, 0}, 0.1);
    const RangeFilter filter(params());
    const auto a = filter.run(clean.ranges, clean.truthT);
    const auto b = filter.run(nlos.ranges, nlos.truthT);
    ASSERT_TRUE(a.ok() && b.ok());
    EXPECT_LT(rmse(clean, *a), 0.3);
    EXPECT_LT(rmse(nlos, *b), 0.4);
    // Most NLOS ranges (≥ 1 m long) are rejected individually, few clean ones are.
    int rejected = 0;
    for (char o : b->filtered.outlier) rejected += o;
    const double share = double(rejected) / double(nlos.ranges.size());
    EXPECT_GT(share, 0.07);
    EXPECT_LT(share, 0.2);
    // Without the gate the same data is clearly worse.
    RangeFilter::Params ungated = params();
    ungated.noise.gate = athlos::estimation::kNoGate;
    const auto c = RangeFilter(ungated).run(nlos.ranges, nlos.truthT);
    ASSERT_TRUE(c.ok());
    EXPECT_GT(rmse(nlos, *c), 1.5 * rmse(nlos, *b));
}

TEST(RangeFilter, NoiseEstimateOnThinnedRangesFindsTheRangeNoise) {
    const Scenario s = simulate(4, {0, 0, 0, 0}, 0.0, 240.0);
    RangeFilter::Params p = params();
    p.rRange = 1.0;
    p.noise.qAccelCv = 10.0;
    double r = 0.0;
    athlos::estimation::NoiseEstimator::Params search;
    search.starts = 2;
    const auto e = RangeFilter::estimateNoise(p, {RangeFilter::thinned(s.ranges, 1.0)}, r, search);
    EXPECT_FALSE(e.cancelled);
    EXPECT_GT(r, 0.5 * 0.01);  // simulated σ = 0.1 m
    EXPECT_LT(r, 2.0 * 0.01);
}

TEST(RangeFilter, ThinningKeepsEachBeaconsSpacing) {
    const Scenario s = simulate(5, {0, 0, 0, 0}, 0.0, 20.0);
    const RangeMeasurements t = RangeFilter::thinned(s.ranges, 1.0);
    std::vector<double> last(4, -1e9);
    for (std::size_t k = 0; k < t.size(); ++k) {
        EXPECT_GE(t.t[k] - last[std::size_t(t.y[k].beacon)], 1.0);
        last[std::size_t(t.y[k].beacon)] = t.t[k];
    }
    EXPECT_NEAR(double(t.size()), 4 * 20.0, 8.0);
}

TEST(RangeFilter, CancelStopsTheRun) {
    const Scenario s = simulate(6, {0, 0, 0, 0}, 0.0);
    const auto r = RangeFilter(params()).run(s.ranges, s.truthT, [](double) { return false; });
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r->filtered.cancelled);
}
