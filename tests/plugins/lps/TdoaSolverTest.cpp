// TDoA fix (Eqn. 2.5) and residuals (Eqn. 3.1): exact solutions on noise-free data, convergence
// from a poor start, the closed-form start, the robust-loss backend.
#include "plugins/lps/TdoaSolver.h"

#include <gtest/gtest.h>
#include <numbers>

using namespace athlos::lps;

namespace {

BeaconLayout ring(int n, double radius = 60.0) {
    BeaconLayout layout;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n + 0.1 * i;
        layout.ids << QString::number(i + 1);
        layout.positions.emplace_back(radius * std::cos(a) * 1.4, radius * std::sin(a),
                                      3.0 + 5.0 * ((i * 37) % 11) / 10.0);
    }
    return layout;
}

// Eqn. 3.5 without noise.
TdoaEpoch epochAt(const BeaconLayout& layout, const Vector3& m, double tOff, double t = 0.0) {
    TdoaEpoch e{t, {}};
    for (int i = 0; i < layout.size(); ++i) {
        const Vector3& b = layout.positions[size_t(i)];
        e.readings.push_back({i, ((m - b).norm() - (layout.reference - b).norm()) / kSpeedOfLight + tOff});
    }
    return e;
}

}  // namespace

TEST(TdoaSolver, NoiseFreePlanarFixIsExact) {
    const BeaconLayout layout = ring(12);
    const auto refDist = referenceDistances(layout);
    TdoaSolver solver;  // planar at 1.2 m
    FixInput input;
    for (const Vector3& m : {Vector3(10, -20, 1.2), Vector3(-70, 15, 1.2), Vector3(0.5, 0.5, 1.2)}) {
        input.assign(epochAt(layout, m, 7e-6), layout, refDist);
        const TagFix fix = solver.solve(input);
        ASSERT_TRUE(fix.valid);
        EXPECT_LT((fix.position - m).norm(), 1e-6);
        EXPECT_NEAR(-fix.offset / kSpeedOfLight, 7e-6, 1e-14);  // o = −c·t_off (Eqn. 3.5 vs 3.1)
        EXPECT_LT(fix.rmsResidual, 1e-6);
        EXPECT_EQ(fix.beaconsUsed, 12);
    }
}

TEST(TdoaSolver, NoiseFreeSpatialFixIsExact) {
    BeaconLayout layout = ring(8, 20.0);
    for (int i = 0; i < layout.size(); ++i) layout.positions[size_t(i)].z() = i % 2 ? 1.0 : 15.0;  // good VDOP
    TdoaSolver::Params p;
    p.geometry = TdoaSolver::Geometry::Spatial;
    TdoaSolver solver(p);
    FixInput input;
    const Vector3 m(3, -4, 2.5);
    input.assign(epochAt(layout, m, -3e-6), layout, referenceDistances(layout));
    const TagFix fix = solver.solve(input);
    ASSERT_TRUE(fix.valid);
    EXPECT_LT((fix.position - m).norm(), 1e-6);
}

TEST(TdoaSolver, ConvergesFromAPoorStart) {
    const BeaconLayout layout = ring(12);
    FixInput input;
    const Vector3 m(40, 25, 1.2);
    input.assign(epochAt(layout, m, 7e-6), layout, referenceDistances(layout));
    TdoaSolver solver;
    TagFix start;
    start.valid = true;
    start.position = Vector3(-60, -40, 1.2);  // 120 m off, offset 2 km off
    start.offset = -2000.0;
    const TagFix fix = solver.solve(input, &start);
    ASSERT_TRUE(fix.valid);
    EXPECT_LT((fix.position - m).norm(), 1e-6);
}

TEST(TdoaSolver, ClosedFormStartIsExactWithoutNoise) {
    const BeaconLayout layout = ring(6);
    FixInput input;
    const Vector3 m(-12, 8, 1.2);
    input.assign(epochAt(layout, m, 1e-6), layout, referenceDistances(layout));
    const auto start = TdoaSolver().linearStart(input);
    ASSERT_TRUE(start.has_value());
    EXPECT_LT((start->position - m).norm(), 1e-6);
    EXPECT_NEAR(start->offset, -kSpeedOfLight * 1e-6, 1e-6);
}

TEST(TdoaSolver, ResidualFollowsEquation31) {
    // One beacon at (3, 4, 0), reference at the origin, tag at (0, 0, 0): |m − b| = 5, |r − b| = 5,
    // c·Δt = 2 m, o = 0.5 m → e = 5 − 5 − 2 − 0.5 = −2.5 m.
    BeaconLayout layout;
    layout.ids << "1";
    layout.positions.emplace_back(3, 4, 0);
    TdoaEpoch epoch{0.0, {{0, 2.0 / kSpeedOfLight}}};
    FixInput input;
    input.assign(epoch, layout, referenceDistances(layout));
    std::vector<double> e;
    TdoaSolver::residuals(input, Vector3::Zero(), 0.5, e);
    ASSERT_EQ(e.size(), 1u);
    EXPECT_NEAR(e[0], -2.5, 1e-12);
}

TEST(TdoaSolver, WeightedRmsIgnoresExcludedReadings) {
    FixInput input;
    input.ranges = {0, 0, 0};
    input.weights = {1, 1, 0};
    EXPECT_NEAR(TdoaSolver::weightedRms(input, {3, 4, 100}), std::sqrt(12.5), 1e-12);
}

TEST(TdoaSolver, RobustLossDownweightsAnOutlier) {
    const BeaconLayout layout = ring(12);
    FixInput input;
    const Vector3 m(5, 5, 1.2);
    TdoaEpoch epoch = epochAt(layout, m, 0.0);
    epoch.readings[3].dt += 15.0 / kSpeedOfLight;  // 15 m late detection
    input.assign(epoch, layout, referenceDistances(layout));
    const double plain = (TdoaSolver().solve(input).position - m).norm();
    TdoaSolver::Params p;
    p.loss = TdoaSolver::Loss::Cauchy;
    p.lossScale = 0.2;
    const TagFix robust = TdoaSolver(p).solve(input);
    EXPECT_GT(plain, 0.5);
    EXPECT_LT((robust.position - m).norm(), 0.1 * plain);
}

TEST(TdoaSolver, TooFewBeaconsGiveAnInvalidFix) {
    const BeaconLayout layout = ring(12);
    FixInput input;
    input.assign(epochAt(layout, Vector3(1, 1, 1.2), 0.0), layout, referenceDistances(layout));
    input.weights.assign(12, 0.0);
    input.weights[0] = input.weights[1] = 1.0;
    EXPECT_FALSE(TdoaSolver().solve(input).valid);
}
