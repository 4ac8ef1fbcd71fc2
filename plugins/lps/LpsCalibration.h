#pragma once
// Automatic calibration of a TDoA LPS (thesis §3.1.2, Fig. 3.2): beacon positions Θ from a
// calibration walk at constant height and a rough initial guess.
//
// Objective (Eqn. 3.2–3.3): nRMSR(Θ) = sqrt( (1/N) Σ_n |e_n(Θ)|² / B_n ), e_n the residuals of
// fix n (Eqn. 3.1) and B_n its number of beacons. The thesis minimises it with SQP over Θ and an
// inner Levenberg–Marquardt solve per fix; here the same objective is a bundle adjustment in Ceres
// over beacons, tag positions and offsets jointly (the inner solves become Schur-eliminated
// blocks), which is the same minimum at a fraction of the cost. Steps:
//   3  solve the fixes with the initial beacons;
//   4  Grubbs test on the fixes' residuals (whole fixes), then ~200 fixes spread over the area
//      (farthest-point sampling);
//   5–8 bundle adjustment: a Huber pass, a Grubbs test on the single readings' residuals (outliers
//      would otherwise be masked by the initial calibration error), then plain least squares until
//      nRMSR improves by less than 0.01 % per iteration (the thesis' stopping rule);
//      restarts from re-perturbed guesses while nRMSR stays above restartNrmsr (multi-start, §3.1.5).
//
// Gauge: TDoA with the reference node r fixed at the origin (or where the table says) determines
// everything except a rotation about the vertical axis through r (distances to r and between tags
// and beacons are unchanged by it; the tag plane stays horizontal). The initial guess fixes it: a
// weak Gaussian prior pulls every beacon towards its guess (σ priorSigmaXy/Z), and after the solve
// the whole solution is explicitly rotated about r's vertical axis to best match the guess. The
// rotation left is therefore the guess' own: σ_θ ≈ σ_guess/√(Σ r_i²) (≈ 4 mrad, 0.2 m at 50 m, for
// σ_guess = 1 m around a 400 m track).
// Track gauge (gauge = Auto or Track, TrackGauge.h; thesis step 6 "rotate the frame to venue
// marks"): when the walk follows the track, the walk's fixes, re-solved with the calibrated
// beacons, are fitted to a line parallel to the track (rotation θ about r plus a lateral offset,
// Cauchy-robust), and the solution is rotated by θ. Auto accepts θ only if the fit is tight
// (inlier RMS ≤ gaugeMaxRms, inlier share ≥ gaugeMinInliers), the walk covers the lap (coverage ≥
// gaugeMinCoverage and, on an oval, both bends) and θ agrees with the guess-based gauge within
// gaugeAgreementSigmas·√(σ_θ,guess² + σ_θ,fit²); otherwise it keeps the guess-based rotation and says why.
// Rough guesses (σ 5–20 m, aerial image or GNSS; issue #16 item 5). Three failure modes of the plain
// bundle adjustment and their remedies:
//  - The prior σ (priorSigmaXy/Z) far tighter than the real guess error pulls the weakly observable
//    heights towards the wrong guessed ones. Empirical prior (adaptPrior): the first start's
//    horizontal shifts from the guess (well observable) estimate the guess error σ̂ =
//    √(Σ|Δxy|²/2B); when σ̂ > adaptPriorFactor·priorSigmaXy the start is re-run with the prior
//    widened to σ̂ (σz scaled alike), and the later starts restart around that solution.
//  - Mirror ambiguity: a planar walk sees a beacon at height z and its reflection 2h − z in the
//    walk plane alike, except through the one distance |r − b_i| (r 1 m below the walk plane
//    here). A guess on the wrong side ends in the reflected minimum (in the study: beacons 10–15 m
//    too low, the walk plane dragged to r's height, η ≈ 1.3). Height plausibility
//    (beaconsAboveWalk): beacons are mounted above the walking tag, so starts and solutions below
//    h + minBeaconClearance are reflected back and re-adjusted; with beaconsAboveWalk off each
//    beacon's reflection is tried and kept when nRMSR drops (mirrorTest).
//  - Flat valley of the heights: nRMSR changes by < 0.01 % per iteration while the heights still
//    move by metres; the final least-squares pass runs to finalTolerance.
// Track constraint (trackConstraint, with gauge auto|track): one extra start with every tag of the
// walk on a line parallel to the track (residual (d_track(m_n) − d)/σ_track, Cauchy beyond
// trackSigmaOutlier, d shared, the tags started on the line). It replaces the free solution when
// ≥ gaugeMinInliers of its tags lie within 3σ_track of the line — a criterion that, unlike
// nRMSR, sees a wrong geometry (the free wrong minimum warps the walk off the track).
// Walk height: one unknown shared by all fixes (weak prior walkHeightPrior ± walkHeightSigma),
// observable through r; a given walkHeight fixes it.
#include "core/util/Expected.h"
#include "core/util/Progress.h"
#include "plugins/lps/BeaconGeometry.h"
#include "plugins/lps/Tdoa.h"
#include "plugins/lps/TrackGauge.h"

