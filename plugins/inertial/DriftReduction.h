#pragma once
// Offline drift reduction of segment orientations (spec §2–§3; Fasel 2017 ch. 2, 5 and 6).
//
// (a) Static correction (ch. 2, Eq. 2.7): at every rest interval of a sensor, the inclination error is
//     the rotation taking the measured specific force (rotated to the earth frame) onto the vertical;
//     it is spread between consecutive rest instants by SLERP and held before the first and after the
//     last. Azimuth is not observable this way.
// (b) Joint drift reduction (ch. 5, Eqs. 5.1–5.14; ch. 6, Eqs. 6.8–6.13): two segments linked by a
//     ball joint see the same joint-centre acceleration. Each sensor's virtual joint acceleration is
//     ã = a + ω̇ × r + ω × (ω × r) (Eqs. 5.3–5.4; ω zero-phase low-passed at 6 Hz, 2nd-order
//     Butterworth), rotated to the earth frame with the drifting orientation (Eqs. 5.1–5.2). The
//     sensor-to-joint vectors r_p, r_d minimise Σ|ã_d^G − ã_p^G| (Eq. 5.5) over samples with
//     |ω_proximal| > 40°/s by Nelder–Mead. Valid drift samples: ||ã_d| − |ã_p|| < 2.5 m/s² and
//     |ã_d|, |ã_p| > 8 m/s² (Eqs. 5.6–5.8; indoor preset: > 6 m/s² and relative difference < 0.2,
//     Eqs. 6.9–6.11); the drift of each sample is averaged over [t − 1.25 s, t + 1.25 s]. Order
//     (Eqs. 5.12–5.14): the root (sacrum) is turned by the mean of its drifts against all its
//     neighbours, then every distal segment is corrected against its already corrected proximal one
//     (sacrum → thighs → shanks → feet, sacrum → sternum). A second pass repeats this on horizontal
//     components with a norm threshold of 0.6 m/s² (Eqs. 6.12–6.13) for the azimuth drift.
//
// Where this departs from the thesis, and why (each measured on BodySimulator, see
// docs/validation/drift-reduction.md):
// - r is fitted with one free rotation per block of 2.5 s in Eq. 5.5 (Kabsch), because the drift in
//   the orientations biased r by several centimetres otherwise.
// - The window's drift is by default the rotation that best maps all valid ã_d^G onto ã_p^G of the
//   window (Wahba's problem, Estimator::Wahba). The thesis's estimator — per-sample smallest rotation
//   (Eqs. 5.9–5.11) averaged with the Markley quaternion mean (Estimator::Markley) — is kept; it is
//   blind to the part of the drift about each vector, and here its correction stalled at 2–4°.
// - Before the passes, a constant heading offset per joint is removed in chain order (least-squares
//   rotation about the vertical between the horizontal parts of ã_d^G and ã_p^G over the recording,
//   the principle of Fasel 2017 ch. 7 for the arms' azimuths): 6D orientations from `orientation`
//   have independent headings. The heading is fitted only on the samples whose horizontal ã exceed
//   the azimuth pass's threshold (Eqs. 6.12–6.13): in walking the hip joint centre's horizontal
//   acceleration is below it on ~99 % of samples, and a heading fitted on all of them came out
//   110–170° wrong. A joint with too few such samples, or whose samples disagree (coherence below
//   minHeadingCoherence), has an unobservable heading and is left uncorrected (LinkResult::heading).
// - In the r fit each block's rotation is pulled weakly towards the blocks' common rotation (fitPrior).
#include "core/math/Angles.h"
#include "core/math/QuaternionOps.h"
#include "plugins/inertial/RestDetector.h"

#include <functional>
#include <vector>

