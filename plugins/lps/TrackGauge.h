#pragma once
// Track gauge of the LPS calibration (thesis §3.1.2 step 6: "rotate/translate the frame to venue
// marks, e.g. home straight along x", with the running track itself as the venue mark).
//
// TDoA with the reference node r fixed leaves one rotation θ about r's vertical axis unobservable
// (LpsCalibration.h). When the calibration walk follows the track, the walk's tag positions p_k
// must lie on a line parallel to the track's reference line (a lane's running line, or the walker
// a little outside it): constant lateral offset d. The fit
//     min_{θ, d} Σ_k ρ( d_track(r + R(θ)(p_k − r)) − d )
// (d_track = signed lateral offset of TrackGeometry::query, ρ = Cauchy, scale from the MAD,
// Gauss–Newton on the 2 unknowns) gives θ from the venue instead of from the guessed beacons.
// The track's pose (TrackGeometry::pose) places it in the LPS frame; the translation is not
// fitted — the reference node fixes it.
//
// Acceptance (decided by the caller, see LpsCalibration::Params): residual RMS of the inliers,
// share of inliers, coverage of the lap (share of 10 m bins of the reference line holding inliers,
// and for an oval both bends), and agreement of θ with the guess-based gauge within a few σ.
#include "core/geometry/TrackGeometry.h"
#include "plugins/lps/Tdoa.h"

#include <vector>

namespace athlos::lps {

struct TrackGaugeFit {
    bool valid = false;          // enough points and the normal equations were regular
    double rotation = 0.0;       // rad, θ to apply about the pivot's vertical axis (counter-clockwise)
    double sigmaRotation = 0.0;  // rad, 1σ of θ from the fit (residual scale and geometry)
    double lateralOffset = 0.0;  // m, d of the fitted parallel line (lateral offset from the reference line)
    double rms = 0.0;            // m, RMS residual of the inliers after the fit
    double inlierShare = 0.0;    // inliers / points (|e| ≤ 3 robust σ, at least 0.3 m)
    double coverage = 0.0;       // share of the reference line's 10 m bins holding inliers
    bool bothBends = false;      // oval: inliers on both bends (always true for a polyline)
    int points = 0, inliers = 0, iterations = 0;
};

// Fits θ and d to horizontal tag positions (z ignored). Needs at least 10 points.
TrackGaugeFit fitTrackGauge(const std::vector<Vector3>& points, const Vector3& pivot, const TrackGeometry& track);

// Rotates every beacon about the pivot's vertical axis by θ (the reference node stays).
void rotateLayout(BeaconLayout& layout, double rotation);

}  // namespace athlos::lps
