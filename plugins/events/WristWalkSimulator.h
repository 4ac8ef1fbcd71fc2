#pragma once
// Wrist-worn IMU and barometer during outdoor walking, with the truth per sample, for wrist-cadence
// and wrist-speed (Fasel thesis ch. 12). Bouts of walking (cadence drifting smoothly within
// cadenceMin..cadenceMax steps/min, a grade per bout) alternate with non-walking periods (standing
// still or arm gestures unrelated to walking).
//
// Model (world x forward, y left, z up): the trunk moves forward at the walking speed v and bounces
// vertically at the step frequency; the arm swings about the shoulder at the stride frequency,
// θ(t) = Θ sin(φ) + 0.15 Θ sin(2φ) with φ the stride phase, the wrist r = 0.36 h below the
// shoulder. Step length L = h (0.415 + 0.004 (c − 100)) k_subject k_grade (c in steps/min;
// ~0.41 h at 100 steps/min, Grieve & Gear 1966), shortened uphill (−1.5 per unit grade) and
// downhill (−0.8), speed v = L c / 60. The arm-swing amplitude grows with the flat-ground step
// length and the bounce with L, so the wrist intensity carries the walker's step length, as the
// thesis's model assumes, while a slope's shortening shows mainly in the barometer. Specific force
// f = R(θ)ᵀ (p̈ + g e_z) with the sensor pitched with the arm and a fixed mounting rotation; gyro
// ω = θ' about the sensor's lateral axis. Barometer: the ISA pressure at the altitude
// (p = 101325 (1 − 2.25577e-5 z)^5.25588 Pa) plus a weather drift and white noise.
#include <cstdint>
#include <vector>

namespace athlos::events {

struct WristWalkParams {
    std::uint64_t seed = 1;
    double duration = 600.0;     // s
    double rate = 100.0;         // Hz, IMU
    double baroRate = 25.0;      // Hz (thesis: 25 Hz)
    double truthRate = 10.0;     // Hz
    double height = 1.75;        // m, the walker's height
    double cadenceMin = 80.0;    // steps/min
    double cadenceMax = 130.0;   // steps/min
    double maxGrade = 0.12;      // |rise/run| of a bout's path
    double walkingShare = 0.75;  // fraction of the time spent walking
    double accNoise = 0.05;      // m/s² (1 σ, white)
    double gyrNoise = 0.01;      // rad/s (1 σ, white)
    double baroNoise = 2.0;      // Pa (1 σ, white)
    double baroDrift = 30.0;     // Pa per hour (weather), sign random
};

struct WristWalkRecording {
    std::vector<double> t;         // IMU time (s)
    std::vector<double> imu;       // row-major acc_x, acc_y, acc_z (m/s²), gyr_x, gyr_y, gyr_z (rad/s)
    std::vector<double> tBaro;     // s
    std::vector<double> pressure;  // Pa
    // Truth at truthRate: cadence (steps/min, 0 when not walking), speed (m/s, along the path),
    // grade (rise/run), altitude (m), walking (1/0).
    std::vector<double> tTruth, cadence, speed, grade, altitude, walking;
    double subjectFactor = 1.0;  // k_subject of the step length
};

WristWalkRecording simulateWristWalk(const WristWalkParams& params);

}  // namespace athlos::events
