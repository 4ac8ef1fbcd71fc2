// The session metrics against hand-computed answers on constructed trajectories: distance to 1 %
// (here exact up to rounding), counts exact, metabolic power and PlayerLoad against worked examples.
#include "plugins/metrics/MetabolicPower.h"
#include "plugins/metrics/PlayerLoad.h"
#include "plugins/metrics/SessionMetrics.h"

#include <gtest/gtest.h>
#include <cmath>
#include <functional>

using namespace athlos::metrics;

namespace {

// A straight run along x sampled at `rate` with the speed profile v(t) and acceleration a(t); the
// position integrates v exactly by the trapezoid rule on a 100× finer grid.
MotionSeries straightRun(double duration, double rate, const std::function<double(double)>& v,
                         const std::function<double(double)>& a) {
    MotionSeries s;
    const auto n = static_cast<std::size_t>(std::llround(duration * rate)) + 1;
    s.resize(n);
    double x = 0.0, tPrev = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = double(k) / rate;
        const int fine = 100;
        for (int j = 0; j < fine && k > 0; ++j) {
            const double t0 = tPrev + (t - tPrev) * j / fine, t1 = tPrev + (t - tPrev) * (j + 1) / fine;
            x += 0.5 * (v(t0) + v(t1)) * (t1 - t0);
        }
        s.t[k] = t;
        s.x[k] = x;
        s.y[k] = 0.0;
        s.speed[k] = v(t);
        s.accel[k] = a(t);
        tPrev = t;
    }
    return s;
}

// 0 → 8 m/s at 4 m/s² (2 s), 8 m/s for 3 s, 8 → 0 m/s at −4 m/s² (2 s), standing 3 s: 10 s.
double sprintSpeed(double t) {
    if (t < 2) return 4 * t;
    if (t < 5) return 8;
    if (t < 7) return 8 - 4 * (t - 5);
    return 0;
}
double sprintAccel(double t) { return t < 2 ? 4 : t < 5 ? 0 : t < 7 ? -4 : 0; }

}  // namespace

TEST(SessionMetrics, ConstantSpeedRun) {
    // 5 m/s for 60 s: 300 m, all in zone 3 (14.4–19.8 km/h = 4–5.5 m/s), no efforts.
    const MotionSeries s = straightRun(
        60, 10, [](double) { return 5.0; }, [](double) { return 0.0; });
    const PeriodMetrics m = computePeriod(s, 0, 60, MetricsParams{});
    EXPECT_NEAR(m.distance, 300.0, 1e-9);
    EXPECT_DOUBLE_EQ(m.maxSpeed, 5.0);
    ASSERT_EQ(m.zoneDistance.size(), 5u);
    EXPECT_NEAR(m.zoneDistance[2], 300.0, 1e-9);
    EXPECT_DOUBLE_EQ(m.zoneDistance[0] + m.zoneDistance[1] + m.zoneDistance[3] + m.zoneDistance[4], 0.0);
    EXPECT_EQ(m.hsrDistance, 0.0);
    EXPECT_EQ(m.sprintCount, 0);
    EXPECT_EQ(m.accelerationCount, 0);
    EXPECT_EQ(m.decelerationCount, 0);
    // Constant speed on grass: EC = 3.6 · 1.29 = 4.644 J/kg/m → 1393.2 J/kg, P = 23.22 W/kg (> 20).
    EXPECT_NEAR(m.metabolicEnergy, 1393.2, 1e-6);
    EXPECT_NEAR(m.metabolicPowerMean, 23.22, 1e-9);
    EXPECT_NEAR(m.highPowerDistance, 300.0, 1e-9);
    EXPECT_NEAR(m.peakDistance[0], 300.0, 1e-9);  // 1 min window = the whole minute
    EXPECT_TRUE(std::isnan(m.peakDistance[1]));   // period shorter than 3 min
}

