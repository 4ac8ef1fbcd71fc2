// Gate detection (eq. 9.1), the sacrum→magnet geometry (eqs. 9.2–9.5), gate matching, and the
// anchor smoother on simulated giant-slalom runs against their truth (Fasel thesis ch. 9: position
// 0.238 m, speed −0.004 ± 0.204 m/s vs dGNSS; judged: RMSE ≤ 0.25 m, speed SD ≤ 0.2 m/s).
#include "plugins/positioning/AnchorSmoother.h"
#include "core/math/Angles.h"
#include "plugins/positioning/GateAveraging.h"
#include "plugins/positioning/GateDetector.h"
#include "plugins/positioning/RestAlignedStrapdown.h"
#include "tools/eval/AnchorEvaluation.h"

#include <cmath>
#include <complex>
#include <gtest/gtest.h>
#include <random>

using namespace athlos;
using namespace athlos::positioning;
using math::Vec3;

TEST(GateDetector, DistanceFromFieldIsEquation91) {
    EXPECT_NEAR(GateDetector::distanceFromField(0.0), 1.0, 1e-12);  // magnet field vanishes: 1 m
    EXPECT_NEAR(GateDetector::distanceFromField(0.5), 0.8, 1e-12);  // the thesis's ≈ 0.8 m detection limit
    EXPECT_NEAR(GateDetector::distanceFromField(1.0), 0.6, 1e-12);
    EXPECT_NEAR(GateDetector::distanceFromField(1.61), 1.0 - 0.4 * 1.61, 1e-12);
    EXPECT_NEAR(GateDetector::distanceFromField(3.0), 0.452 - 0.062 * 3.0, 1e-12);  // second branch
    // The simulator inverts the same relation.
    for (double r : {0.3, 0.45, 0.6, 0.75, 0.9})
        EXPECT_NEAR(GateDetector::distanceFromField(GateRunSimulator::magnetExcess(r)), r, 0.01) << r;
}

TEST(GateDetector, FindsPeaksWithInterpolatedTimeAndSide) {
    // Two Gaussian bumps at 1.2345 s (left turn) and 3.0 s (right turn), 100 Hz.
    std::vector<double> t, e, yaw;
    for (int k = 0; k < 500; ++k) {
        const double tk = 0.01 * k;
        t.push_back(tk);
        e.push_back(1.1 * std::exp(-std::pow((tk - 1.2345) / 0.02, 2)) +
                    0.7 * std::exp(-std::pow((tk - 3.0) / 0.02, 2)));
        yaw.push_back(tk < 2.0 ? 0.8 : -0.8);
    }
    const auto crossings = GateDetector({0.3, 0.4}).detect(t, e, yaw);
    ASSERT_EQ(crossings.size(), 2u);
    EXPECT_NEAR(crossings[0].t, 1.2345, 0.002);
    EXPECT_NEAR(crossings[0].distance, GateDetector::distanceFromField(1.1), 0.02);
    EXPECT_EQ(crossings[0].side, 1);
    EXPECT_EQ(crossings[1].side, -1);
    EXPECT_NEAR(crossings[1].t, 3.0, 0.002);
}

TEST(AnchorSmoother, SacrumToMagnetFollowsTheTriangle) {
    // Skiing along +x at 20 m/s, gate on the left, |r| = 0.8 m, sacrum 0.5 m above the snow:
    // d = (0, 0, −0.5), x = √(0.8² − 0.5²) to the left (+y).
    const Vec3 r = AnchorSmoother::sacrumToMagnet(Vec3(20, 0, 0), 0.8, +1, 0.5);
    EXPECT_NEAR(r.x(), 0.0, 1e-12);
    EXPECT_NEAR(r.y(), std::sqrt(0.64 - 0.25), 1e-12);
    EXPECT_NEAR(r.z(), -0.5, 1e-12);
    EXPECT_NEAR(AnchorSmoother::sacrumToMagnet(Vec3(20, 0, 0), 0.8, -1, 0.5).y(), -r.y(), 1e-12);
    // Downhill: d stays normal to the velocity (the snow normal when skiing along the fall line).
    const Vec3 v(10, 0, -5);
    EXPECT_NEAR(AnchorSmoother::sacrumToMagnet(v, 0.7, 1, 0.5).dot(v), 0.0, 1e-9);
}