namespace athlos::inertial {

class DriftReduction {
public:
    struct Params {
        // Joint drift (Fasel 2017 ch. 5 on snow; see onSnow()/indoor()).
        double gyrCutoff = 6.0;                     // Hz, low-pass of ω (Eqs. 5.3–5.4, Mester 1992)
        double omegaThreshold = 40.0 * math::kDeg;  // rad/s, |ω_proximal| for the r optimisation (Eq. 5.5)
        double maxNormDifference = 2.5;             // m/s², ||ã_d| − |ã_p|| (Eq. 5.6)
        double maxRelativeDifference = 0.0;         // ||ã_d| − |ã_p|| / mean norm (Eq. 6.11); 0 = not used
        double minNorm = 8.0;                       // m/s², |ã_d|, |ã_p| (Eqs. 5.7–5.8)
        double window = 1.25;                       // s, half width of the Markley mean (ch. 5)
        bool azimuthPass = true;                    // second pass on horizontal components (ch. 6)
        double azimuthMinNorm = 0.6;                // m/s², threshold of the azimuth pass (Eqs. 6.12–6.13)
        // The constant heading of a joint (alignHeading) is fitted on the samples whose horizontal ã both
        // exceed azimuthMinNorm (the azimuth pass's condition) and accepted only with at least as many of
        // them as a window needs (minWindowSamples, minWindowShare) and a weighted mean resultant length
        // of their heading differences (circular statistics, Mardia & Jupp 2000 §2.3) of at least this:
        // 0.5 ≈ a circular standard deviation of 68° per sample. Otherwise the joint's heading is
        // unobservable: it keeps the relative heading of its input (align it at the start, joint-angles
        // heading=align-start) and only its inclination drift is corrected.
        double minHeadingCoherence = 0.5;
        // Repetitions of the (3D, azimuth) passes. The drift of one sample is the smallest rotation between
        // two vectors, blind to the part about the vectors themselves, so one pass removes only part of
        // the drift; repeating converges (an addition to Fasel 2017, which applies each pass once).
        int iterations = 1;
        // How the drift of a window is found from its valid samples (see the file comment):
        // Markley — per-sample smallest rotation ã_d → ã_p (Eqs. 5.9–5.11) averaged with the Markley mean
        // (Fasel 2017); Wahba — the one rotation that best maps all ã_d onto ã_p of the window in the
        // least-squares sense (Wahba's problem, solved by SVD; Markley 1988), evaluated every wahbaStep s
        // and interpolated by SLERP.
        enum class Estimator { Markley, Wahba };
        Estimator estimator = Estimator::Wahba;
        double wahbaStep = 0.05;            // s
        // The correction passes' drift estimates (virtual accelerations, valid samples, window sums) use
        // every k-th sample, k the largest whole number with rate / k ≥ estimationRate (500 Hz → every
        // 5th; 100 Hz and below: every sample); the correction is still applied to every sample. The drift
        // changes over seconds and a window (±1.25 s) still holds 250 samples at 100 Hz. On the simulated
        // 500 Hz skiing run (10 seeds) the joint-angle RMSE moved by ≤ 0.01° (at 50 Hz by ≤ 0.04°) while
        // the passes ran about 4× faster; in walking, where few samples are valid, the hip rotation got
        // 0.1–0.2° worse, so the indoor preset uses every sample (docs/validation/drift-reduction.md).
        // 0 = every sample. The Markley estimator always uses every sample.
        double estimationRate = 100.0;      // Hz
        bool alignHeading = true;           // remove a constant heading offset per joint first
        int minWindowSamples = 5;           // valid drift samples a window needs for an estimate …
        double minWindowShare = 0.1;        // … and this share of the window's samples
        int minFitSamples = 200;            // fewer samples above omegaThreshold: also use |ω_distal| (see .cpp)
        int maxOptimisationSamples = 3000;  // evenly thinned set for the Nelder–Mead cost
        double fitBlock = 2.5;              // s, blocks with their own rotation in the r fit (see .cpp)
        int maxFitBlocks = 60;              // at most this many blocks (the cost of the fit grows with them)
        // Pull of each block's rotation towards the blocks' common rotation, relative to the block's
        // ‖Σ ud upᵀ‖ (the same weak prior as the window solution's pull to the identity): a block whose
        // vectors are all close to gravity leaves the rotation about them free, and in walking r then
        // fell into a second minimum 15 cm from the truth (docs/validation/drift-reduction.md).
        double fitPrior = 0.01;
        bool jointCorrection = true;
        // Static correction (Fasel 2017 ch. 2; rest detection as in VQF). Its model is the integrated
        // gyroscope's (strap-down): an inclination error that grows between rests, so the error found at
        // each rest is spread back over the motion before it. A filter that corrects its inclination
        // with the accelerometer (VQF, Madgwick, Mahony, Kalman, offline VQF) already uses the rests, and
        // its error at a rest right after motion is a transient that decays within seconds; spread back
        // over the motion it made the absolute inclination worse (skiing simulation with VQF: 3.2° →
        // 6.7°, joint angles unchanged). staticCorrectionSuits() (DriftReductionProcessor.h) is that rule.
        bool staticCorrection = true;
        RestDetector::Params rest;
    };
    static Params onSnow() { return {}; }
    static Params indoor() {
        Params p;
        p.minNorm = 6.0;
        p.maxNormDifference = 1e9;
        p.maxRelativeDifference = 0.2;
        p.estimationRate = 0.0;
        return p;
    }

