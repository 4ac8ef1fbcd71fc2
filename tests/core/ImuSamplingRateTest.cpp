// ImuSamplingRate on a simulated foot-like motion with ground truth: rests, then swings that turn the
// sensor by up to 60° about a tilted axis while it moves forward (accelerometer = Rᵀ(p̈ + g e_z), from the
// true orientation), sampled at a known rate. The true rate has the lowest score among 51.2 · 2^k Hz and
// among nearby rates; a sensor that is never still gives no estimate.
#include "core/io/ImuSamplingRate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

using namespace athlos;
using math::Quat;
using math::Vec3;

namespace {

constexpr double kPi = std::numbers::pi;

// Strides of 1.1 s: 0.5 s rest, 0.6 s swing. In the swing the sensor turns by θ(s) = 1.0 sin(2π s) rad
// (s ∈ [0, 1] the swing phase) about an axis mostly medio-lateral, and moves 1.2 m forward with a
// minimum-jerk profile; gyroscope and accelerometer with white noise.
ImuSamplingRate::Imu simulate(double rate, int strides, unsigned seed = 1) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    const double dt = 1.0 / rate, rest = 0.5, swing = 0.6, period = rest + swing;
    const Vec3 axis = Vec3(0.2, 1.0, 0.1).normalized();
    const Quat mount = Quat(Eigen::AngleAxisd(0.7, Vec3(0.3, 1.0, 0.0).normalized()));  // sensor on the instep
    const auto state = [&](double t, Quat& q, Vec3& p) {
        const int k = int(std::floor(t / period));
        const double local = t - k * period;
        double theta = 0.0, x = 1.2 * k;
        if (local > rest) {
            const double s = (local - rest) / swing;
            theta = 1.0 * std::sin(2.0 * kPi * s);
            x += 1.2 * (10 * s * s * s - 15 * s * s * s * s + 6 * s * s * s * s * s);
        }
        q = Quat(Eigen::AngleAxisd(theta, axis)) * mount;
        p = Vec3(x, 0.0, 0.05 * (1.0 - std::cos(2.0 * kPi * std::max(0.0, local - rest) / swing)));
    };
    ImuSamplingRate::Imu imu;
    const int n = int(strides * period * rate);
    for (int i = 0; i < n; ++i) {
        const double t = i * dt, h = 1e-4;
        Quat q0, q1, q2;
        Vec3 p0, p1, p2;
        state(t - h, q0, p0);
        state(t, q1, p1);
        state(t + h, q2, p2);
        const Vec3 acc = (p2 - 2.0 * p1 + p0) / (h * h) + 9.81 * Vec3::UnitZ();
        const Quat dq = q1.conjugate() * q2;  // body rate over [t, t + h]
        const Vec3 w = 2.0 * dq.vec() / h;
        imu.acc.push_back(q1.conjugate() * acc + 0.03 * Vec3(noise(rng), noise(rng), noise(rng)));
        imu.gyr.push_back(w + 0.005 * Vec3(noise(rng), noise(rng), noise(rng)));
    }
    return imu;
}

}  // namespace

TEST(ImuSamplingRate, TheTrueRateScoresLowest) {
    const std::vector<double> rates{51.2, 102.4, 204.8, 409.6, 819.2};
    for (double truth : {102.4, 204.8}) {
        const std::vector<ImuSamplingRate::Imu> imus{simulate(truth, 12)};
        const ImuSamplingRate estimator;
        auto best = estimator.best(imus, rates);
        ASSERT_TRUE(best.ok()) << best.message().toStdString();
        EXPECT_DOUBLE_EQ(best->rate, truth);
        EXPECT_GE(best->segments, 10);
        // By a margin: every other candidate at least twice the score.
        for (const auto& c : estimator.scores(imus, rates)) {
            if (c.rate == truth) continue;
            EXPECT_GT(c.score, 2.0 * best->score) << c.rate << " Hz vs " << truth;
        }
        // A continuous scan has its minimum within 10 % of the truth.
        std::vector<double> scan;
        for (double f = 0.5 * truth; f <= 2.0 * truth; f *= 1.05) scan.push_back(f);
        auto fine = estimator.best(imus, scan);
        ASSERT_TRUE(fine.ok());
        EXPECT_NEAR(fine->rate / truth, 1.0, 0.1) << fine->rate;
    }
}

TEST(ImuSamplingRate, NoStillPhasesNoEstimate) {
    // A sensor turning all the time (2 rad/s about its z axis, z up): never still.
    ImuSamplingRate::Imu spinning;
    for (int i = 0; i < 2000; ++i) {
        spinning.acc.push_back(9.81 * Vec3::UnitZ());
        spinning.gyr.push_back(Vec3(0.0, 0.0, 2.0));
    }
    const std::vector<ImuSamplingRate::Imu> imus{spinning};
    auto best = ImuSamplingRate().best(imus, {51.2, 102.4, 204.8});
    ASSERT_FALSE(best.ok());
    EXPECT_NE(best.message().indexOf("still"), -1) << best.message().toStdString();
    EXPECT_FALSE(ImuSamplingRate().best({}, {102.4}).ok());
    EXPECT_FALSE(ImuSamplingRate().best(imus, {}).ok());
}