TEST(AnchorSmoother, MatchesGatesInOrderDespiteDriftAndMisses) {
    std::vector<Gate> gates;
    for (int n = 0; n < 10; ++n) gates.push_back({QString::number(n), Vec3(27.0 * n, (n % 2 ? 5.0 : -5.0), -8.0 * n)});
    // Crossings of gates 0, 1, 2, 4, 5, …, 9 (gate 3 missed) in a frame 40 m off and drifting 0.5 m per gate.
    std::vector<Vec3> est;
    std::vector<int> truth;
    for (int n = 0; n < 10; ++n) {
        if (n == 3) continue;
        est.push_back(gates[n].position + Vec3(40.0 + 0.5 * n, -30.0, 3.0));
        truth.push_back(n);
    }
    const auto match = AnchorSmoother::matchGates(est, gates, 8.0, true);
    ASSERT_EQ(match.size(), truth.size());
    for (std::size_t m = 0; m < truth.size(); ++m) EXPECT_EQ(match[m], truth[m]) << m;
}

TEST(RestAlignedStrapdown, RemovesTiltDriftBetweenRests) {
    // Sensor at rest, then turning about z at 0.1 rad/s for 10 s, then at rest; the gyroscope has a
    // bias of 0.5 °/s on x (the start rest calibrates it) plus 0.005 rad/s while moving (what no rest
    // sees): the finish rest levels it.
    const double dt = 0.01;
    std::vector<double> t;
    std::vector<Vec3> gyr, acc;
    std::vector<math::Quat> stream;
    std::vector<unsigned char> startStill, finishStill;
    const Vec3 bias(0.5 * math::kDeg, 0.0, 0.0);
    for (int k = 0; k < 1600; ++k) {
        const double tk = dt * k;
        const bool moving = tk >= 3.0 && tk < 13.0;
        t.push_back(tk);
        gyr.push_back(Vec3(0, 0, moving ? 0.1 : 0.0) + bias + (moving ? Vec3(0.005, 0, 0) : Vec3::Zero()));
        acc.push_back(Vec3(0, 0, 9.81));  // level throughout (rotation about the vertical only)
        stream.push_back(math::Quat::Identity());
        startStill.push_back(tk < 3.0);
        finishStill.push_back(tk >= 13.0);
    }
    const auto q = RestAlignedStrapdown::compute(t, gyr, acc, stream, startStill, finishStill);
    ASSERT_TRUE(q.ok()) << q.message().toStdString();
    EXPECT_LT(math::inclinationAngle(q->back()) / math::kDeg, 0.01);
    EXPECT_NEAR(math::headingAngle(q->back()), 1.0, 0.05);
    // Without the finish rest the drift (≈ 2.7° after 10 s) stays.
    const auto raw =
        RestAlignedStrapdown::compute(t, gyr, acc, stream, startStill, std::vector<unsigned char>(t.size(), 0));
    EXPECT_GT(math::inclinationAngle(raw->back()) / math::kDeg, 1.0);
    EXPECT_FALSE(
        RestAlignedStrapdown::compute(t, gyr, acc, stream, std::vector<unsigned char>(t.size(), 0), finishStill).ok());
}

