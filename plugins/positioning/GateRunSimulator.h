#pragma once
// Simulated giant-slalom run with magnets buried at the gates (Fasel thesis ch. 9, Fig. 9.1/9.3):
//  - the sacrum follows a sinusoidal line down a slope, one turn per gate (gates ~27 m apart, the
//    thesis course had 21.8–27.8 m), speed 15–25 m/s, standing still at the start and the finish;
//  - at each gate the magnet lies on the inside of the turn, δ ∈ [0.15, 0.5] m beside and
//    h ∈ [0.45, 0.6] m below the sacrum (snow surface), so |r| ≈ 0.5–0.8 m: the thesis saw every
//    magnet up to ≈ 0.8 m;
//  - the magnet's field adds to the earth's field with the thesis's intensity/distance relation
//    (eq. 9.1 inverted, see GateDetector.h for the reading of |B|) and the direction of a vertical
//    dipole;
//  - a sacrum IMU (x forward, y left, z up) with bias, noise, gyroscope drift (≈ 0.15 °/s),
//    speed-dependent vibration and magnetometer noise; optional 10 Hz GNSS with white noise.
// The ideal gyroscope sample k is the constant body rate from q_{k−1} to q_k, the accelerometer
// f = Rᵀ(a + g e_z), the magnetometer Rᵀ(B_earth + B_magnets). Deterministic for a seed.
#include "core/math/QuaternionOps.h"

#include <QString>
#include <cstdint>
#include <vector>

namespace athlos::positioning {

struct Gate {
    QString id;
    math::Vec3 position;  // ENU (m)
};

class GateRunSimulator {
public:
    struct Params {
        std::uint64_t seed = 1;
        std::uint64_t courseSeed = 0;  // ≠ 0: the gates' magnet offsets from this seed (several runs, one course)
        int gates = 24;
        double gateSpacing = 26.0;                       // m along the fall line between turns
        double spacingJitter = 0.25;                     // rad of phase wobble (varies the gate distances)
        double amplitude = 5.0;                          // m, lateral excursion of the sacrum line
        double slope = 17.0 * 3.14159265358979 / 180.0;  // rad
        double courseAzimuth = 1.2;                      // rad, fall line direction counter-clockwise from east
        math::Vec3 start{12.0, -30.0, 2.0};              // m, sacrum at the start (ENU)
        double meanSpeed = 20.0;                         // m/s
        double speedAmplitude = 4.0;                     // m/s (speed stays in mean ± amplitude)
        double accelTime = 2.5;                          // s, time constant of the start and speed changes
        double brake = 6.0;                              // m/s² after the finish line
        double restStart = 4.0;                          // s standing at the start
        double restEnd = 4.0;                            // s standing at the finish
        double imuRate = 200.0;                          // Hz (acc, gyr and mag share the time axis)
        // IMU errors
        double gyrBias = 0.15 * 3.14159265358979 / 180.0;  // rad/s, σ per axis (drift ≈ 0.15 °/s)
        double gyrBiasWalk = 1e-4;                         // rad/s per √s: bias instability after the start
        double gyrNoise = 0.005;                           // rad/s per sample (σ)
        double accBias = 0.05;                             // m/s², σ per axis
        double accNoise = 0.1;                             // m/s² per sample (σ)
        double vibration = 0.5;                            // m/s² per sample at 20 m/s (σ, ∝ speed)
        double magNoise = 0.3;                             // µT per sample (σ)
        math::Vec3 earthField{0.0, 21.0, -43.0};           // µT, ENU
        // Gate geometry (per gate, uniform)
        double lateralMin = 0.15, lateralMax = 0.5;  // m, sacrum → magnet horizontally
        double heightMin = 0.45, heightMax = 0.6;    // m, sacrum above the magnet
        // GNSS (0 Hz: none)
        double gnssRate = 0.0;
        double gnssSigma = 1.0;  // m, per axis
        double gravity = 9.81;
    };

    struct Result {
        // IMU at imuRate, sensor frame: acc (m/s²), gyr (rad/s), mag (µT).
        std::vector<double> t;
        std::vector<math::Vec3> acc, gyr, mag;
        // Truth at the IMU times (ENU): sacrum position, velocity, orientation (sensor → earth).
        std::vector<math::Vec3> position, velocity;
        std::vector<math::Quat> orientation;
        std::vector<Gate> gates;                 // surveyed magnet positions
        std::vector<double> gateTimes;           // truth crossing times (closest approach)
        std::vector<double> gateDistance;        // truth |r| at the crossing (m)
        double startMove = 0.0, stopMove = 0.0;  // s, the moving part
        std::vector<double> gnssT;
        std::vector<math::Vec3> gnss;  // ENU (m)
    };

    static Result simulate(const Params& params);
    // The magnet excess field |B_magnet| / |B_earth| at distance r (m) (thesis eq. 9.1 inverted; 0 beyond 1 m).
    static double magnetExcess(double distance);
};

}  // namespace athlos::positioning