#include <cstdint>
#include <limits>

namespace athlos::lps {

class LpsCalibration {
public:
    enum class OutlierTest { Grubbs, Mad };
    // Where the rotation about the reference node's vertical axis comes from (see above).
    enum class Gauge { Auto, Guess, Track };
    // Beacon geometry (BeaconGeometry.h) of the guess and of the result: a layout whose horizontal
    // positions are not observable (too few, clustered, collinear) is refused or only reported.
    enum class GeometryCheck { Refuse, Warn };

    struct Params {
        double walkHeight = std::numeric_limits<double>::quiet_NaN();  // m; NaN = estimate
        double walkHeightPrior = 1.0;                                  // m
        double walkHeightSigma = 0.5;                                  // m
        int calibrationFixes = 200;                                    // thesis: 200 training fixes; 0 = all
        int minBeacons = 4;
        OutlierTest outlierTest = OutlierTest::Grubbs;
        double alpha = 0.05;              // Grubbs significance
        double madK = 4.0;                // MAD test: |e − med| > madK·1.4826·MAD
        double rangeNoise = 0.1;          // m, nominal TDoA noise (weights data against the prior)
        double priorSigmaXy = 2.0;        // m, initial guess uncertainty
        double priorSigmaZ = 1.0;         // m
        double huberScale = 0.5;          // m, first (robust) pass
        double relativeTolerance = 1e-4;  // stop when nRMSR improves by less than 0.01 %
        // Final least-squares pass: the heights lie in a flat valley where nRMSR changes by < 0.01 %
        // per iteration while they still move by metres; this pass runs to this tolerance.
        double finalTolerance = 1e-9;
        int maxIterations = 200;
        int maxStarts = 5;
        double restartNrmsr = 0.3;    // m; above this after a start, restart from a re-perturbed guess
        double restartSigmaXy = 2.0;  // m
        double restartSigmaZ = 1.0;   // m
        std::uint64_t seed = 1;
        Gauge gauge = Gauge::Auto;
        TrackGeometry track;            // in LPS coordinates (its pose); default: iaaf-400m at the origin
        double gaugeMaxRms = 0.5;       // m, inlier RMS of the track fit
        double gaugeMinInliers = 0.8;   // share of the walk's fixes within the fit's inlier band
        double gaugeMinCoverage = 0.5;  // share of the reference line's 10 m bins the walk visits
        double gaugeAgreementSigmas = 3.0;
        // m, horizontal σ of the initial guess for the agreement test; NaN = priorSigmaXy (as widened
        // by adaptPrior). Set it
        // when the guess is known to be worse than the prior assumes (the prior also weights the fit).
        double gaugeGuessSigma = std::numeric_limits<double>::quiet_NaN();
        GeometryCheck geometryCheck = GeometryCheck::Refuse;
        BeaconGeometryParams geometry;
        bool adaptPrior = true;           // widen the prior to the guess error the first start finds
        double adaptPriorFactor = 1.5;    // ... when it exceeds priorSigmaXy by this factor
        bool beaconsAboveWalk = true;     // height plausibility: beacons above the walk plane
        double minBeaconClearance = 0.5;  // m, least height of a beacon above the walk plane
        bool mirrorTest = true;
        double mirrorMinGain = 1e-3;     // relative nRMSR decrease that accepts a reflected beacon
        bool trackConstraint = true;     // an extra start with the walk's tags on a track-parallel line
        double trackSigma = 0.3;         // m, σ of the walk's lateral offset about its line (track constraint)
        double trackSigmaOutlier = 1.0;  // m, Cauchy scale of the track constraint (walker off the line)
        double trackMaxLateral = 10.0;   // m, start value of the lateral offset clamped to ± this
    };

