// Missing IMU samples: short runs bridged by linear interpolation (values worked out by hand), ends
// held, long runs refused with their times and rows, nothing changed on refusal.
#include "plugins/events/ImuGaps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace athlos::events;

namespace {
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const std::vector<double> kT = {0.0, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06};  // 100 Hz
}  // namespace

TEST(ImuGaps, ShortRunsAreInterpolatedColumnByColumn) {
    // Two columns; samples 2 and 3 incomplete (sample 3 keeps its finite second column).
    std::vector<double> v = {0, 10, 1, 11, kNaN, kNaN, kNaN, 99, 4, 14, 5, 15, 6, 16};
    auto fill = fillShortGaps(v, 2, kT, 0.03);
    ASSERT_TRUE(fill.ok()) << fill.message().toStdString();
    EXPECT_EQ(fill->runs, 1u);
    EXPECT_EQ(fill->samples, 2u);
    EXPECT_NEAR(fill->longest, 0.03, 1e-12);  // from sample 1 to sample 4
    // Between (0.01, 1 | 11) and (0.04, 4 | 14): at 0.02 → 2 | 12, at 0.03 → 3 | (99 kept).
    EXPECT_NEAR(v[4], 2.0, 1e-12);
    EXPECT_NEAR(v[5], 12.0, 1e-12);
    EXPECT_NEAR(v[6], 3.0, 1e-12);
    EXPECT_EQ(v[7], 99.0);
}

TEST(ImuGaps, RunsAtTheEndsHoldTheNearestSample) {
    std::vector<double> v = {kNaN, 1, 2, 3, 4, 5, std::numeric_limits<double>::infinity()};
    auto fill = fillShortGaps(v, 1, kT, 0.02);
    ASSERT_TRUE(fill.ok()) << fill.message().toStdString();
    EXPECT_EQ(fill->runs, 2u);
    EXPECT_EQ(v.front(), 1.0);
    EXPECT_EQ(v.back(), 5.0);
}

TEST(ImuGaps, LongRunsAreRefusedWithTheirTimesAndNothingChanges) {
    std::vector<double> v = {0, 1, kNaN, kNaN, kNaN, 5, 6};
    const std::vector<double> before = v;
    auto fill = fillShortGaps(v, 1, kT, 0.03);  // 0.01 … 0.05 s is 0.04 s
    ASSERT_FALSE(fill.ok());
    EXPECT_TRUE(fill.message().contains(QStringLiteral("from t = 0.010 s to 0.050 s"))) << fill.message().toStdString();
    EXPECT_TRUE(fill.message().contains(QStringLiteral("rows 3 to 5"))) << fill.message().toStdString();
    EXPECT_TRUE(fill.message().contains(QStringLiteral("max_gap = 0.03 s"))) << fill.message().toStdString();
    for (std::size_t i = 0; i < v.size(); ++i)
        EXPECT_TRUE(v[i] == before[i] || (std::isnan(v[i]) && std::isnan(before[i]))) << i;
    std::vector<double> none(7, kNaN);
    EXPECT_FALSE(fillShortGaps(none, 1, kT, 1.0).ok());
    std::vector<double> complete = {0, 1, 2, 3, 4, 5, 6};
    auto nothing = fillShortGaps(complete, 1, kT, 0.0);
    ASSERT_TRUE(nothing.ok());
    EXPECT_EQ(nothing->runs, 0u);
}
