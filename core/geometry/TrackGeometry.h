#pragma once
// Track geometry as data: an oval running track (World Athletics 400 m, 200 m indoor, any radius /
// straight length) or an arbitrary polyline (cycling track, skating oval, road), placed in LPS
// coordinates by a pose. Answers the questions a motion model, a simulator or a beacon selector
// asks: running direction (heading) and curvature at a position, with their gradients (for EKF
// Jacobians), nearest point, arc length and lateral offset, lane running lines.
//
// Track frame (ARCHITECTURE.md): oval centred at the origin, straights parallel to x, bend centres
// at (±(straight/2), 0), running counter-clockwise (home straight y < 0 towards +x, back straight
// y > 0 towards −x). Polylines run in vertex order. The pose maps track to LPS coordinates:
// p_lps = R(rotation) · p_track + (x, y).
//
// Track coordinates along the reference line: s = arc length (m) from the reference start, d =
// lateral offset (m) to the RIGHT of the running direction (outwards on a counter-clockwise oval).
// Oval reference line = inner kerb; s = 0 at the finish line (end of the home straight, x = +L/2,
// y = −r), so s runs: bend 1 (centre +L/2), back straight, bend 2 (centre −L/2), home straight.
#include "core/math/Angles.h"
#include "core/util/Expected.h"

#include <Eigen/Core>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <vector>

namespace athlos {

struct TrackPose {
    double x = 0.0;  // m, translation of the track origin in LPS coordinates
    double y = 0.0;
    double rotation = 0.0;  // rad, counter-clockwise rotation of the track frame
};

// Local description of the track at (the point of the reference line nearest to) a position.
// Heading and curvature are those of the line through the queried point parallel to the reference
// line (constant lateral offset), which is what a runner keeping a lane follows.
struct TrackQuery {
    Eigen::Vector2d nearest = Eigen::Vector2d::Zero();  // nearest reference-line point (LPS)
    double s = 0.0;                                     // arc length of `nearest` along the reference line (m)
    double d = 0.0;          // signed lateral offset, positive to the right of the running direction (m)
    double heading = 0.0;    // running direction at the point (rad, LPS frame, in (−π, π])
    double curvature = 0.0;  // signed curvature of the parallel line through the point (1/m, > 0 = left turn)
    Eigen::Vector2d headingGradient = Eigen::Vector2d::Zero();    // ∂heading/∂p (1/m), LPS frame
    Eigen::Vector2d curvatureGradient = Eigen::Vector2d::Zero();  // ∂curvature/∂p (1/m²), LPS frame
    int segment = 0;      // oval: 0 bend 1, 1 back straight, 2 bend 2, 3 home straight; polyline: segment index
    bool onBend = false;  // oval only: inside a bend sector
};

// A point on a line parallel to the reference line (for simulators): position, heading, curvature.
struct TrackPoint {
    Eigen::Vector2d position = Eigen::Vector2d::Zero();  // LPS
    double heading = 0.0;
    double curvature = 0.0;  // of the parallel line at offset d (1/m)
};

class TrackGeometry {
public:
    enum class Kind { Oval, Polyline };

    struct OvalParams {
        double kerbRadius = 36.50;      // m, inner kerb radius of the bends
        double straightLength = 84.39;  // m
        double laneWidth = 1.22;        // m
        int lanes = 8;
        double firstLaneLine = 0.30;  // m, lane 1 running line outside the kerb
        double otherLaneLine = 0.20;  // m, running line of lanes ≥ 2 outside their inner lane line
    };

    struct PolylineParams {
        std::vector<Eigen::Vector2d> points;  // track frame, in running order
        bool closed = false;
        double laneWidth = 1.0;  // m, for lane offsets (cycling, skating: set as needed)
        int lanes = 1;
    };

    TrackGeometry();  // = iaaf400m()
    static TrackGeometry oval(const OvalParams& params, QString name = {});
    static TrackGeometry polyline(PolylineParams params, QString name = {});
    static TrackGeometry iaaf400m();    // bend 36.50 m, straights 84.39 m, 8 lanes of 1.22 m
    static TrackGeometry indoor200m();  // bend 17.20 m, lane 1 running line exactly 200 m, 6 lanes of 1.00 m

    // Built-in names: "iaaf-400m", "indoor-200m".
    static QStringList builtinNames();
    static Expected<TrackGeometry> builtin(const QString& name);
    // A project's /geometry/<name> document first, then the built-ins. Errors name the geometry.
    static Expected<TrackGeometry> resolve(const std::map<QString, QJsonObject>& projectGeometry, const QString& name);

