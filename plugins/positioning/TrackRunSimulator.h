#pragma once
// Simulated LPS recordings of runners on a track with ground truth (thesis §4.1.3 and seed 001 §III):
//  - a standing pre-start, start acceleration v(t) = v_max (1 − e^{−t/τ}), then near-constant speed
//    (slow fatigue decline plus an Ornstein–Uhlenbeck fluctuation), deceleration after the finish;
//  - lane keeping with lane changes: the 800 m break to lane 1 after the first bend, and overtakes
//    (one lane out and back);
//  - an LPS tag: Gaussian noise σ_x² = 5·10⁻³ m², σ_y² = 1.6·10⁻² m²; 5 % outliers in bursts with
//    SD 7 m (variance ≈ 50 m²); sample intervals 10 ms + 1.5·τ ms, τ ~ Poisson(20); outages of
//    several seconds up to 13.7 s.
// Deterministic for a seed (std::mt19937_64).
#include "core/geometry/TrackGeometry.h"
#include "plugins/positioning/PositionFilter.h"

#include <cstdint>
#include <vector>

namespace athlos::positioning {

class TrackRunSimulator {
public:
    struct Params {
        std::uint64_t seed = 1;
        double distance = 400.0;    // m along the running line
        int lane = 1;               // start lane
        double topSpeed = 7.0;      // m/s
        double accelTime = 1.3;     // s, τ of the start acceleration
        double fatigue = 0.08;      // fraction of top speed lost linearly over the distance
        double speedSd = 0.15;      // m/s, OU fluctuation (correlation time 3 s)
        double preStart = 2.0;      // s standing before the gun
        double postFinish = 3.0;    // s recorded after the finish (decelerating)
        bool laneChanges = true;    // 800 m break to lane 1 and random overtakes
        double noiseVarX = 5e-3;    // m²
        double noiseVarY = 1.6e-2;  // m²
        double outlierFraction = 0.05;
        double outlierBurst = 5.0;      // mean samples per burst
        double outlierSd = 7.0;         // m
        double intervalBase = 0.010;    // s
        double intervalScale = 0.0015;  // s per Poisson count
        double intervalPoisson = 20.0;
        double outagesPer400m = 1.0;  // mean number of outages per 400 m
        double outageMin = 2.0;       // s
        double outageMax = 13.7;      // s
        double truthRate = 100.0;     // Hz
        TrackGeometry track = TrackGeometry::iaaf400m();
    };

    struct Truth {
        std::vector<double> t, x, y, speed, heading;
    };

    struct Result {
        PositionSamples measured;
        std::vector<char> outlier;  // per measured sample: 1 = drawn from the outlier distribution
        Truth truth;
        double outageSeconds = 0.0;
    };

    static Result simulate(const Params& params);

    // Truth position at t by linear interpolation (clamped at the ends).
    static Eigen::Vector2d truthAt(const Truth& truth, double t);
    // RMSE (m) of positions against the truth over the samples with truth coverage.
    static double rmse(const Truth& truth, const std::vector<double>& t, const std::vector<Eigen::Vector2d>& p);
};

}  // namespace athlos::positioning
