#pragma once
// Simulated lower limb with three IMUs (pelvis, thigh, shank) and known joint angles (spec §10):
// standing, walking-like gait along a curve (hip and knee flexion, 3-DOF knee with small
// ab/adduction and rotation coupled to flexion, pelvic rotation/obliquity/tilt), standing, slow
// squats, standing. The segments form a kinematic chain pelvis → hip → thigh → knee → shank, so the
// reference hip and knee angles are exact by construction, and each sensor sits on its segment at
// a known offset with a known, non-trivial mount (sensor-to-segment rotation).
//
// The ideal IMU is consistent with the truth: gyroscope sample k is the constant body rate taking the
// sensor orientation at t_k − Δt to t_k (strapdown reproduces the truth exactly), and the
// accelerometer measures f = Rᵀ(a + g e_z) with a the sensor's acceleration (second derivative of
// its position, including the ω̇ × r + ω × (ω × r) terms of the lever arm) at t_k. Errors: a constant
// bias per axis and white noise, drawn from the seed.
#include "core/math/Angles.h"
#include "plugins/inertial/JointAngles.h"

#include <array>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

namespace athlos::inertial {

enum class LimbSegment { Pelvis = 0, Thigh = 1, Shank = 2 };

struct LimbSimulatorParams {
    std::uint64_t seed = 1;
    Side side = Side::Right;
    double rate = 100.0;                     // Hz
    double standDuration = 3.0;              // s, each standing phase
    double walkDuration = 20.0;              // s
    double gaitPeriod = 1.1;                 // s per stride
    double walkSpeed = 1.2;                  // m/s
    double walkTurn = std::numbers::pi / 2;  // rad, total change of heading while walking
    int squats = 3;
    double squatDuration = 4.0;   // s each
    double initialHeading = 0.4;  // rad, anterior direction counter-clockwise from East
    // IMU errors (per axis: bias drawn uniformly in ±bias, white noise σ per sample)
    double gyrBias = 0.3 * math::kDeg;  // rad/s
    double gyrNoise = 0.004;            // rad/s
    double accBias = 0.05;              // m/s²
    double accNoise = 0.04;             // m/s²
    double gravity = 9.81;
};

struct SimulatedSegment {
    math::Quat mount = math::Quat::Identity();  // segment → sensor coordinates (JointAngles::Params)
    math::Vec3 gyrBias = math::Vec3::Zero(), accBias = math::Vec3::Zero();
    // Lever arms from the sensor to the joint centres in sensor coordinates (NaN where the segment
    // does not touch the joint): pelvis and thigh reach the hip, thigh and shank the knee.
    math::Vec3 toHip = math::Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    math::Vec3 toKnee = math::Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
    std::vector<math::Vec3> acc, gyr;  // sensor frame, m/s², rad/s
    std::vector<math::Quat> sensor;    // true sensor → earth (ENU)
    std::vector<math::Quat> segment;   // true segment → earth (ENU)
};

struct LimbSimulation {
    std::vector<double> t;
    std::array<SimulatedSegment, 3> segments;  // indexed by LimbSegment
    std::vector<AnatomicalAngles> knee, hip;   // reference joint angles (rad), signs as in JointAngles.h
    std::vector<unsigned char> phase;          // 0 stand, 1 walk, 2 squat
    double walkBegin = 0, walkEnd = 0, squatBegin = 0, squatEnd = 0;
    const SimulatedSegment& operator[](LimbSegment s) const { return segments[static_cast<int>(s)]; }
};

LimbSimulation simulateLimb(const LimbSimulatorParams& params);

// Segment → sensor mount from the sensor's x and z axes written in segment coordinates, then turned
// by a small misalignment (rotation vector in the sensor frame), as a real strap never sits square.
// (Also used by BodySimulator.)
math::Quat mountFromAxes(const math::Vec3& x, const math::Vec3& z, const math::Vec3& misalignment);

// The mounts the simulator uses for a side (also in LimbSimulation::segments[i].mount).
math::Quat simulatedMount(LimbSegment segment, Side side);

}  // namespace athlos::inertial
