#pragma once
// Placing a track from surveyed points, like a pitch from its corners (PitchGeometry): an oval by
// the two ends of its home straight, a polyline by its points, in the project's ENU frame (m; from
// lat/lon through the project's geodetic origin, Geodesy.h).
//
// Oval: A is the start and B the end (the finish line) of the home straight on the inner kerb, so
// the athletes run from A to B (TrackGeometry.h: home straight at y = −kerb radius towards +x). The
// pose follows: rotation = direction of A→B from East (counter-clockwise, rad), origin (the track's
// centre) = midpoint(A, B) + R(rotation)·(0, kerb radius). |AB| should be the straight length; the
// residual of each end is half the difference (the least-squares pose for a known length).
#include "core/geometry/TrackGeometry.h"
#include "core/util/Expected.h"

#include <Eigen/Core>
#include <array>
#include <vector>

namespace athlos {

struct TrackPlacement {
    TrackGeometry track;
    std::vector<double> residuals;  // m, per given point (oval: A, B; polyline: none, all 0)
};

// Refuses (naming the parameter) a straight whose measured length differs from the track's by more
// than 2·maxResidual.
Expected<TrackPlacement> placeOval(const TrackGeometry& oval, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                   double maxResidual);
// The points (≥ 2, consecutive points distinct) become the polyline; its pose is the identity.
Expected<TrackPlacement> placePolyline(const std::vector<Eigen::Vector2d>& points, bool closed, const QString& name);

}  // namespace athlos