TEST(SessionMetrics, OneSprintOneAccelerationOneDeceleration) {
    const MotionSeries s = straightRun(10, 10, sprintSpeed, sprintAccel);
    const PeriodMetrics m = computePeriod(s, 0, 10, MetricsParams{});
    // 8 m (ramp up) + 24 m (3 s at 8 m/s) + 8 m (ramp down) = 40 m.
    EXPECT_NEAR(m.distance, 40.0, 0.4);
    EXPECT_DOUBLE_EQ(m.maxSpeed, 8.0);
    EXPECT_EQ(m.sprintCount, 1);  // ≥ 7 m/s from 1.75 s to 5.25 s: 3.5 s
    EXPECT_EQ(m.accelerationCount, 1);
    EXPECT_EQ(m.decelerationCount, 1);
    // Distance above 5.5 m/s (HSR): from 1.375 s to 5.625 s: 2·(8² − 5.5²)/(2·4) + 24 = 40 − 2·5.5²/8 = 32.4375 m.
    EXPECT_NEAR(m.hsrDistance, 32.4375, 0.01 * 32.4375);
    // The zones add up to the distance.
    double zones = 0;
    for (double z : m.zoneDistance) zones += z;
    EXPECT_NEAR(zones, m.distance, 1e-9);
}

TEST(SessionMetrics, MaxSpeedIsHeldForItsDuration) {
    // 5 m/s with a one-sample spike to 12 m/s at 3 s and a 0.6-s plateau at 8 m/s from 6 s.
    auto v = [](double t) {
        if (std::abs(t - 3.0) < 1e-9) return 12.0;
        return t >= 6.0 - 1e-9 && t <= 6.6 + 1e-9 ? 8.0 : 5.0;
    };
    const MotionSeries s = straightRun(10, 10, v, [](double) { return 0.0; });
    MetricsParams p;
    EXPECT_DOUBLE_EQ(computePeriod(s, 0, 10, p).maxSpeed, 8.0);  // 0.5 s default: the plateau, not the spike
    p.maxSpeedDuration = 0.0;
    EXPECT_DOUBLE_EQ(computePeriod(s, 0, 10, p).maxSpeed, 12.0);
    p.maxSpeedDuration = 1.0;
    EXPECT_DOUBLE_EQ(computePeriod(s, 0, 10, p).maxSpeed, 5.0);
    // An outage splits the plateau: held for 0.3 s on either side only.
    MotionSeries gap = s;
    gap.valid[63] = 0;
    p.maxSpeedDuration = 0.5;
    EXPECT_DOUBLE_EQ(computePeriod(gap, 0, 10, p).maxSpeed, 5.0);
}

TEST(SessionMetrics, EffortDurationsUseInterpolatedCrossings) {
    // Triangular speed peaks 6 → 8 → 6 m/s: above 7 m/s for exactly half the peak's length, at 10 Hz
    // and at 3 Hz alike. Peak lengths 1.8 s (0.9 s above: no sprint) and 2.2 s (1.1 s: a sprint).
    auto peaks = [](double t) {
        auto tri = [](double t, double t0, double len) {
            const double u = (t - t0) / len;
            return u <= 0 || u >= 1 ? 0.0 : 2.0 * (1 - std::abs(2 * u - 1));
        };
        return 6.0 + tri(t, 1.0, 1.8) + tri(t, 5.0, 2.2);
    };
    for (double rate : {10.0, 50.0}) {
        const MotionSeries s = straightRun(10, rate, peaks, [](double) { return 0.0; });
        EXPECT_EQ(computePeriod(s, 0, 10, MetricsParams{}).sprintCount, 1) << rate << " Hz";
    }
    MetricsParams shorter;
    shorter.sprintMinDuration = 0.85;
    const MotionSeries s = straightRun(10, 10, peaks, [](double) { return 0.0; });
    EXPECT_EQ(computePeriod(s, 0, 10, shorter).sprintCount, 2);
}

TEST(SessionMetrics, AccelerationEffortsNeedTheirDuration) {
    // Accelerations of 3.5 m/s² for 0.4 s (too short) and 0.7 s, a deceleration of −3.2 m/s² for 0.6 s.
    auto accel = [](double t) {
        if (t >= 1.0 && t < 1.4) return 3.5;
        if (t >= 3.0 && t < 3.7) return 3.5;
        if (t >= 6.0 && t < 6.6) return -3.2;
        return 0.0;
    };
    MotionSeries s = straightRun(
        10, 100, [](double) { return 3.0; }, accel);
    const PeriodMetrics m = computePeriod(s, 0, 10, MetricsParams{});
    EXPECT_EQ(m.accelerationCount, 1);
    EXPECT_EQ(m.decelerationCount, 1);
}

