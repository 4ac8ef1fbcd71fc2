// The window statistics against hand-computed values.
#include "plugins/activity/FeatureMath.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <vector>

using namespace athlos::activity;

TEST(FeatureMathTest, MomentsOfASmallSample) {
    // x = 1, 2, 3, 10: mean 4, deviations −3, −2, −1, 6 → m2 = 50/4 = 12.5, m3 = 180/4 = 45,
    // m4 = 1394/4 = 348.5; skewness 45 / 12.5^1.5 = 1.018233, excess kurtosis 348.5 / 156.25 − 3 = −0.7696.
    const double x[] = {1, 2, 3, 10};
    const Moments m = moments(x, 4);
    EXPECT_DOUBLE_EQ(m.mean, 4.0);
    EXPECT_NEAR(m.sd, std::sqrt(12.5), 1e-12);
    EXPECT_NEAR(m.skewness, 45.0 / std::pow(12.5, 1.5), 1e-12);
    EXPECT_NEAR(m.skewness, 1.018233, 1e-6);
    EXPECT_NEAR(m.kurtosis, -0.7696, 1e-12);
    EXPECT_DOUBLE_EQ(m.energy, (1 + 4 + 9 + 100) / 4.0);
    double scratch[4];
    EXPECT_DOUBLE_EQ(median(x, 4, scratch), 2.5);
    const double odd[] = {5, -1, 3};
    EXPECT_DOUBLE_EQ(median(odd, 3, scratch), 3.0);
}

TEST(FeatureMathTest, ConstantSignalHasNoShape) {
    const std::vector<double> x(50, 9.81);
    const Moments m = moments(x.data(), x.size());
    EXPECT_NEAR(m.sd, 0.0, 1e-12);
    EXPECT_EQ(m.skewness, 0.0);
    EXPECT_EQ(m.kurtosis, 0.0);
    EXPECT_EQ(correlation(x.data(), x.data(), x.size()), 0.0);
    EXPECT_EQ(dominant(x.data(), x.size(), 50.0).amplitude, 0.0);
}

TEST(FeatureMathTest, ExtremesAndTheirPositions) {
    const double x[] = {0, 4, -2, 1, 3};
    const Extremes e = extremes(x, 5);
    EXPECT_EQ(e.max, 4.0);
    EXPECT_EQ(e.min, -2.0);
    EXPECT_DOUBLE_EQ(e.argmax, 0.25);  // index 1 of 0..4
    EXPECT_DOUBLE_EQ(e.argmin, 0.5);
}

TEST(FeatureMathTest, DominantFrequencyOfAPureSine) {
    // 150 samples at 50 Hz (an efficient DFT length, so no padding): 2 Hz falls on bin 6 exactly.
    const double rate = 50.0;
    std::vector<double> x(150);
    for (std::size_t i = 0; i < x.size(); ++i)
        x[i] = 1.5 + 3.0 * std::sin(2 * std::numbers::pi * 2.0 * double(i) / rate);
    const Dominant d = dominant(x.data(), x.size(), rate);
    EXPECT_NEAR(d.frequency, 2.0, 1e-9);
    EXPECT_NEAR(d.amplitude, 3.0, 1e-9);
    // Between bins (2.15 Hz = bin 6.45) the ratio interpolation lands within 3 % of a bin
    // (exact but for the leakage of the negative frequency).
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::cos(2 * std::numbers::pi * 2.15 * double(i) / rate);
    EXPECT_NEAR(dominant(x.data(), x.size(), rate).frequency, 2.15, 0.03 * rate / 150.0);
}

TEST(FeatureMathTest, Correlation) {
    const double x[] = {1, 2, 3};
    const double y[] = {1, 3, 2};
    // Deviations (−1, 0, 1) and (−1, 1, 0): Σxy = 1, Σx² = Σy² = 2 → r = 0.5.
    EXPECT_NEAR(correlation(x, y, 3), 0.5, 1e-12);
    const double line[] = {3, 5, 7};
    EXPECT_NEAR(correlation(x, line, 3), 1.0, 1e-12);
    const double negative[] = {-1, -2, -3};
    EXPECT_NEAR(correlation(x, negative, 3), -1.0, 1e-12);
}

TEST(FeatureMathTest, QuantilesAndBandShares) {
    // 0, 1, …, 20 shuffled: ⌊q·20⌋ → p10 = 2, p25 = 5, p50 = 10, p75 = 15, p90 = 18.
    const double x[] = {7, 19, 0, 12, 3, 15, 9, 20, 1, 11, 5, 17, 2, 14, 8, 18, 4, 13, 6, 16, 10};
    double scratch[21];
    const Quantiles q = quantiles(x, 21, scratch);
    EXPECT_EQ(q.p10, 2.0);
    EXPECT_EQ(q.p25, 5.0);
    EXPECT_EQ(q.p50, 10.0);
    EXPECT_EQ(q.p75, 15.0);
    EXPECT_EQ(q.p90, 18.0);
    // Spectrum of length 100 at 50 Hz (bins 0.5 Hz apart): power 1 at 2 Hz (bin 4), 3 at 5 Hz (bin 10).
    std::vector<double> magnitude(51, 0.0);
    magnitude[4] = 1.0;
    magnitude[10] = std::sqrt(3.0);
    const double edges[] = {0.3, 1.0, 3.0, 6.0, 12.0};
    double shares[4];
    bandShares(magnitude.data(), magnitude.size(), 100, 50.0, edges, 4, shares);
    EXPECT_DOUBLE_EQ(shares[0], 0.0);
    EXPECT_DOUBLE_EQ(shares[1], 0.25);
    EXPECT_DOUBLE_EQ(shares[2], 0.75);
    EXPECT_DOUBLE_EQ(shares[3], 0.0);
}

TEST(FeatureMathTest, QuantilesOfShortWindows) {
    const double x[] = {3, 1, 2};
    double scratch[3];
    const Quantiles q = quantiles(x, 3, scratch);  // ⌊q·2⌋: p10 = p25 = 1, p75 = p90 = 2 (indices 0 and 1)
    EXPECT_EQ(q.p10, 1.0);
    EXPECT_EQ(q.p25, 1.0);
    EXPECT_EQ(q.p50, 2.0);
    EXPECT_EQ(q.p75, 2.0);
    EXPECT_EQ(q.p90, 2.0);
}
