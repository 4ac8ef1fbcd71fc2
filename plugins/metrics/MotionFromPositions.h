#pragma once
// Speed and acceleration of an athlete from position fixes, for the session metrics.
//
// Raw positions overstate distance: white position noise of σ adds roughly √π·σ·√2 … per step, which at
// 10 Hz turns σ = 0.1 m into several hundred metres over a match. By default the fixes therefore go
// through the robust Kalman smoother of position-filter (EKF, CTRA or constant-velocity model, outlier
// gating, RTS smoothing) with Q, R and the gate estimated from the data itself (eq. 4.13 of the LPS
// seed). The estimate runs on evenly spread chunks of the recording (a representative subsample), not
// on all of it: the noise of a device does not change within a session, and a 90-min match then takes
// about a second instead of eleven.
//
// Standing still: a smoother's position wanders by its own error even when the athlete stands, and that
// wander adds distance (a goalkeeper's distance by some 10 %). Where the fixes of a window of
// `stationaryWindow` seconds around a grid sample are consistent with one fixed point under the
// estimated measurement noise — the scatter Σ|p_i − p̄|²/r is below the χ²(2(n − 1)) quantile at
// `stationaryConfidence` (Wilson–Hilferty) — the athlete is taken as standing: speed and acceleration 0
// and the position held at the mean of the run's fixes. Gated outliers are left out of the test.
//
// Outages longer than `maxGap` are not bridged: grid samples inside them are invalid and add no
// distance (an athlete's path during a 30-s outage is unknown, a straight line would understate it).
#include "core/util/Expected.h"
#include "plugins/metrics/SessionMetrics.h"
#include "plugins/positioning/PositionFilter.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace athlos::metrics {

struct MotionParams {
    bool filter = true;  // false: raw positions, speed and acceleration by central differences
    positioning::ModelKind model = positioning::ModelKind::ConstantVelocity;  // or Unconstrained (CTRA)
    double rate = 10.0;                                                       // Hz, output grid of the filtered motion
    double maxGap = 2.0;                                                      // s, longer outages are not bridged
    double noiseChunk = 60.0;            // s, length of one chunk of the noise estimate
    int noiseChunks = 8;                 // chunks of the noise estimate (0 = estimate on the whole recording)
    bool estimateNoise = true;           // false: use `noise` as given
    double stationaryWindow = 2.0;       // s, window of the standing test (0 = off)
    double stationaryConfidence = 0.99;  // χ² quantile of the standing test
    positioning::NoiseSettings noise;
};

struct MotionResult {
    MotionSeries series;
    std::vector<std::pair<std::string, double>> estimatedNoise;  // empty unless estimated
    int outliers = 0;                                            // fixes rejected by the gate
    double stationaryTime = 0.0;                                 // s taken as standing still
    bool cancelled = false;
};

using MotionProgress = std::function<bool(double)>;  // fraction; false = cancel

// Errors: fewer than 10 fixes, or no two fixes within maxGap.
Expected<MotionResult> motionFromPositions(const positioning::PositionSamples& fixes, const MotionParams& params,
                                           const MotionProgress& progress = {});

// Quantile of the χ² distribution with k degrees of freedom at probability p (Wilson–Hilferty 1931,
// relative error < 1 % for k ≥ 3 at p = 0.99).
double chiSquareQuantile(double p, double k);

}  // namespace athlos::metrics