// The judged figures on simulated GS runs: IMU → vqf orientation → rest-aligned strapdown → gates →
// two-pass smoother; and the same run without anchors, which must be far worse.
TEST(AnchorSmootherValidation, GiantSlalomRunMeetsTheThesisFigures) {
    for (int seed : {1, 4}) {
        AnchorEvalOptions o;
        o.simulation.seed = std::uint64_t(seed);
        const auto score = evaluateAnchorRun(o);
        ASSERT_TRUE(score.ok()) << score.message().toStdString();
        EXPECT_LE(score->positionRmse, 0.25) << "seed " << seed;
        EXPECT_LE(score->speedSd, 0.2) << "seed " << seed;
        EXPECT_LE(std::abs(score->speedMean), 0.05) << "seed " << seed;
        EXPECT_GE(score->matched, score->gates - 1) << "seed " << seed;

        o.pipeline.smoother.passes = 0;
        const auto free = evaluateAnchorRun(o);
        ASSERT_TRUE(free.ok()) << free.message().toStdString();
        EXPECT_GT(free->positionRmse, 5.0 * score->positionRmse) << "seed " << seed;
        EXPECT_GT(free->positionRmse, 1.0) << "seed " << seed;
    }
}

TEST(AnchorSmootherValidation, FewerAnchorsGiveLargerErrorsButStillWork) {
    // The thesis's simulated super-G (every 2nd gate): errors grow but stay sub-metre.
    AnchorEvalOptions o;
    o.simulation.seed = 2;
    const auto all = evaluateAnchorRun(o);
    o.keepEveryGate = 3;
    const auto third = evaluateAnchorRun(o);
    ASSERT_TRUE(all.ok() && third.ok());
    EXPECT_LT(third->positionRmse, 0.5);
    EXPECT_GT(third->positionRmse, all->positionRmse);
}

TEST(GateAveraging, RunToRunDriftPartlyCancels) {
    // 20 true gates; 6 runs whose estimates drift by independent random walks (σ 0.5 m per gate) in
    // frames rotated, scaled and shifted: the averaged gates (aligned on first/last) beat one run.
    std::vector<Vec3> truth;
    for (int m = 0; m < 20; ++m) truth.push_back(Vec3(27.0 * m, m % 2 ? 5.0 : -5.0, -8.0 * m));
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal(0.0, 0.5);
    std::vector<std::vector<Vec3>> runs;
    double single = 0.0;
    auto errorAligned = [&](const std::vector<Vec3>& est) {
        // Horizontal error after mapping the first/last estimate onto the truth's (as the averaging does).
        using C = std::complex<double>;
        const C f(est.front().x(), est.front().y()), l(est.back().x(), est.back().y());
        const C F(truth.front().x(), truth.front().y()), L(truth.back().x(), truth.back().y());
        const C a = (L - F) / (l - f);
        double sum = 0.0;
        for (std::size_t m = 0; m < est.size(); ++m)
            sum += std::abs(F + a * (C(est[m].x(), est[m].y()) - f) - C(truth[m].x(), truth[m].y()));
        return sum / double(est.size());
    };
    for (int r = 0; r < 6; ++r) {
        const double angle = 0.05 * (r - 2), scale = 1.0 + 0.01 * (r - 3);
        const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Vec3::UnitZ()).toRotationMatrix();
        Vec3 drift = Vec3::Zero();
        std::vector<Vec3> est;
        for (const Vec3& g : truth) {
            drift += Vec3(normal(rng), normal(rng), 0.2 * normal(rng));
            est.push_back(scale * (R * (g + drift)) + Vec3(3.0 * r, -2.0 * r, 1.0));
        }
        single += errorAligned(est) / 6.0;
        runs.push_back(est);
    }
    const auto mean = GateAveraging::average(runs);
    ASSERT_TRUE(mean.ok()) << mean.message().toStdString();
    ASSERT_EQ(mean->size(), truth.size());
    EXPECT_LT(errorAligned(*mean), 0.6 * single);
    // Runs of different lengths cannot be paired.
    runs[2].pop_back();
    EXPECT_FALSE(GateAveraging::average(runs).ok());
}

TEST(AnchorSmootherValidation, GnssFreeGatesFromFiveRuns) {
    AnchorEvalOptions o;
    const auto score = evaluateGateAveraging(o, 5, 100);
    ASSERT_TRUE(score.ok()) << score.message().toStdString();
    EXPECT_LT(score->averagedMean, score->singleMean);
}
