// core/math/Statistics.h: median and upper median (odd and even sizes, empty input, order of the
// input, duplicates).
#include "core/math/Statistics.h"

#include <gtest/gtest.h>
#include <cmath>

using athlos::math::median;
using athlos::math::upperMedian;

TEST(Statistics, MedianOfOddSizeIsTheMiddleValue) {
    EXPECT_EQ(median({7.0}), 7.0);
    EXPECT_EQ(median({3, 1, 2}), 2.0);
    EXPECT_EQ(median({5, -1, 4, 100, 0}), 4.0);
    EXPECT_EQ(upperMedian({3, 1, 2}), 2.0);
}

TEST(Statistics, MedianOfEvenSizeAveragesTheMiddlePair) {
    EXPECT_EQ(median({4, 1, 3, 2}), 2.5);
    EXPECT_EQ(median({1, 2}), 1.5);
    EXPECT_EQ(median({-1, -1, 5, 5}), 2.0);
    // The upper median takes the higher of the two middle values (always a member of the set).
    EXPECT_EQ(upperMedian({4, 1, 3, 2}), 3.0);
    EXPECT_EQ(upperMedian({1, 2}), 2.0);
}

TEST(Statistics, MedianOfEmptySetIsNaN) {
    EXPECT_TRUE(std::isnan(median({})));
    EXPECT_TRUE(std::isnan(upperMedian({})));
}

TEST(Statistics, MedianIgnoresOrderAndOutliers) {
    EXPECT_EQ(median({1, 2, 3, 4, 1e9}), 3.0);
    EXPECT_EQ(median({1e9, 4, 3, 2, 1}), 3.0);
    EXPECT_EQ(median({2, 2, 2, 9}), 2.0);
    EXPECT_EQ(median({-3.5, -3.5}), -3.5);
}
