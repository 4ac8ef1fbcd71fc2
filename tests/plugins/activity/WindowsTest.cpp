// Sliding windows, their labels from annotation overlap, and intervals from classified windows.
#include "plugins/activity/ActivityModel.h"
#include "plugins/activity/Windows.h"

#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::activity;

namespace {
StreamData ramp(std::size_t rows, double rate) {
    StreamData d(rows, 1);
    for (std::size_t i = 0; i < rows; ++i) d.t[i] = double(i) / rate;
    return d;
}
}  // namespace

TEST(WindowsTest, SlidingWindowsCoverTheStream) {
    const StreamData d = ramp(1001, 100.0);  // 0 .. 10 s
    const auto w = slidingWindows(d, 3.0, 1.5);
    // Starts 0, 1.5, …, 6.0 (6.0 + 3 = 9 ≤ 10; 7.5 + 3 > 10): 5 windows of 300 samples.
    ASSERT_EQ(w.size(), 5u);
    EXPECT_DOUBLE_EQ(w[0].tStart, 0.0);
    EXPECT_DOUBLE_EQ(w[4].tStart, 6.0);
    EXPECT_EQ(w[0].end - w[0].begin, 300u);
    EXPECT_EQ(w[1].begin, 150u);
    // Shorter than one window: one window over everything.
    const auto short_ = slidingWindows(ramp(100, 100.0), 3.0, 1.5);
    ASSERT_EQ(short_.size(), 1u);
    EXPECT_EQ(short_[0].end, 100u);
}

TEST(WindowsTest, LabelByLargestOverlap) {
    const Window w{10.0, 13.0, 0, 0};
    Annotations a(2);
    a[0].label = QStringLiteral("walk");
    a[0].tEnd = 11.0;
    a[1].label = QStringLiteral("run");
    a[1].tStart = 11.0;
    a[1].tEnd = 20.0;
    EXPECT_EQ(windowLabel(w, a, {}, 0.5), QStringLiteral("run"));  // 2 s of run, 1 s of walk
    EXPECT_EQ(windowLabel(w, a, {QStringLiteral("walk")}, 0.3), QStringLiteral("walk"));
    EXPECT_EQ(windowLabel(w, a, {QStringLiteral("walk")}, 0.5), QString());   // 1/3 < 0.5
    EXPECT_EQ(windowLabel(Window{30.0, 33.0, 0, 0}, a, {}, 0.0), QString());  // unannotated
}

TEST(WindowsTest, IntervalsMergeAndCoverTheSpan) {
    const std::vector<double> centres = {1.5, 3.0, 4.5, 6.0, 7.5};
    // Classes a, a, b, b, a with certain probabilities.
    cv::Mat p = (cv::Mat_<float>(5, 2) << 1, 0, 0.8f, 0.2f, 0, 1, 0.1f, 0.9f, 1, 0);
    const auto out = intervalsFromWindows(centres, p, {QStringLiteral("a"), QStringLiteral("b")}, 0.0, 9.2, 0);
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[0].label, QStringLiteral("a"));
    EXPECT_DOUBLE_EQ(out[0].tStart, 0.0);  // first window extends to the start
    EXPECT_DOUBLE_EQ(out[0].tEnd, 3.75);   // half-way between centres 3.0 and 4.5
    EXPECT_NEAR(out[0].confidence, 0.9, 1e-6);
    EXPECT_EQ(out[1].label, QStringLiteral("b"));
    EXPECT_DOUBLE_EQ(out[1].tStart, 3.75);
    EXPECT_DOUBLE_EQ(out[1].tEnd, 6.75);
    EXPECT_DOUBLE_EQ(out[2].tEnd, 9.2);  // last window extends to the end
    // Smoothing over one neighbour each side: window 4 (b 0.9) between b 1.0 and a 1.0 stays b,
    // window 5 (a) averaged with window 4 → a 0.55: still a.
    const auto smooth = intervalsFromWindows(centres, p, {QStringLiteral("a"), QStringLiteral("b")}, 0.0, 9.2, 1);
    ASSERT_EQ(smooth.size(), 3u);
    // A single deviating window is absorbed by smoothing.
    cv::Mat q = (cv::Mat_<float>(5, 2) << 1, 0, 1, 0, 0.4f, 0.6f, 1, 0, 1, 0);
    EXPECT_EQ(intervalsFromWindows(centres, q, {QStringLiteral("a"), QStringLiteral("b")}, 0.0, 9.2, 0).size(), 3u);
    EXPECT_EQ(intervalsFromWindows(centres, q, {QStringLiteral("a"), QStringLiteral("b")}, 0.0, 9.2, 1).size(), 1u);
}