    // JSON document for Project::geometry():
    //   {"type": "track-oval", "name", "kerb_radius", "straight_length", "lane_width", "lanes",
    //    "first_lane_line", "other_lane_line", "pose": {"x", "y", "rotation"}}
    //   {"type": "track-polyline", "name", "points": [[x, y], …], "closed", "lane_width", "lanes", "pose"}
    static Expected<TrackGeometry> fromJson(const QJsonObject& json);
    QJsonObject toJson() const;

    Kind kind() const { return kind_; }
    const QString& name() const { return name_; }
    const TrackPose& pose() const { return pose_; }
    void setPose(const TrackPose& pose);
    const OvalParams& ovalParams() const { return oval_; }
    const PolylineParams& polylineParams() const { return poly_; }

    // Length of the reference line (oval: kerb line; polyline: the polyline, closing segment included).
    double referenceLength() const;
    // Offset d of a lane's running line (lane ≥ 1): oval 0.30 m / (lane−1)·w + 0.20 m; polyline (lane−½)·w.
    double laneOffset(int lane) const;
    // Length of a lap along the running line of a lane (oval lane 1: 400.0 m).
    double laneLength(int lane) const;

    // Queries in LPS coordinates.
    TrackQuery query(const Eigen::Vector2d& p) const;
    // The lean part of query() for motion models in the filter loop: heading, curvature, their
    // gradients and d (nearest, s and segment are left at their defaults). Inline for the oval.
    inline TrackQuery field(const Eigen::Vector2d& p) const;
    double headingAt(const Eigen::Vector2d& p) const { return query(p).heading; }
    double curvatureAt(const Eigen::Vector2d& p) const { return query(p).curvature; }
    // Point at arc length s (wrapped on closed tracks, clamped on open ones) and offset d.
    TrackPoint pointAt(double s, double d) const;

    // Pose transform.
    Eigen::Vector2d toLps(const Eigen::Vector2d& pTrack) const;
    Eigen::Vector2d toTrack(const Eigen::Vector2d& pLps) const;

private:
    inline TrackQuery fieldOval(const Eigen::Vector2d& p) const;
    TrackGeometry(Kind kind, OvalParams oval, PolylineParams poly, QString name);
    TrackQuery queryOvalLocal(const Eigen::Vector2d& q) const;
    TrackQuery queryPolylineLocal(const Eigen::Vector2d& q) const;
    TrackPoint pointOvalLocal(double s, double d) const;
    TrackPoint pointPolylineLocal(double s, double d) const;
    void buildPolyline();

    Kind kind_ = Kind::Oval;
    QString name_;
    TrackPose pose_;
    Eigen::Matrix2d rot_ = Eigen::Matrix2d::Identity();
    OvalParams oval_;
    PolylineParams poly_;
    // Polyline caches: cumulative length at each vertex, segment headings, vertex curvature.
    std::vector<double> cumLength_;
    std::vector<double> segHeading_;
    std::vector<double> segCurvature_;
};

inline TrackQuery TrackGeometry::field(const Eigen::Vector2d& p) const {
    return kind_ == Kind::Oval ? fieldOval(p) : query(p);
}

inline TrackQuery TrackGeometry::fieldOval(const Eigen::Vector2d& p) const {
    using math::wrapAngle;
    constexpr double pi = std::numbers::pi;
    const Eigen::Vector2d q = rot_.transpose() * (p - Eigen::Vector2d(pose_.x, pose_.y));
    const double halfL = 0.5 * oval_.straightLength;
    TrackQuery f;
    if (std::abs(q.x()) > halfL) {
        const Eigen::Vector2d rel(q.x() - (q.x() > 0 ? halfL : -halfL), q.y());
        const double rho2 = std::max(rel.squaredNorm(), 1e-12), rho = std::sqrt(rho2);
        const double invRho2 = 1.0 / rho2, invRho = rho * invRho2;
        const Eigen::Vector2d tangent = rot_ * Eigen::Vector2d(-rel.y(), rel.x());      // running direction × ρ
        f.heading = wrapAngle(std::atan2(rel.y(), rel.x()) + pi / 2 + pose_.rotation);  // eq. 4.21
        f.curvature = invRho;
        f.headingGradient = tangent * invRho2;
        f.curvatureGradient = rot_ * (-rel * (invRho2 * invRho));
        f.d = rho - oval_.kerbRadius;
        f.onBend = true;
    } else {
        f.heading = wrapAngle((q.y() >= 0 ? pi : 0.0) + pose_.rotation);  // eq. 4.19
        f.d = std::abs(q.y()) - oval_.kerbRadius;
    }
    return f;
}

}  // namespace athlos
