#include "core/geometry/TrackPlacement.h"

#include <Eigen/Geometry>
#include <cmath>

namespace athlos {

Expected<TrackPlacement> placeOval(const TrackGeometry& oval, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                   double maxResidual) {
    if (oval.kind() != TrackGeometry::Kind::Oval)
        return makeError(QStringLiteral("track: '%1' is not an oval").arg(oval.name()));
    if (!(maxResidual > 0) || !std::isfinite(maxResidual))
        return makeError(QStringLiteral("max_residual must be a positive number of metres"));
    if (!a.allFinite() || !b.allFinite()) return makeError(QStringLiteral("straight: the two points must be finite"));
    const double straight = oval.ovalParams().straightLength, measured = (b - a).norm();
    if (!(measured > 0)) return makeError(QStringLiteral("straight: the two ends of the home straight coincide"));
    const double residual = 0.5 * std::abs(measured - straight);
    if (residual > maxResidual)
        return makeError(QStringLiteral("straight: the two ends are %1 m apart, the home straight of '%2' is %3 m "
                                        "(each end %4 m off, max_residual %5 m)")
                             .arg(measured, 0, 'f', 2)
                             .arg(oval.name())
                             .arg(straight, 0, 'f', 2)
                             .arg(residual, 0, 'f', 2)
                             .arg(maxResidual));
    const double rotation = std::atan2(b.y() - a.y(), b.x() - a.x());
    const Eigen::Vector2d origin =
        0.5 * (a + b) + Eigen::Rotation2Dd(rotation) * Eigen::Vector2d(0.0, oval.ovalParams().kerbRadius);
    TrackPlacement placed{oval, {residual, residual}};
    placed.track.setPose({origin.x(), origin.y(), rotation});
    return placed;
}

Expected<TrackPlacement> placePolyline(const std::vector<Eigen::Vector2d>& points, bool closed, const QString& name) {
    if (points.size() < 2)
        return makeError(QStringLiteral("points: a polyline needs at least 2 points, got %1").arg(points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (!points[i].allFinite()) return makeError(QStringLiteral("points: point %1 is not finite").arg(i + 1));
        if (i > 0 && (points[i] - points[i - 1]).norm() <= 0.0)
            return makeError(QStringLiteral("points: points %1 and %2 coincide").arg(i).arg(i + 1));
    }
    TrackGeometry::PolylineParams params;
    params.points = points;
    params.closed = closed;
    return TrackPlacement{TrackGeometry::polyline(std::move(params), name), std::vector<double>(points.size(), 0.0)};
}

}  // namespace athlos
