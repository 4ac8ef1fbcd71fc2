// gait-summary's engine on hand-made stride tables whose answer is worked out by hand: which strides
// are steady (turns and the ends of straight runs out), mean / SD (n − 1) / CV, and the symmetry index.
#include "plugins/events/GaitSummary.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace athlos::events;

namespace {

// Ten strides of 1.1 s: 0–4 adjacent and straight, 5 turns (1 rad), 6–9 adjacent and straight after a
// 0.5 s pause. The steady ones (edge 1) are 1, 2, 3 and 7, 8 with lengths 1.0, 1.2, 1.4, 1.1, 1.3; the
// others are 5.0 m, so that counting any of them shows in the mean.
FootStrides walk(const QString& foot, double scale) {
    FootStrides f;
    f.foot = foot;
    f.names = {QStringLiteral("stride_length"), QStringLiteral("stride_time")};
    f.units = {QStringLiteral("m"), QStringLiteral("s")};
    f.parameters.resize(2);
    const double lengths[10] = {5.0, 1.0, 1.2, 1.4, 5.0, 5.0, 5.0, 1.1, 1.3, 5.0};
    double t = 0.0;
    for (int i = 0; i < 10; ++i) {
        if (i == 6) t += 0.5;  // a pause: stride 6 does not start where 5 ended
        f.start.push_back(t);
        f.end.push_back(t + 1.1);
        t += 1.1;
        f.turn.push_back(i == 5 ? 1.0 : (i % 2 ? 0.05 : -0.05));
        f.parameters[0].push_back(scale * lengths[i]);
        f.parameters[1].push_back(1.1);
    }
    return f;
}

}  // namespace

TEST(GaitSummary, SteadyStridesLeaveOutTurnsAndTheEndsOfEveryStraightRun) {
    const std::vector<bool> use = steadyStrides(GaitSummaryParams{}, walk(QStringLiteral("left"), 1.0));
    const std::vector<bool> expected = {false, true, true, true, false, false, false, true, true, false};
    EXPECT_EQ(use, expected);
    GaitSummaryParams none;
    none.edgeStrides = 0;
    const std::vector<bool> all = steadyStrides(none, walk(QStringLiteral("left"), 1.0));
    for (int i = 0; i < 10; ++i) EXPECT_EQ(all[std::size_t(i)], i != 5) << i;
    none.maxTurn = 2.0;
    for (bool u : steadyStrides(none, walk(QStringLiteral("left"), 1.0))) EXPECT_TRUE(u);
}

TEST(GaitSummary, MeanSdCvOfTheSteadyStrides) {
    const GaitSummary g = summariseGait(GaitSummaryParams{}, {walk(QStringLiteral("left"), 1.0)});
    ASSERT_EQ(g.feet.size(), 1u);
    const FootSummary& s = g.feet[0];
    EXPECT_EQ(s.strides, 10);
    EXPECT_EQ(s.turns, 1);
    EXPECT_EQ(s.edges, 4);
    EXPECT_EQ(s.used, 5);
    // 1.0, 1.2, 1.4, 1.1, 1.3: mean 1.2, squares 0.04 + 0 + 0.04 + 0.01 + 0.01 over n − 1 = 4.
    EXPECT_EQ(s.stats[0].n, 5);
    EXPECT_NEAR(s.stats[0].mean, 1.2, 1e-12);
    EXPECT_NEAR(s.stats[0].sd, std::sqrt(0.025), 1e-12);
    EXPECT_NEAR(s.stats[0].cv, 100.0 * std::sqrt(0.025) / 1.2, 1e-9);
    EXPECT_NEAR(s.stats[1].sd, 0.0, 1e-12);
    EXPECT_TRUE(g.symmetry.empty());
}

TEST(GaitSummary, SymmetryIndexAndBothFeetTogether) {
    // The right foot's steady strides are 0.8 × the left's: means 1.2 and 0.96.
    const GaitSummary g =
        summariseGait(GaitSummaryParams{}, {walk(QStringLiteral("left"), 1.0), walk(QStringLiteral("right"), 0.8)});
    ASSERT_EQ(g.feet.size(), 2u);
    ASSERT_EQ(g.symmetry.size(), 2u);
    EXPECT_NEAR(g.symmetry[0], 100.0 * 0.24 / 1.08, 1e-9);  // Robinson et al. 1987
    EXPECT_NEAR(g.symmetry[1], 0.0, 1e-12);
    EXPECT_EQ(g.pooled.foot, QStringLiteral("both"));
    EXPECT_EQ(g.pooled.used, 10);
    EXPECT_EQ(g.pooled.stats[0].n, 10);
    EXPECT_NEAR(g.pooled.stats[0].mean, 1.08, 1e-12);
    // The SD of the ten values, from their definition.
    const double v[10] = {1.0, 1.2, 1.4, 1.1, 1.3, 0.8, 0.96, 1.12, 0.88, 1.04};
    double ss = 0.0;
    for (double x : v) ss += (x - 1.08) * (x - 1.08);
    EXPECT_NEAR(g.pooled.stats[0].sd, std::sqrt(ss / 9.0), 1e-12);
}

