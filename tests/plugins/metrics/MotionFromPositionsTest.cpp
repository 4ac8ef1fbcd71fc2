// Motion from position fixes: the raw path, the smoothed path against the truth of a noisy simulated
// run (distance within 1 %, speed, acceleration efforts), outages and the noise chunks.
#include "plugins/metrics/MotionFromPositions.h"

#include <gtest/gtest.h>
#include <cmath>
#include <random>

using namespace athlos::metrics;
using athlos::positioning::PositionSamples;

namespace {

// A shuttle run on a 30 m line, repeated: accelerate at 3.5 m/s² to 6 m/s, run, decelerate at −3.5 m/s²,
// turn, standing 3 s; sampled at 10 Hz with white noise σ and a few outliers. Truth returned.
struct Simulated {
    PositionSamples fixes;
    MotionSeries truth;
};

Simulated shuttle(double sigma, unsigned seed) {
    Simulated s;
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const double dt = 0.01;  // integration step
    double t = 0, x = 0, v = 0, dir = 1, heading = 0.3;
    int phase = 0;  // 0 standing, 1 accelerating, 2 running, 3 decelerating
    double phaseEnd = 2.0, runStart = 0;
    std::size_t next = 0;
    while (t < 300.0) {
        double a = 0;
        if (phase == 0 && t >= phaseEnd) phase = 1, runStart = x;
        if (phase == 1) a = 3.5, phase = v >= 6.0 ? 2 : 1;
        if (phase == 2 && std::abs(x - runStart) >= 30.0 - 6.0 * 6.0 / (2 * 3.5)) phase = 3;
        if (phase == 3) {
            a = -3.5;
            if (v <= 0) v = 0, phase = 0, phaseEnd = t + 3.0, dir = -dir;
        }
        if (phase == 1 && v >= 6.0) a = 0, v = 6.0;
        if (std::llround(t * 100) == std::llround(next * 10.0)) {  // 10 Hz sample
            s.truth.t.push_back(t);
            s.truth.x.push_back(x * std::cos(heading));
            s.truth.y.push_back(x * std::sin(heading));
            s.truth.speed.push_back(v);
            s.truth.accel.push_back(a);
            s.truth.valid.push_back(1);
            double fx = x * std::cos(heading) + noise(rng), fy = x * std::sin(heading) + noise(rng);
            if (uniform(rng) < 0.003) fx += 8.0, fy -= 6.0;
            s.fixes.t.push_back(t);
            s.fixes.p.emplace_back(fx, fy);
            ++next;
        }
        v = std::max(0.0, v + a * dt);
        x += dir * v * dt;
        t += dt;
    }
    return s;
}

double pathLength(const MotionSeries& s) {
    double d = 0;
    for (std::size_t k = 1; k < s.size(); ++k)
        if (s.valid[k] && s.valid[k - 1]) d += std::hypot(s.x[k] - s.x[k - 1], s.y[k] - s.y[k - 1]);
    return d;
}

}  // namespace

TEST(MotionFromPositions, RawPathOfExactFixes) {
    PositionSamples line;
    for (int k = 0; k <= 100; ++k) {
        line.t.push_back(k * 0.1);
        line.p.emplace_back(0.6 * k, 0.8 * k);  // 10 m/s
    }
    MotionParams p;
    p.filter = false;
    const auto r = motionFromPositions(line, p);
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_NEAR(pathLength(r->series), 100.0, 1e-9);
    for (double v : r->series.speed) EXPECT_NEAR(v, 10.0, 1e-9);
}

TEST(MotionFromPositions, SmoothedNoisyShuttleKeepsDistanceSpeedAndEfforts) {
    const Simulated sim = shuttle(0.1, 7);
    const double truthDistance = pathLength(sim.truth);
    const auto smoothed = motionFromPositions(sim.fixes, MotionParams{});
    ASSERT_TRUE(smoothed.ok()) << smoothed.message().toStdString();
    MotionParams rawParams;
    rawParams.filter = false;
    const auto raw = motionFromPositions(sim.fixes, rawParams);
    ASSERT_TRUE(raw.ok());
    const double filtered = pathLength(smoothed->series), unfiltered = pathLength(raw->series);
    EXPECT_NEAR(filtered / truthDistance, 1.0, 0.015) << "truth " << truthDistance << " m, smoothed " << filtered;
    EXPECT_GT(unfiltered / truthDistance, 1.2) << "raw positions overstate the distance";
    EXPECT_GT(smoothed->outliers, 0);

    const PeriodMetrics truth = computePeriod(sim.truth, 0, 300, MetricsParams{});
    const PeriodMetrics est = computePeriod(smoothed->series, 0, 300, MetricsParams{});
    EXPECT_NEAR(est.maxSpeed, truth.maxSpeed, 0.3);
    EXPECT_GT(truth.accelerationCount, 10);
    EXPECT_NEAR(est.accelerationCount, truth.accelerationCount, 0.15 * truth.accelerationCount);
    EXPECT_NEAR(est.decelerationCount, truth.decelerationCount, 0.15 * truth.decelerationCount);
}

TEST(MotionFromPositions, LongOutagesAreNotBridged) {
    PositionSamples line;
    for (int k = 0; k <= 200; ++k) {
        if (k > 50 && k < 150) continue;  // a 10-s outage
        line.t.push_back(k * 0.1);
        line.p.emplace_back(2.0 * k * 0.1, 0.0);  // 2 m/s
    }
    for (bool filter : {false, true}) {
        MotionParams p;
        p.filter = filter;
        const auto r = motionFromPositions(line, p);
        ASSERT_TRUE(r.ok());
        EXPECT_NEAR(pathLength(r->series), 20.0, 0.2) << (filter ? "smoothed" : "raw");
    }
}

TEST(MotionFromPositions, RefusesTooFewFixes) {
    PositionSamples few;
    for (int k = 0; k < 5; ++k) few.t.push_back(k), few.p.emplace_back(k, 0);
    EXPECT_FALSE(motionFromPositions(few, MotionParams{}).ok());
}
