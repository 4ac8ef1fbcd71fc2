// Beacon selection (§3.2): every method removes a planted NLOS reading in a constructed case; the
// field-of-view rule (Eqn. 3.8) excludes the beacons behind a runner with a known heading.
#include "plugins/lps/BeaconSelection.h"
#include "plugins/lps/GainPattern.h"

#include <gtest/gtest.h>
#include <numbers>

using namespace athlos::lps;

namespace {

BeaconLayout square() {
    // Ten beacons around a 100 m × 60 m area, 4–7 m high; reference at the origin.
    BeaconLayout layout;
    const double xy[10][2] = {{-50, -30}, {0, -35},  {50, -30}, {55, 0},   {50, 30},
                              {0, 35},    {-50, 30}, {-55, 0},  {25, -33}, {-25, 33}};
    for (int i = 0; i < 10; ++i) {
        layout.ids << QString::number(i + 1);
        layout.positions.emplace_back(xy[i][0], xy[i][1], 4.0 + (i % 4));
    }
    return layout;
}

FixInput inputWithBias(const BeaconLayout& layout, const Vector3& m, int biased, double bias) {
    TdoaEpoch e{0.0, {}};
    for (int i = 0; i < layout.size(); ++i) {
        const Vector3& b = layout.positions[size_t(i)];
        const double extra = i == biased ? bias : 0.0;
        e.readings.push_back({i, ((m - b).norm() - b.norm() + extra) / kSpeedOfLight});
    }
    FixInput input;
    input.assign(e, layout, referenceDistances(layout));
    return input;
}

}  // namespace

class SelectionRemovesNlos : public ::testing::TestWithParam<BeaconSelection::Method> {};

TEST_P(SelectionRemovesNlos, PlantedNlosReadingGetsNoWeight) {
    const BeaconLayout layout = square();
    const Vector3 m(10, -5, 1.2);
    FixInput input = inputWithBias(layout, m, 3, 8.0);  // beacon 4 (east) 8 m late
    TdoaSolver solver;
    BeaconSelection::Params p;
    p.method = GetParam();
    const BeaconSelection selection(p);
    BeaconSelection::View view{m, std::numbers::pi};  // running west: the east beacon is behind the body
    const TagFix fix = selection.solve(input, solver, nullptr, &view);
    ASSERT_TRUE(fix.valid);
    EXPECT_EQ(input.weights[3], 0.0);
    EXPECT_LT((fix.position - m).norm(), 1e-4);
}

INSTANTIATE_TEST_SUITE_P(Methods, SelectionRemovesNlos,
                         ::testing::Values(BeaconSelection::Method::Irls, BeaconSelection::Method::LargestResidual,
                                           BeaconSelection::Method::FieldOfView, BeaconSelection::Method::AllSubsets,
                                           BeaconSelection::Method::BestSubset));

TEST(BeaconSelection, AllBeaconsIsBiasedByTheNlosReading) {
    const BeaconLayout layout = square();
    const Vector3 m(10, -5, 1.2);
    FixInput input = inputWithBias(layout, m, 3, 8.0);
    TdoaSolver solver;
    BeaconSelection::Params p;
    p.method = BeaconSelection::Method::All;
    const TagFix fix = BeaconSelection(p).solve(input, solver, nullptr);
    EXPECT_GT((fix.position - m).norm(), 1.0);  // the baseline the selection methods must beat
}

TEST(BeaconSelection, FieldOfViewExcludesBeaconsBehindTheRunner) {
    const BeaconLayout layout = square();
    BeaconSelection::Params p;
    p.method = BeaconSelection::Method::FieldOfView;
    p.fovRefine = false;
    const BeaconSelection selection(p);
    const Vector3 m(0, 0, 1.2);
    const BeaconSelection::View view{m, 0.0};  // facing +x
    FixInput input = inputWithBias(layout, m, -1, 0.0);
    TdoaSolver solver;
    selection.solve(input, solver, nullptr, &view);
    for (int i = 0; i < input.size(); ++i) {
        const Vector3 d = layout.positions[size_t(i)] - m;
        const double bearing = std::abs(std::atan2(d.y(), d.x()));
        if (bearing > 2.0) {
            EXPECT_EQ(input.weights[size_t(i)], 0.0) << "beacon " << i << " is behind";
        }
        if (bearing < 0.9) {
            EXPECT_EQ(input.weights[size_t(i)], 1.0) << "beacon " << i << " is in front";
        }
    }
    EXPECT_GE(input.activeCount(), 4);
}