TEST(GaitSummary, OneSteadyStrideHasAMeanButNoSpread) {
    GaitSummaryParams p;
    p.edgeStrides = 2;  // runs of 5 and 4 keep stride 2 only
    const GaitSummary g = summariseGait(p, {walk(QStringLiteral("left"), 1.0)});
    EXPECT_EQ(g.feet[0].used, 1);
    EXPECT_NEAR(g.feet[0].stats[0].mean, 1.2, 1e-12);
    EXPECT_TRUE(std::isnan(g.feet[0].stats[0].sd));
    EXPECT_TRUE(std::isnan(g.feet[0].stats[0].cv));
}

TEST(GaitSummary, NoRatiosForASignedQuantity) {
    // A stride height that crosses zero (level walking) has a mean and SD, but no CV and no SI.
    FootStrides left = walk(QStringLiteral("left"), 1.0), right = walk(QStringLiteral("right"), 1.0);
    for (FootStrides* f : {&left, &right}) {
        f->names << QStringLiteral("stride_height");
        f->units << QStringLiteral("m");
        f->parameters.push_back({0, 0.02, -0.01, 0.03, 0, 0, 0, -0.02, 0.01, 0});
    }
    const GaitSummary g = summariseGait(GaitSummaryParams{}, {left, right});
    const ParameterStats& h = g.feet[0].stats[2];
    EXPECT_NEAR(h.mean, 0.006, 1e-12);
    EXPECT_FALSE(std::isnan(h.sd));
    EXPECT_TRUE(std::isnan(h.cv));
    EXPECT_TRUE(std::isnan(g.symmetry[2]));
    EXPECT_FALSE(std::isnan(g.symmetry[0]));
}

TEST(GaitSummary, TerrainByStrideHeight) {
    // Heights: 0.29 m (two steps up) for strides 0–4, 0.15 m (one step and a landing: a transition) for
    // stride 6, −0.29 m (down) for 7–9; stride 5 turns. With terrain up the steady strides are 1–3 (the
    // run 0–4 without its ends), down keeps stride 8 only; the transition counts for neither.
    FootStrides f = walk(QStringLiteral("left"), 1.0);
    f.height = {0.29, 0.29, 0.29, 0.29, 0.29, 0.0, 0.15, -0.29, -0.29, -0.29};
    f.names << QStringLiteral("stride_height");
    f.units << QStringLiteral("m");
    f.parameters.push_back(f.height);
    GaitSummaryParams up;
    up.terrain = Terrain::Up;
    std::vector<bool> expected = {false, true, true, true, false, false, false, false, false, false};
    EXPECT_EQ(steadyStrides(up, f), expected);
    GaitSummaryParams down;
    down.terrain = Terrain::Down;
    expected = {false, false, false, false, false, false, false, false, true, false};
    EXPECT_EQ(steadyStrides(down, f), expected);
    const GaitSummary g = summariseGait(down, {f});
    EXPECT_EQ(g.feet[0].turns, 1);
    EXPECT_EQ(g.feet[0].terrain, 6);  // 0–4 up, 6 a transition
    EXPECT_EQ(g.feet[0].edges, 2);
    EXPECT_EQ(g.feet[0].used, 1);
    // A negative quantity of one sign has a CV relative to |mean|: down stairs, height −0.29 m.
    GaitSummaryParams downAll = down;
    downAll.edgeStrides = 0;
    const ParameterStats& h = summariseGait(downAll, {f}).feet[0].stats[2];
    EXPECT_NEAR(h.mean, -0.29, 1e-12);
    EXPECT_NEAR(h.cv, 0.0, 1e-9);
    EXPECT_EQ(terrainOf(QStringLiteral("up")), Terrain::Up);
    EXPECT_FALSE(terrainOf(QStringLiteral("stairs")).has_value());
}
