#pragma once
// Position filtering of 2D LPS tracks: one non-template front end over the filter × model matrix
// (EKF / UKF / SRUKF × unconstrained CTRA / constant velocity / pseudo-measurement / augmented
// track model), the robust time-grid runner, and noise estimation from the data (eq. 4.13).
#include "core/estimation/NoiseEstimator.h"
#include "core/estimation/TimeGridRunner.h"
#include "core/estimation/Ukf.h"
#include "core/geometry/TrackGeometry.h"
#include "plugins/positioning/Ctra.h"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace athlos::positioning {

enum class FilterKind { Ekf, Ukf, SrUkf };
enum class ModelKind { Unconstrained, Pseudo, Augmented, ConstantVelocity };

// Every noise quantity any model uses (variances; Q entries are densities per second).
struct NoiseSettings {
    CtraNoise ctra;
    double qAccelCv = 1.0;    // m²/s³, constant-velocity model
    double rHeading = 0.01;   // rad², pseudo-measurements
    double rTurnRate = 0.01;  // rad²/s²
    double rAccel = 0.1;      // m²/s⁴
    double gate = 16.0;       // α on d²
};

struct PositionSamples {
    std::vector<double> t;
    std::vector<Eigen::Vector2d> p;
};

struct PositionFilterResult {
    std::vector<double> t;
    std::vector<Kinematics> states;
    std::vector<double> mahalanobis2;  // per input sample
    std::vector<double> logDetSigma;   // per input sample
    std::vector<char> outlier;         // per input sample: 1 = gated out
    bool cancelled = false;
};

class PositionFilter {
public:
    struct Params {
        FilterKind filter = FilterKind::Ekf;
        ModelKind model = ModelKind::Augmented;
        std::shared_ptr<const TrackGeometry> track;  // required for pseudo / augmented
        NoiseSettings noise;
        estimation::Smoothing smoothing = estimation::Smoothing::None;
        double lag = 0.5;         // s, fixed-lag smoothing
        double maxStep = 0.1;     // s, longest prediction step (outages are crossed in steps)
        bool cvSwitch = true;     // track models: a = 0 after the acceleration phase
        double accelPhase = 6.0;  // s of constant acceleration after the detected start
        double bridgeGap = 2.0;   // s: augmented model with RTS, outages at least this long are bridged
                                  // along the track (TrackGapBridge); 0 = off
        estimation::UnscentedParams unscented;
    };

    using ProgressFn = std::function<bool(double)>;  // fraction; false = cancel

    explicit PositionFilter(Params params);

    // Filters samples; output at tOut (empty = at the input times).
    PositionFilterResult run(const PositionSamples& in, const std::vector<double>& tOut,
                             const ProgressFn& progress = {}) const;
    // J(Θ) of eq. 4.13 for the current noise settings (forward pass at the input times, no smoothing).
    double objective(const PositionSamples& in) const;

    // Estimates the model's noise parameters and α from one or more runs (no ground truth): the
    // summed objective over the runs, minimised by the multi-start Nelder–Mead of NoiseEstimator.
    struct Estimate {
        NoiseSettings noise;
        double objective = 0.0;
        int evaluations = 0;
        bool cancelled = false;
        std::vector<std::pair<std::string, double>> values;  // the estimated parameters by name
    };
    static Estimate estimateNoise(const Params& params, const std::vector<PositionSamples>& runs,
                                  const estimation::NoiseEstimator::Params& search, const ProgressFn& progress = {});

    // A representative subsample for estimateNoise(): `count` windows of `duration` seconds spread
    // evenly over the fixes (the whole input when it is shorter than count × duration). The noise of a
    // device does not change within a session, so a 90-min match needs no 54 000-sample estimate.
    static std::vector<PositionSamples> noiseChunks(const PositionSamples& fixes, double duration, int count);
    // The windows [a, a + duration] of noiseChunks over [t0, t1], evenly spread; empty when the span is not
    // longer than count × duration (then the whole input is used). Shared with RangeFilter::noiseChunks.
    static std::vector<std::pair<double, double>> chunkWindows(double t0, double t1, double duration, int count);
    // Uniform grid on multiples of 1/rate covering [tBegin, tEnd].
    static std::vector<double> outputGrid(double tBegin, double tEnd, double rate);
    // Rough measurement variance from the data: MAD of second differences (robust to outliers).
    static double roughMeasurementVariance(const PositionSamples& in);
    // Time the athlete starts moving (first robustly detected displacement > 2 m), for the CA → CV switch.
    static double detectStart(const PositionSamples& in);

    const Params& params() const { return params_; }

private:
    Params params_;
};

}  // namespace athlos::positioning