TEST(BeaconSelection, FieldOfViewKeepsAtLeastFourBeacons) {
    const BeaconLayout layout = square();
    BeaconSelection::Params p;
    p.method = BeaconSelection::Method::FieldOfView;
    p.kappa = 0.0;  // nothing is in view
    p.fovRefine = false;
    FixInput input = inputWithBias(layout, Vector3(0, 0, 1.2), -1, 0.0);
    TdoaSolver solver;
    const BeaconSelection::View view{Vector3(0, 0, 1.2), 0.0};
    const TagFix fix = BeaconSelection(p).solve(input, solver, nullptr, &view);
    EXPECT_EQ(input.activeCount(), 4);
    EXPECT_EQ(fix.beaconsUsed, 4);
}

TEST(BeaconSelection, FieldOfViewRefinementRejectsGrossOutlierInView) {
    // The thesis' gross outliers: 20 m late, planted in turn on every beacon inside the field of view.
    const BeaconLayout layout = square();
    BeaconSelection::Params p;
    p.method = BeaconSelection::Method::FieldOfView;
    ASSERT_TRUE(p.fovRefine);
    const BeaconSelection selection(p);
    const Vector3 m(10, -5, 1.2);
    const BeaconSelection::View view{Vector3(9, -5, 1.2), 0.0};  // m̂_ini 1 m behind, facing +x
    int planted = 0;
    for (int k = 0; k < layout.size(); ++k) {
        if (selection.linkMargin(layout.positions[size_t(k)], view) <= 0.0) continue;
        ++planted;
        FixInput input = inputWithBias(layout, m, k, 20.0);
        TdoaSolver solver;
        const TagFix fix = selection.solve(input, solver, nullptr, &view);
        ASSERT_TRUE(fix.valid) << "outlier on beacon " << k;
        EXPECT_LT((fix.position - m).head<2>().norm(), 0.5) << "outlier on beacon " << k;
        EXPECT_GE(input.activeCount(), p.minBeacons);
    }
    EXPECT_GE(planted, 4);
}

TEST(BeaconSelection, FieldOfViewRefinementFallsBackOnImplausibleJump) {
    // m̂_ini far from where the in-view fix lands: the fix is re-solved with IRLS over all readings.
    const BeaconLayout layout = square();
    BeaconSelection::Params p;
    p.method = BeaconSelection::Method::FieldOfView;
    const Vector3 m(10, -5, 1.2);
    const BeaconSelection::View view{Vector3(16, -5, 1.2), 0.0};
    FixInput input = inputWithBias(layout, m, 3, 20.0);
    TdoaSolver solver;
    const TagFix fix = BeaconSelection(p).solve(input, solver, nullptr, &view);
    ASSERT_TRUE(fix.valid);
    EXPECT_LT((fix.position - m).head<2>().norm(), 0.5);
}

TEST(BeaconSelection, FreeSpaceLossFollowsEquation39) {
    const BeaconSelection selection;
    // 20 log10(100) + 20 log10(5.8e9) − 147.55
    EXPECT_NEAR(selection.freeSpaceLoss(100.0), 40.0 + 20.0 * std::log10(5.8e9) - 147.55, 1e-9);
}

TEST(GainPattern, DefaultIsAFrontLobe) {
    const GainPattern g;
    EXPECT_NEAR(g.gainDb(0.0), 0.0, 1e-9);
    EXPECT_NEAR(g.gainDb(std::numbers::pi), -30.0, 0.01);
    EXPECT_NEAR(g.gain(0.3), g.gain(-0.3), 1e-12);
    EXPECT_GT(g.gain(0.5), g.gain(1.5));
}

TEST(GainPattern, ParsedTableIsMirroredAndInterpolated) {
    auto g = GainPattern::parse("0:1, 90:0.5, 180:0.01");
    ASSERT_TRUE(g.ok()) << g.message().toStdString();
    EXPECT_NEAR(g->gain(std::numbers::pi / 4), 0.75, 1e-9);
    EXPECT_NEAR(g->gain(-std::numbers::pi / 4), 0.75, 1e-9);  // mirrored
    EXPECT_NEAR(g->gain(std::numbers::pi), 0.01, 1e-9);
    EXPECT_FALSE(GainPattern::parse("0:1, 90:-2").ok());
    EXPECT_FALSE(GainPattern::parse("nonsense").ok());
}

TEST(FixHistory, MedianOfLastFiveAndStaleness) {
    FixHistory history(5, 2.0);
    for (int k = 0; k < 7; ++k) {
        TagFix f;
        f.valid = true;
        f.t = 0.1 * k;
        f.position = Vector3(k == 5 ? 1000.0 : double(k), 0, 0);  // one wild fix
        history.push(f);
    }
    // last five x: 2, 3, 4, 1000, 6 → median 4
    ASSERT_TRUE(history.median(0.7).has_value());
    EXPECT_DOUBLE_EQ(history.median(0.7)->x(), 4.0);
    EXPECT_FALSE(history.median(5.0).has_value());
}
