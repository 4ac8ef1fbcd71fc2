#pragma once
// Foot-motion simulator with ground truth for gait-parameters: a foot-mounted IMU (x forward along
// the foot, y left, z up through the sole) that stands still in stance and, in each swing, moves
// by the stride's horizontal displacement along its mean heading (minimum-jerk profile
// s(τ) = 10τ³ − 15τ⁴ + 6τ⁵), lifts by h (1 − cos 2πτ)/2 (plus a step rise H s(τ) on stairs),
// pitches by θ(τ) = A sin(2πτ) sin²(πτ) and turns by Δψ s(τ). Orientation R = Rz(ψ) Ry(θ), so
// (analytically) ω_body = Ry(θ)ᵀ ψ' e_z + θ' e_y and a_body = Rᵀ (p̈ + g e_z); noise and a constant
// gyroscope and accelerometer bias are added.
//
// Optional realism (all off by default, so that the foot is perfectly still in stance):
//  - stanceRate ω₀: the foot rolls heel-to-toe through the whole stance, at ω₀ at mid-stance and
//    stanceEdgeRate ω_e at contact and push-off (rate ω₀ + (ω_e − ω₀)(2τ − 1)², τ the stance
//    fraction), so the gyroscope never reads zero; the swing pitch gets a cubic Hermite term from
//    the push-off pitch back to the next contact's, with rate ω_e at both ends (ω stays continuous);
//  - stancePivot (per stride): part of the heading change happens in the stance before the swing
//    (minimum-jerk in time), the foot pivoting on its ball;
//  - leverArm d: the trajectory above is the pivot point F (ball of the foot) and the sensor sits
//    at F + R d, so a rolling or pivoting foot moves the sensor (its acceleration gets the second
//    derivative of R d, by central differences);
//  - accScale / gyrScale: per-axis scale errors, applied before bias and noise.
#include <Eigen/Core>
#include <vector>

namespace athlos::events {

struct SimStride {
    double length = 1.4;       // m, horizontal displacement
    double rise = 0.0;         // m, vertical displacement (stairs)
    double turn = 0.0;         // rad, heading change
    double lift = 0.12;        // m, h: swing height above the straight line
    double pitch = 0.6;        // rad, A
    double stance = 0.65;      // s, foot still before the swing
    double swing = 0.45;       // s
    double stancePivot = 0.0;  // rad: heading change in the stance before the swing (not part of `turn`)
};

struct SimConfig {
    double rate = 102.4;                          // Hz
    double standStart = 2.0;                      // s still before the first stride's stance
    double standEnd = 2.0;                        // s still after the last swing
    double gyrNoise = 0.01;                       // rad/s (1 σ)
    double accNoise = 0.05;                       // m/s² (1 σ)
    Eigen::Vector3d gyrBias{0.01, -0.015, 0.02};  // rad/s
    Eigen::Vector3d accBias{0.05, -0.03, 0.04};   // m/s²
    unsigned seed = 7;
    double stanceRate = 0.0;                             // rad/s, ω₀: heel-to-toe roll at mid-stance (0: still)
    double stanceEdgeRate = 3.0;                         // rad/s, ω_e: the roll at contact and push-off
    Eigen::Vector3d leverArm = Eigen::Vector3d::Zero();  // m, d: sensor relative to the pivot (foot frame)
    Eigen::Vector3d accScale = Eigen::Vector3d::Ones();
    Eigen::Vector3d gyrScale = Eigen::Vector3d::Ones();
    std::vector<SimStride> strides;
};

struct SimTruth {
    double start = 0.0, end = 0.0;  // s: the middle of the stances before and after the swing
    // Of the pivot point (the footprint); the sensor's own displacement is in SimRecording::position.
    double length = 0.0, rise = 0.0, turn = 0.0, lift = 0.0;
    double stance = 0.0, swing = 0.0;  // s, within [start, end]
    double swingStart = 0.0;           // s
};

struct SimRecording {
    std::vector<double> t;
    std::vector<double> values;             // row-major acc_x, acc_y, acc_z (m/s²), gyr_x, gyr_y, gyr_z (rad/s)
    std::vector<SimTruth> truth;            // one per stride, swing between start and end
    std::vector<Eigen::Vector3d> position;  // m: the sensor's true position per sample
};

SimRecording simulateFoot(const SimConfig& config);

}  // namespace athlos::events
