#pragma once
// Beacon selection against NLOS readings (thesis §3.2): which readings of one instant enter the
// fix of Eqn. 2.5, always keeping at least B_min = 4 (over-determined planar fix).
//   All             every reading, equal weights (baseline, method 1)
//   Irls            iteratively reweighted LS, bisquare weights, zero above k·MAD (method 6, k = 2.5)
//   LargestResidual drop the reading with the largest |e_i| until the mean |e| of the rest is below
//                   a threshold (method 8)
//   FieldOfView     keep beacon i if G_t(φ_i) − L_fs(m̂_ini, b_i) + κ > 0   (Eqn. 3.8–3.10), the
//                   proposed method: φ_i is the bearing to the beacon relative to the body heading,
//                   m̂_ini the median of the last five fixes. Without such a history (start, gaps)
//                   the fix falls back to LargestResidual. With fovRefine, LargestResidual then
//                   runs on the beacons in view, choosing by leave-one-out (an addition of this
//                   project, see docs).
//   AllSubsets      method 4, after Cong & Zhuang (2005) as the thesis adapts it (§3.2.3): solve for every
//                   hypothesis of which readings are NLOS (weight 0, the rest equal), sum each reading's
//                   |e_i| over all hypotheses, bisquare weights from the sums, final fix. Hypotheses with
//                   at most `subsetMaxExcluded` NLOS readings (all 2^B with 0 = no limit, B ≤ 16).
//   BestSubset      method 5 (Cong & Zhuang 2001): every combination of B_best = 5 readings is solved;
//                   the one with the lowest RMS residual is the fix.
#include "plugins/lps/GainPattern.h"
#include "plugins/lps/TdoaSolver.h"

#include <deque>

namespace athlos::lps {

class BeaconSelection {
public:
    enum class Method { All, Irls, LargestResidual, FieldOfView, AllSubsets, BestSubset };

    struct Params {
        Method method = Method::Irls;
        int minBeacons = 4;
        double irlsK = 2.5;          // bisquare cut-off in units of the (σ-scaled) MAD
        double irlsMinScale = 0.05;  // m, floor of 1.4826·MAD (noise-free data has MAD → 0)
        int irlsIterations = 10;
        double rejectionThreshold = 0.25;  // m, mean |e| at which LargestResidual stops
        double kappa = 100.0;  // dB, κ of Eqn. 3.8 for the default pattern (grid search, docs/validation/lps.md)
        // After the field-of-view selection, leave-one-out rejection among the beacons in view (drop the
        // reading whose removal leaves the smallest mean |e|, down to B_min): removes the gross
        // outliers (late detections) a field of view cannot predict.
        bool fovRefine = true;
        // m; with fovRefine, a fix farther than this from m̂_ini (median of the last five fixes,
        // ≈ 0.2–0.3 s behind at 10 Hz: ~2 m at sprint speed) is re-solved from m̂_ini with IRLS over
        // all readings (grid 1.5…8 m on seed 777, docs/validation/lps.md).
        double fovMaxJump = 4.0;
        double frequency = 5.8e9;   // Hz, carrier of the thesis' LPS (free-space loss)
        int bestSubsetSize = 5;     // B_best of method 5 ("yielded the best results in [Cong 01]", §3.2.3)
        int subsetMaxExcluded = 3;  // method 4: NLOS hypotheses with at most this many readings; 0 = all 2^B
        GainPattern gain;
    };

    // The body's view for the field-of-view rule: m̂_ini and the heading φ_body (rad, LPS frame).
    struct View {
        Vector3 position = Vector3::Zero();
        double heading = 0.0;
    };

    BeaconSelection() : BeaconSelection(Params()) {}
    explicit BeaconSelection(const Params& params) : params_(params) {}
    const Params& params() const { return params_; }

    // Selects (sets input.weights) and solves one instant. start: warm start or nullptr.
    TagFix solve(FixInput& input, TdoaSolver& solver, const TagFix* start, const View* view = nullptr) const;

    // Link margin G_t(φ_i) − L_fs(|m̂ − b_i|) + κ (dB) of a beacon; > 0 = in the field of view.
    double linkMargin(const Vector3& beacon, const View& view) const;
    // Free-space loss (Eqn. 3.9): 20 log10 d + 20 log10 f − 147.55 (d in m, f in Hz).
    double freeSpaceLoss(double distance) const;

    TagFix solveAll(FixInput& input, TdoaSolver& solver, const TagFix* start) const;
    TagFix solveIrls(FixInput& input, TdoaSolver& solver, const TagFix* start) const;
    TagFix solveLargestResidual(FixInput& input, TdoaSolver& solver, const TagFix* start) const;
    TagFix solveFieldOfView(FixInput& input, TdoaSolver& solver, const TagFix* start, const View& view) const;
    TagFix solveAllSubsets(FixInput& input, TdoaSolver& solver, const TagFix* start) const;
    TagFix solveBestSubset(FixInput& input, TdoaSolver& solver, const TagFix* start) const;

private:
    // Method 8's loop from the current weights and fix.
    TagFix rejectLargest(FixInput& input, TdoaSolver& solver, TagFix fix) const;
    // fovRefine: like rejectLargest, but drops the reading whose removal leaves the smallest mean |e|.
    // Method 6 restricted to the readings with mask > 0 (the others get weight 0 unless B_min needs them).
    TagFix solveIrlsWeighted(FixInput& input, TdoaSolver& solver, const TagFix* start,
                             const std::vector<double> mask) const;
    TagFix rejectLeaveOneOut(FixInput& input, TdoaSolver& solver, TagFix fix) const;
    Params params_;
};

// m̂_ini of the field-of-view rule: component-wise median of the last `size` valid fixes, forgotten
// after a gap longer than maxGap seconds.
class FixHistory {
public:
    explicit FixHistory(int size = 5, double maxGap = 2.0) : size_(size), maxGap_(maxGap) {}
    void push(const TagFix& fix);
    // Median position, or nothing while the history is empty or stale at time t.
    std::optional<Vector3> median(double t) const;
    // Direction of travel (rad) over the history, if it moved at least minDistance metres.
    std::optional<double> motionHeading(double t, double minDistance = 0.5) const;
    void clear() { fixes_.clear(); }

private:
    int size_;
    double maxGap_;
    std::deque<TagFix> fixes_;
};

}  // namespace athlos::lps
