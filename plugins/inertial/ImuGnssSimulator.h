#pragma once
// Simulated IMU and GNSS from a known football-like trajectory (spec §10): rest, then sprints from
// standstill (exponential speed model), decelerations, turns and jogging, with a trunk lean that
// follows the acceleration and a running bounce at step frequency. The IMU sees that motion through
// bias, white noise, scale errors and saturation; the GNSS through white noise plus a slowly varying
// (first-order Gauss–Markov) error, at its own rate.
//
// The ideal IMU is consistent with the truth by construction: the gyroscope sample k is the constant
// body rate that takes q_k−1 to q_k (so strapdown of error-free data reproduces the truth exactly),
// and the accelerometer measures f = Rᵀ(a + g e_z) at t_k.
#include "core/math/Angles.h"
#include "plugins/inertial/OrientationTypes.h"

#include <cstdint>
#include <vector>

namespace athlos::inertial {

struct SimulatorParams {
    std::uint64_t seed = 1;
    double duration = 90.0;    // s, including the initial rest
    double initialRest = 5.0;  // s
    double imuRate = 100.0;    // Hz
    double gnssRate = 10.0;    // Hz
    double mountYaw = 0.3;     // rad, sensor x axis relative to the running direction
    // false: the same rotations (turns, lean, sway) but no translation, so the accelerometer sees
    // gravity only — for orientation tests where a sprint's sustained acceleration (which no
    // IMU-only filter can tell from tilt) would dominate the error.
    bool translation = true;
    // IMU errors
    double gyrBias = 0.5 * math::kDeg;      // rad/s, per-axis bias drawn in ±this
    double gyrNoise = 0.003;                // rad/s per sample (σ)
    double gyrScale = 0.01;                 // relative, per axis in ±this
    double gyrRange = 1000.0 * math::kDeg;  // rad/s, saturation
    double accBias = 0.1;                   // m/s², per axis in ±this
    double accNoise = 0.05;                 // m/s² per sample (σ)
    double accScale = 0.01;
    double accRange = 16.0 * 9.81;           // m/s²
    double magNoise = 0.5;                   // µT
    Vec3 magField = Vec3(0.0, 20.0, -44.0);  // µT, ENU (north, dip ≈ 65°)
    // GNSS errors
    double gnssHorizontalSigma = 2.5;   // m, horizontal RMS of the white error (per axis 2.5/√2)
    double gnssVerticalSigma = 4.0;     // m
    double gnssCorrelatedSigma = 0.5;   // m per axis, slowly varying error
    double gnssCorrelationTime = 60.0;  // s
    double gnssVelocitySigma = 0.1;     // m/s per axis
    double gravity = 9.81;
};

struct SimulatedData {
    // IMU at imuRate: t, acc (m/s²), gyr (rad/s), mag (µT), sensor frame.
    std::vector<double> imuT;
    std::vector<Vec3> acc, gyr, mag;
    // Truth at the IMU times (ENU, origin at the start): position, velocity, orientation, sprint flags.
    std::vector<Vec3> position, velocity;
    std::vector<Quat> orientation;
    std::vector<double> distance;        // horizontal path length since the start (m)
    std::vector<int> sprint;             // index of the 10 m sprint this sample belongs to, or -1
    std::vector<double> sprintDistance;  // distance since that sprint's start (m), NaN outside
    // GNSS at gnssRate: t, position and velocity in ENU (m, m/s).
    std::vector<double> gnssT;
    std::vector<Vec3> gnssPosition, gnssVelocity;
    // Errors actually applied (for tests): gyroscope bias (rad/s) and accelerometer bias (m/s²).
    Vec3 gyrBias, accBias;
};

SimulatedData simulateImuGnss(const SimulatorParams& params);

}  // namespace athlos::inertial
