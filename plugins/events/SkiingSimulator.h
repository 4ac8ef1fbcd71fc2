#pragma once
// Skiing simulators with ground truth for xc-skiing-cycles, skimo-phases and alpine-turns.
//
// Ski cycles (cross-country diagonal stride, ski mountaineering): a ski IMU (x along the ski, y to the
// left, z up) moves in the vertical plane along a track of arc length s whose inclination is
// β(s) = β₀ + β₁ sin(2π s / λ) (uphill positive). Each cycle starts with the ski motionless for the
// thrust (static friction, Fasel 2017 ch. 3), then moves by the cycle length L with speed
// s'(τ) = L / T · 60 τ² (1 − τ)³ (τ ∈ [0, 1] over the moving time T: fast swing, long glide, zero
// speed and acceleration at both ends) while the ski pitches by δ(τ) = δ₁ sin²(πτ) away from the track.
// Orientation R = R_y(−(β + δ)), so ω = (0, −(β' s' + δ'), 0) and a = Rᵀ (p̈ + g e_z) with
// p̈ = s'' t̂ + s'² β' n̂ (tangent t̂ = (cos β, sin β), normal n̂ = (−sin β, cos β)). Noise, a constant
// gyroscope and accelerometer bias and speed-proportional snow vibration are added.
//
// A pole IMU (optional) rotates in the same plane; each pole plant adds a damped 40 Hz shock along
// the pole from the plant instant and each pole lift a 30 ms acceleration pulse centred on the lift
// (the signatures of Fasel 2017 Table 3.1).
//
// Alpine: a sacrum IMU on a slope of angle α follows y(u) = ±A sin(π (u − U_k) / D_k) across the fall
// line (turn k between U_k and U_k + D_k, A/D fixed so the heading is continuous) at speed V along the
// fall line, heading ψ = atan(dy/du) in the slope plane, leaning into the turn by atan(v² κ / g) and
// pitching ±5° at 1.7 Hz; turn switches (curvature sign changes) are at u = U_k.
#include <Eigen/Core>
#include <vector>

namespace athlos::events {

struct SkiCycleSimConfig {
    double rate = 200.0;      // Hz
    double standStart = 2.0;  // s still before the first cycle
    double standEnd = 2.0;    // s still after the last cycle
    int cycles = 40;
    double cycleTimeMin = 1.2, cycleTimeMax = 1.6;  // s, drawn uniformly per cycle
    double stillFraction = 0.15;                    // thrust (motionless) share of the cycle
    double speedMin = 3.0, speedMax = 6.0;          // m/s cycle speed, drawn uniformly per cycle
    double slope0 = 0.0;                            // rad, β₀
    double slope1 = 0.087;                          // rad, β₁ (5°)
    double slopeWavelength = 150.0;                 // m, λ
    double skiPitch = -0.17;                        // rad, δ₁ (ski tail lifted in the swing)
    double gyrNoise = 0.01;                         // rad/s (1 σ)
    double accNoise = 0.05;                         // m/s² (1 σ)
    double vibration = 0.5;                         // m/s² (1 σ) at 5 m/s, proportional to speed
    Eigen::Vector3d gyrBias{0.01, -0.02, 0.015};    // rad/s
    Eigen::Vector3d accBias{0.05, -0.04, 0.03};     // m/s²
    bool pole = true;                               // simulate a pole IMU
    double polePlantLead = 0.10;                    // s, pole plant before the thrust start
    double poleContactFraction = 0.45;              // pole on the snow, share of the cycle
    double truthZeroSpeed = 0.1;                    // m/s: thrust start/end of the truth (Fasel 2017 Table 3.1)
    double truthZeroAcc = 1.0;                      // m/s²
    unsigned seed = 3;
};

struct SkiCycleTruth {
    double thrustStart = 0, thrustEnd = 0, glideStart = 0, end = 0;  // s; end = next thrust start
    double polePlant = 0, poleLift = 0;                              // s
    double length = 0;                                               // m of track (arc length)
    double speed = 0;                                                // m/s, length / duration
    double elevation = 0;                                            // m gained over the cycle
    double slope = 0;                                                // rad, atan2(Δz, Δx) of the cycle
};

struct SkiCycleRecording {
    std::vector<double> t;
    std::vector<double> ski;    // row-major acc_x..z (m/s²), gyr_x..z (rad/s)
    std::vector<double> pole;   // same layout, empty without pole
    std::vector<double> speed;  // true ski speed per sample (m/s)
    std::vector<SkiCycleTruth> truth;
};

SkiCycleRecording simulateSkiCycles(const SkiCycleSimConfig& config);

// A ski-mountaineering ascent: steep track, skins (no ski pitch), slow cycles, no pole.
SkiCycleSimConfig skimoConfig(unsigned seed);

struct AlpineSimConfig {
    double rate = 200.0;      // Hz
    double standStart = 2.0;  // s still before the run (speed ramps up over 2 s)
    double standEnd = 2.0;
    int turns = 24;
    double slope = 0.454;                                   // rad, α (26°, spec §10)
    double speed = 20.0;                                    // m/s along the fall line
    double turnDistanceMin = 22.0, turnDistanceMax = 32.0;  // m, D_k (27 m on average, spec §10)
    double amplitudeRatio = 0.1;                            // A / D
    double wobble = 0.087;                                  // rad, pitch oscillation amplitude
    double gyrNoise = 0.02;                                 // rad/s
    double accNoise = 0.1;                                  // m/s²
    double vibration = 2.0;                                 // m/s² (1 σ) while skiing
    Eigen::Vector3d gyrBias{0.02, -0.01, 0.015};
    unsigned seed = 5;
};

struct AlpineTurnTruth {
    double start = 0, end = 0;  // s, turn switch to turn switch
    bool left = false;          // turning to the skier's left
};

struct AlpineRecording {
    std::vector<double> t;
    std::vector<double> sacrum;  // row-major acc_x..z, gyr_x..z
    std::vector<AlpineTurnTruth> turns;
};

AlpineRecording simulateAlpine(const AlpineSimConfig& config);

}  // namespace athlos::events
