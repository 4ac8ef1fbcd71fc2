// The IMU/optical clock offset diagnostic (tools/eval/ImuClockOffset.h) on a synthetic recording with
// known truth: a sensor translating and rotating, the accelerometer sampled late by a known delay.
#include "tools/eval/ImuClockOffset.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>

using namespace athlos;
using math::Quat;
using math::Vec3;

namespace {
Vec3 position(double t) { return {0.3 * std::sin(2.1 * t), 0.2 * std::sin(3.3 * t + 1.0), 0.1 * std::sin(1.7 * t)}; }
Vec3 acceleration(double t) {
    return {-0.3 * 2.1 * 2.1 * std::sin(2.1 * t), -0.2 * 3.3 * 3.3 * std::sin(3.3 * t + 1.0),
            -0.1 * 1.7 * 1.7 * std::sin(1.7 * t)};
}
Quat orientation(double t) {
    return math::quatFromRotationVector(Vec3(0.6 * std::sin(1.3 * t), 0.4 * std::sin(0.9 * t + 0.5), 0.8 * t));
}
// delay: how late (s) the accelerometer samples; gaps: NaN optical samples every 500.
void recording(double ts, double delay, std::vector<Vec3>& acc, std::vector<Quat>& q, std::vector<Vec3>& pos) {
    const std::size_t n = 6000;
    acc.resize(n);
    q.resize(n);
    pos.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * ts, ta = t - delay;
        acc[k] = orientation(ta).conjugate() * (acceleration(ta) + Vec3(0.0, 0.0, 9.81));
        q[k] = orientation(t);
        pos[k] = position(t);
        if (k % 500 == 250) {
            q[k].coeffs().setConstant(std::numeric_limits<double>::quiet_NaN());
            pos[k].setConstant(std::numeric_limits<double>::quiet_NaN());
        }
    }
}
}  // namespace

TEST(ImuClockOffset, FindsTheAccelerometerDelay) {
    const double ts = 0.01;
    for (const double delay : {0.0, 0.015, -0.02}) {
        std::vector<Vec3> acc, pos;
        std::vector<Quat> q;
        recording(ts, delay, acc, q, pos);
        const eval::ClockOffset c = eval::imuClockOffset(acc, q, pos, ts);
        EXPECT_NEAR(c.samples * ts, delay, 0.002) << "true delay " << delay << " s";
        EXPECT_LT(c.rms, 0.1);
    }
}