    struct GaugeReport {
        Gauge requested = Gauge::Auto;
        Gauge used = Gauge::Guess;  // Guess or Track
        QString reason;             // why the track rotation was (not) used
        double rotation = 0.0;      // rad, applied on top of the guess-based gauge (0 for Guess)
        double sigmaGuess = 0.0;    // rad, σ_θ of the guess-based gauge
        TrackGaugeFit fit;          // track fit (fit.valid false when not attempted or impossible)
    };

    struct BeaconReport {
        double rmsResidual = 0.0;  // m, over the calibration fixes
        int readings = 0;
        double shift = 0.0;  // m, distance from the initial guess
    };

    struct Report {
        double nrmsrInitial = 0.0;     // m, calibration fixes solved with the initial beacons
        double nrmsrCalibrated = 0.0;  // m, same fixes with the calibrated beacons
        double nrmsrReference = std::numeric_limits<double>::quiet_NaN();          // with reference beacons, if given
        double etaInitial() const { return nrmsrInitial / nrmsrReference; }        // Eqn. 3.6
        double etaCalibrated() const { return nrmsrCalibrated / nrmsrReference; }  // Eqn. 3.7
        int epochs = 0, fixesUsed = 0, fixesRemoved = 0, readingsRemoved = 0;
        int starts = 0, iterations = 0;
        double priorSigmaXy = 0.0;      // m, prior σ used in the end (widened by adaptPrior)
        bool poorGuess = false;         // the first start found the guess worse than the prior
        int mirrored = 0;               // beacon reflections in the walk plane (height plausibility)
        bool trackConstrained = false;  // the solution is the track-constrained start's
        double trackShare = std::numeric_limits<double>::quiet_NaN();  // its tags' share on the line
        double walkHeight = 0.0;
        bool converged = false;
        GaugeReport gauge;
        BeaconGeometryReport geometry;  // of the calibrated beacons, area = the walk
        QString geometryWarning;        // non-empty: what is not observable (2D or 3D)
        std::vector<BeaconReport> beacons;
    };

    struct Result {
        BeaconLayout beacons;
        Report report;
    };

    LpsCalibration() : LpsCalibration(Params()) {}
    explicit LpsCalibration(const Params& params) : params_(params) {}
    const Params& params() const { return params_; }

    // reference: surveyed beacons for η (optional). Errors say what is missing in the data.
    Expected<Result> run(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& initial,
                         const Progress& progress = {}, const BeaconLayout* reference = nullptr) const;

    // nRMSR (Eqn. 3.3) of the epochs, each solved on its own (planar at height, all readings).
    static double nrmsr(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& beacons, double height,
                        int minBeacons = 4);

    // Indices of `count` points spread over the set (greedy farthest-point sampling in xy).
    static std::vector<int> spreadSelection(const std::vector<Vector3>& points, int count);

    // σ_θ of the guess-based gauge: σ_xy/√(Σ horizontal |b_i − r|²).
    static double guessRotationSigma(const BeaconLayout& beacons, double sigmaXy);

    static const char* gaugeName(Gauge gauge);

private:
    struct Start;
    Expected<Start> adjust(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& start, const BeaconLayout& guess,
                           const Progress& progress, bool onTrack) const;
    double trackLineShare(const std::vector<Vector3>& tags, double lateral) const;
    Expected<GaugeReport> applyGauge(const std::vector<TdoaEpoch>& epochs, double height, BeaconLayout& beacons,
                                     double guessSigmaXy) const;
    Params params_;
};

}  // namespace athlos::lps
