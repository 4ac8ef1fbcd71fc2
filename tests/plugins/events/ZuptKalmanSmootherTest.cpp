// ZuptKalmanSmoother on the foot-motion simulator: the per-sample and batch interfaces agree, the
// smoothed velocity is zero where zero velocity was measured, a still foot stays put, and the
// stance detector keeps the mid-stances. Stride lengths per scenario against the truth, beside the
// instant method: GaitParametersSimulationTest.
#include "plugins/events/ZuptKalmanSmoother.h"

#include "plugins/events/FootMotionSimulator.h"
#include "plugins/events/StrideSegmenter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace athlos::events;

namespace {

SimConfig walk() {
    SimConfig c;
    c.gyrBias.setZero();  // gait-parameters removes it first (StaticGyroBias); the filter has no bias state
    for (int i = 0; i < 6; ++i) c.strides.push_back(SimStride{});
    return c;
}

std::vector<bool> stanceOf(const SimRecording& rec) {
    return detectStance(rec.t.data(), rec.values.data() + 3, rec.t.size(), 6, 0.15, 0.26, {});
}

// Gravity as the accelerometer reads it (with its bias), as smoothStrides takes it.
double gravity(const SimRecording& rec) {
    return meanAccelerometer(rec.t.data(), rec.values.data(), 6, rec.t.size(), 0, 1.0).norm();
}

Eigen::Quaterniond levelled(const SimRecording& rec) {
    return levelledOrientation(meanAccelerometer(rec.t.data(), rec.values.data(), 6, rec.t.size(), 0, 0.15), 0.0);
}

}  // namespace

TEST(ZuptKalmanSmoother, PerSampleAndBatchAgree) {
    const SimRecording rec = simulateFoot(walk());
    const std::vector<bool> stance = stanceOf(rec);
    const ZuptKalmanParams params;
    ZuptKalmanSmoother smoother(params, levelled(rec), 9.81);
    for (std::size_t k = 0; k < rec.t.size(); ++k)
        smoother.addSample(rec.t[k], Eigen::Vector3d(&rec.values[6 * k]), Eigen::Vector3d(&rec.values[6 * k + 3]),
                           stance[k]);
    EXPECT_EQ(smoother.samples(), rec.t.size());
    const auto a = smoother.smooth();
    const auto b = ZuptKalmanSmoother::smooth(params, levelled(rec), 9.81, rec.t.data(), rec.values.data(), 6,
                                              rec.values.data() + 3, 6, stance);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) ASSERT_EQ(a[k].position, b[k].position) << k;
    // The last sample has nothing after it: smoothed = filtered.
    EXPECT_EQ(a.back().position, smoother.filtered().position);
}

// The batch keeps the gains of one block at a time and forms them again from a copy of the filter:
// over several blocks (and a last block of a few samples) it must give what the per-sample interface,
// which keeps every gain, gives.
TEST(ZuptKalmanSmoother, BatchInBlocksEqualsPerSample) {
    SimConfig c = walk();
    for (int i = 0; i < 120; ++i) c.strides.push_back(SimStride{});
    const SimRecording rec = simulateFoot(c);
    const std::vector<bool> stance = stanceOf(rec);
    ASSERT_GT(rec.t.size(), 3 * ZuptKalmanSmoother::kBlock);
    const ZuptKalmanParams params;
    // Whole blocks plus 1, plus 2 and plus a few hundred samples: the edge cases of the last block.
    for (const std::size_t n : {2 * ZuptKalmanSmoother::kBlock + 1, 2 * ZuptKalmanSmoother::kBlock + 2, rec.t.size()}) {
        ZuptKalmanSmoother smoother(params, levelled(rec), 9.81);
        for (std::size_t k = 0; k < n; ++k)
            smoother.addSample(rec.t[k], Eigen::Vector3d(&rec.values[6 * k]), Eigen::Vector3d(&rec.values[6 * k + 3]),
                               stance[k]);
        const auto a = smoother.smooth();
        const std::vector<bool> first(stance.begin(), stance.begin() + static_cast<std::ptrdiff_t>(n));
        const auto b = ZuptKalmanSmoother::smooth(params, levelled(rec), 9.81, rec.t.data(), rec.values.data(), 6,
                                                  rec.values.data() + 3, 6, first);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t k = 0; k < n; ++k) {
            ASSERT_LT((a[k].position - b[k].position).norm(), 1e-12) << n << ' ' << k;
            ASSERT_LT((a[k].velocity - b[k].velocity).norm(), 1e-12) << n << ' ' << k;
            ASSERT_LT(a[k].orientation.angularDistance(b[k].orientation), 1e-12) << n << ' ' << k;
        }
    }
}

