#pragma once
// Tightly coupled filtering of raw two-way ranges (issue #16 item 2): instead of solving a fix per
// instant and filtering the fixes, every range d_i to beacon b_i updates the robust Kalman framework
// of thesis §4.1 directly, one scalar update per measurement:
//   h(x) = |m(x) − b_i|,  m(x) = [p_x, p_y, h_tag]ᵀ       (the ToA term of thesis eq. 2.4)
//   C = ∂h/∂x = (m − b_i)ᵀ/h on p_x, p_y, 0 elsewhere
// with the tag at a known height h_tag (2D). Anchors that report at different instants need no
// merging (each range is an update at its own time stamp), a single anchor still constrains the
// track between the others' reports, and the gate α acts per measurement, so one NLOS anchor is
// rejected while the others of the same instant are used (per-instant fixes lose the whole instant).
// Everything else is the framework of PositionFilter: any motion model (constant velocity, CTRA,
// augmented track model), re-acquisition after long rejections, RTS or fixed-lag smoothing, output on
// any grid, noise=auto by the innovation likelihood of eq. 4.13 (here over q, r_range and α).
// Optionally the state carries one constant offset per beacon, h = |m − b_i| + β_i (see RangeModel).
#include "core/estimation/NoiseEstimator.h"
#include "core/estimation/TimeGridRunner.h"
#include "plugins/positioning/PositionFilter.h"

#include <Eigen/Core>
#include <functional>
#include <optional>
#include <vector>

namespace athlos::positioning {

// One two-way range: distance (m) and the index of its beacon in RangeMeasurements::beacons.
struct RangeObservation {
    double range = 0.0;
    int beacon = 0;
};

struct RangeMeasurements {
    std::vector<double> t;  // s, non-decreasing (equal stamps allowed: several anchors at one instant)
    std::vector<RangeObservation> y;
    std::vector<Eigen::Vector3d> beacons;  // m, in the frame of the output

    std::size_t size() const { return t.size(); }
    // The measurements with t in [a, b], sharing the beacons.
    RangeMeasurements slice(double a, double b) const;
};

class RangeFilter {
public:
    struct Params {
        ModelKind model = ModelKind::ConstantVelocity;  // Pseudo is not available for ranges
        std::shared_ptr<const TrackGeometry> track;     // model=augmented
        NoiseSettings noise;                            // motion noise and the gate α
        double rRange = 0.01;                           // m², range measurement variance
        double tagHeight = 1.0;                         // m, z of the tag in the beacons' frame
        estimation::Smoothing smoothing = estimation::Smoothing::Rts;
        double lag = 0.5;         // s, fixed-lag smoothing
        double maxStep = 0.1;     // s, longest prediction step
        bool covariance = false;  // also return the position standard deviations at the output times
        bool offsets = true;      // estimate a constant range offset per beacon (≤ 8 beacons)
        double biasSigma = 0.2;   // m, prior standard deviation of each offset
        double qBias = 1e-6;      // m²/s, random-walk density of the offsets
    };

    struct Result {
        PositionFilterResult filtered;    // states at the output times, d² and flags per measurement
        std::vector<Eigen::Vector2d> sd;  // σ_x, σ_y (m) per output time (Params::covariance)
        Eigen::Vector2d start = Eigen::Vector2d::Zero();
        std::vector<double> offsets;  // m per beacon (smoothed, mid-recording); empty without offsets
    };

    using ProgressFn = PositionFilter::ProgressFn;

    explicit RangeFilter(Params params);

    // Filters the ranges; output at tOut (empty: at the measurement times). An error when no
    // starting position can be found (fewer than 3 beacons with a range in the first seconds).
    Expected<Result> run(const RangeMeasurements& in, const std::vector<double>& tOut,
                         const ProgressFn& progress = {}) const;
    // J(Θ) of eq. 4.13 for the current noise settings (forward pass, no smoothing); +∞ without a start.
    double objective(const RangeMeasurements& in) const;

    // noise=auto: the motion model's q, r_range and α minimising the summed objective of the runs.
    static PositionFilter::Estimate estimateNoise(const Params& params, const std::vector<RangeMeasurements>& runs,
                                                  double& rRange, const estimation::NoiseEstimator::Params& search,
                                                  const ProgressFn& progress = {});
    // Every beacon's measurements at least `spacing` s apart (the first of each stretch kept): range
    // errors (multipath) are correlated over fractions of a second, and the innovation likelihood of
    // eq. 4.13 assumes white noise — on the raw 10 Hz series it explains the slow error as motion and
    // picks a range variance far below the real one.
    static RangeMeasurements thinned(const RangeMeasurements& in, double spacing);
    // Windows of `duration` s spread over the recording for estimateNoise (see PositionFilter::noiseChunks).
    static std::vector<RangeMeasurements> noiseChunks(const RangeMeasurements& in, double duration, int count);
    // Robust range variance per beacon from second differences of its series (MAD), the median over beacons.
    static double roughRangeVariance(const RangeMeasurements& in);
    // Starting position: least squares Σ (|m − b_i| − d̃_i)² over a grid and Gauss–Newton, d̃_i the median
    // range of beacon i in the first `window` seconds (extended until 3 beacons have reported).
    static std::optional<Eigen::Vector2d> initialPosition(const RangeMeasurements& in, double tagHeight,
                                                          double window = 1.0);

    const Params& params() const { return params_; }

private:
    Params params_;
};

}  // namespace athlos::positioning