TEST(SessionMetrics, OutagesAddNoDistanceAndSplitEfforts) {
    MotionSeries s = straightRun(
        20, 10, [](double) { return 7.5; }, [](double) { return 0.0; });
    // Samples 50..59 (5.0–5.9 s) inside an outage.
    for (std::size_t k = 50; k < 60; ++k) s.valid[k] = 0;
    const PeriodMetrics m = computePeriod(s, 0, 20, MetricsParams{});
    // Steps 49→50 … 59→60 (11 steps of 0.75 m) are lost: 150 − 8.25 m.
    EXPECT_NEAR(m.distance, 150.0 - 8.25, 1e-9);
    EXPECT_EQ(m.sprintCount, 2);  // the sprint is split by the outage
}

TEST(SessionMetrics, PeakDistanceOverSlidingWindows) {
    // 2 m/s for 120 s, 6 m/s for 90 s, 2 m/s for 120 s.
    auto v = [](double t) { return t >= 120 && t < 210 ? 6.0 : 2.0; };
    const MotionSeries s = straightRun(330, 10, v, [](double) { return 0.0; });
    const PeriodMetrics m = computePeriod(s, 0, 330, MetricsParams{});
    EXPECT_NEAR(m.peakDistance[0], 360.0, 0.5);  // 60 s at 6 m/s
    EXPECT_NEAR(m.peakDistance[1], 720.0, 0.5);  // 90 s at 6 + 90 s at 2
    EXPECT_NEAR(m.peakDistance[2], 960.0, 0.5);  // 90 s at 6 + 210 s at 2
}

TEST(SessionMetrics, PeriodSelectsSamples) {
    const MotionSeries s = straightRun(10, 10, sprintSpeed, sprintAccel);
    const PeriodMetrics m = computePeriod(s, 2.0, 5.0, MetricsParams{});
    EXPECT_NEAR(m.distance, 24.0, 1e-9);
    EXPECT_NEAR(m.duration, 3.0, 1e-12);
    EXPECT_EQ(m.accelerationCount, 0);
    EXPECT_EQ(m.sprintCount, 1);  // at sprint speed from the period's start for 3 s
}

TEST(MetabolicPower, WorkedExamples) {
    // ES = 0: EC = 3.6 · KT.
    EXPECT_NEAR(energyCost(0.0), 3.6 * 1.29, 1e-12);
    EXPECT_NEAR(energyCost(0.0, {1.0, 9.81}), 3.6, 1e-12);
    // a_f = 0.2 g: ES = 0.2, polynomial 155.4·0.00032 − 30.4·0.0016 − 43.3·0.008 + 46.3·0.04 + 19.5·0.2
    // + 3.6 = 9.006688; EM = √1.04 = 1.0198039; EC = 9.006688 · 1.0198039 · 1.29 = 11.848722 J/kg/m.
    EXPECT_NEAR(energyCost(0.2 * 9.81), 11.848722, 1e-5);
    // Deceleration a_f = −0.2 g: 0.2 (odd powers negated): −0.049728 − 0.04864 + 0.3464 + 1.852 − 3.9 + 3.6
    // = 1.800032; · 1.019804 · 1.29 = 2.368027 J/kg/m.
    EXPECT_NEAR(energyCost(-0.2 * 9.81), 2.368027, 1e-5);
    EXPECT_NEAR(metabolicPower(4.0, 0.0), 4.0 * 4.644, 1e-12);
}

TEST(PlayerLoad, AccumulatesTheRateOfChangeInG) {
    AccelerationSeries a;
    const double g = 9.80665;
    // A 1 g step on x, then a (3, 4) g/10 step: √(0.3² + 0.4²) = 0.5 g; then back on z by 2 g.
    a.t = {0.00, 0.01, 0.02, 0.03};
    a.ax = {0, g, g, g};
    a.ay = {0, 0, 0.3 * g, 0.3 * g};
    a.az = {0, 0, 0.4 * g, -1.6 * g};
    EXPECT_NEAR(playerLoad(a, 0, 1), (1.0 + 0.5 + 2.0) / 100.0, 1e-12);
    EXPECT_NEAR(playerLoad(a, 0.005, 0.025), 0.5 / 100.0, 1e-12);  // only the middle step is in range
}