// The batch reports its progress (rising, up to 1) and stops when told to: empty states, and no
// strides from smoothStrides (the processor then returns "cancelled" and stores nothing).
TEST(ZuptKalmanSmoother, BatchReportsProgressAndCancels) {
    SimConfig c = walk();
    for (int i = 0; i < 200; ++i) c.strides.push_back(SimStride{});  // > 8192 samples: several reports
    const SimRecording rec = simulateFoot(c);
    const std::vector<bool> stance = stanceOf(rec);
    const ZuptKalmanParams params;
    std::vector<double> seen;
    const auto all = ZuptKalmanSmoother::smooth(params, levelled(rec), 9.81, rec.t.data(), rec.values.data(), 6,
                                                rec.values.data() + 3, 6, stance, [&](double f) {
                                                    seen.push_back(f);
                                                    return true;
                                                });
    EXPECT_EQ(all.size(), rec.t.size());
    ASSERT_GE(seen.size(), 4u);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    EXPECT_EQ(seen.back(), 1.0);
    int calls = 0;
    const auto none = ZuptKalmanSmoother::smooth(params, levelled(rec), 9.81, rec.t.data(), rec.values.data(), 6,
                                                 rec.values.data() + 3, 6, stance, [&](double) { return ++calls < 2; });
    EXPECT_TRUE(none.empty());
    EXPECT_EQ(calls, 2);  // stopped at the second report, not at the end
    const StrideSegmentation segmentation = segmentStrides({}, rec.t.data(), rec.values.data() + 3, rec.t.size(), 6);
    ASSERT_GT(segmentation.strides.size(), 100u);
    const FootTrajectory cancelled =
        smoothStrides({}, segmentation.strides, rec.t.data(), rec.values.data(), 6, rec.values.data() + 3, 6,
                      rec.t.size(), nullptr, [](double) { return false; });
    EXPECT_TRUE(cancelled.strides.empty());
    EXPECT_TRUE(cancelled.position.empty());
}

TEST(ZuptKalmanSmoother, VelocityIsZeroInStanceAndTheSwingsCoverTheStrides) {
    const SimRecording rec = simulateFoot(walk());
    const std::vector<bool> stance = stanceOf(rec);
    const auto states = ZuptKalmanSmoother::smooth({}, levelled(rec), gravity(rec), rec.t.data(), rec.values.data(), 6,
                                                   rec.values.data() + 3, 6, stance);
    double worst = 0.0;
    std::size_t stanceSamples = 0;
    for (std::size_t k = 0; k < states.size(); ++k)
        if (stance[k]) {
            worst = std::max(worst, states[k].velocity.norm());
            ++stanceSamples;
        }
    EXPECT_GT(stanceSamples, rec.t.size() / 3);
    EXPECT_LT(worst, 0.02);
    // Six strides of 1.4 m straight ahead (x): the end point within 1 %.
    EXPECT_NEAR(states.back().position.head<2>().norm(), 6 * 1.4, 0.084) << states.back().position.transpose();
    EXPECT_NEAR(states.back().position.z(), 0.0, 0.06);  // under 1 cm per stride (accelerometer bias)
}

TEST(ZuptKalmanSmoother, AStillFootStaysPut) {
    SimConfig c;  // no strides: 4 s of standing with noise and biases
    const SimRecording rec = simulateFoot(c);
    const std::vector<bool> stance(rec.t.size(), true);
    const auto states = ZuptKalmanSmoother::smooth({}, levelled(rec), 9.81, rec.t.data(), rec.values.data(), 6,
                                                   rec.values.data() + 3, 6, stance);
    // A still foot has no dynamics, so only the noise floor acc_noise drives its velocity noise:
    // with a floor of 0.01 m/s² (an IMU's white noise alone) the simulated accelerometer bias
    // would move it by 23 mm in 4 s; 0.05 m/s² keeps it at 2.3 mm.
    double worst = 0.0;
    for (const auto& s : states) worst = std::max(worst, s.position.norm());
    std::printf("[ figures  ] still foot, 4 s: largest displacement %.4f m\n", worst);
    EXPECT_LT(worst, 0.005);
}

TEST(ZuptKalmanSmoother, StanceDetectorKeepsTheMidStances) {
    // A foot that is never still (1 rad/s): nothing under the threshold but the given mid-stances
    // and their half window on each side.
    std::vector<double> t(200), gyr(600, 0.0);
    for (std::size_t k = 0; k < t.size(); ++k) {
        t[k] = 0.01 * double(k);
        gyr[3 * k + 1] = 1.0;
    }
    const std::vector<bool> stance = detectStance(t.data(), gyr.data(), t.size(), 3, 0.105, 0.26, {50, 199});
    std::size_t count = 0;
    for (bool s : stance) count += s;
    EXPECT_EQ(count, 11u + 6u);  // 45…55 and 194…199
    EXPECT_TRUE(stance[45] && stance[55] && !stance[44] && !stance[56] && stance[194] && !stance[193]);
    // Under the threshold: everything is stance.
    const std::vector<bool> all = detectStance(t.data(), gyr.data(), t.size(), 3, 0.105, 1.5, {});
    for (bool s : all) EXPECT_TRUE(s);
}

TEST(ZuptKalmanSmoother, StanceAroundAMidStanceEndsWhereTheFootTurnsFaster) {
    // A short stance (1 rad/s on samples 48…52, 3 rad/s around it, as a running foot rolls): the
    // 11-sample average is 23/11 rad/s from 47 to 53, 25/11 at 46 and 54, 27/11 at 45 and 55. Only
    // the samples within the threshold (0.26) of the mid-stance's average are forced stance: 46…54,
    // not the whole half window 45…55.
    std::vector<double> t(100), gyr(300, 0.0);
    for (std::size_t k = 0; k < t.size(); ++k) {
        t[k] = 0.01 * double(k);
        gyr[3 * k + 1] = k >= 48 && k <= 52 ? 1.0 : 3.0;
    }
    const std::vector<bool> stance = detectStance(t.data(), gyr.data(), t.size(), 3, 0.105, 0.26, {50});
    for (std::size_t k = 0; k < t.size(); ++k) EXPECT_EQ(stance[k], k >= 46 && k <= 54) << k;
}