    struct Segment {
        std::vector<math::Quat> q;         // sensor → earth (ENU), drifting
        std::vector<math::Vec3> acc, gyr;  // sensor frame, m/s², rad/s; same length as q
    };
    struct Link {
        int proximal = 0, distal = 0;  // indices into the segment list
    };
    enum class HeadingStatus {
        NotAligned,     // alignHeading off
        Aligned,        // constant heading offset removed, headings corrected by the passes
        TooFewSamples,  // too few samples with horizontal ã above azimuthMinNorm: heading kept
        Incoherent      // their heading differences disagree (coherence < minHeadingCoherence): heading kept
    };
    struct LinkResult {
        math::Vec3 proximalToJoint = math::Vec3::Zero(), distalToJoint = math::Vec3::Zero();  // sensor frames (m)
        double headingOffset = 0.0;      // rad, removed from the distal segment before the passes
        double validShare = 0.0;         // share of samples used in the first pass (Eqs. 5.6–5.8)
        double azimuthValidShare = 0.0;  // … in the azimuth pass
        double meanCorrection = 0.0;     // rad, mean angle of the applied smoothed drift (both passes; every wahbaStep)
        int optimisationSamples = 0;
        bool distalExcitation = false;  // the fit also used samples where only the distal segment turned
        double optimisationCost = 0.0;  // m/s², mean |ã_d^G − ã_p^G| at the optimum
        HeadingStatus heading = HeadingStatus::NotAligned;
        int headingSamples = 0;         // samples the heading was fitted on
        double headingCoherence = 0.0;  // their weighted mean resultant length (0–1)
    };
    struct Result {
        std::vector<std::vector<math::Quat>> q;  // corrected, same layout as the input
        std::vector<LinkResult> links;
        std::vector<int> restIntervals;  // per segment
    };
    // Progress callback: fraction done; returns false to cancel (the result is then empty).
    using Progress = std::function<bool(double)>;

    explicit DriftReduction(const Params& params) : params_(params) {}
    // links: proximal → distal pairs forming a tree; the root is the one segment that is never distal.
    Result run(const std::vector<Segment>& segments, const std::vector<Link>& links, double ts,
               const Progress& progress = {}) const;

    // Building blocks (exposed for tests).
    // Zero-phase (forward–backward) 2nd-order Butterworth low-pass of a 3-channel signal.
    static std::vector<math::Vec3> zeroPhaseLowPass(const std::vector<math::Vec3>& x, double cutoff, double ts);
    // Markley et al. 2007 mean of unit quaternions (the eigenvector of Σ q qᵀ with the largest eigenvalue).
    static math::Quat markleyMean(const std::vector<math::Quat>& q);
    // Per-sample solution of Wahba's problem over the valid pairs within ±halfWidth samples (rotation R
    // minimising Σ|R from − to|², pulled towards the identity by `prior`), computed every `step` samples
    // and interpolated by SLERP; with aboutVertical, R is restricted to rotations about earth z (the
    // azimuth pass). With stride > 1 the inputs are every stride-th sample (i ↦ output sample i·stride;
    // halfWidth, step in input samples) and out gets max(outSize, (n − 1)·stride + 1) samples. Returns
    // false when no window had minCount valid pairs (all identity then).
    static bool windowedWahba(const std::vector<math::Vec3>& from, const std::vector<math::Vec3>& to,
                              const std::vector<unsigned char>& valid, std::size_t halfWidth, std::size_t step,
                              int minCount, bool aboutVertical, std::vector<math::Quat>& out, double prior = 0.01,
                              std::size_t stride = 1, std::size_t outSize = 0);
    // Per-sample Markley mean of the valid quaternions within ±halfWidth samples; samples whose window
    // holds fewer than minCount valid ones are filled by SLERP between neighbours (held at the ends).
    // Returns false when no sample could be estimated (all identity then).
    static bool windowedMean(const std::vector<math::Quat>& q, const std::vector<unsigned char>& valid,
                             std::size_t halfWidth, int minCount, std::vector<math::Quat>& out);

private:
    Params params_;
};

}  // namespace athlos::inertial
