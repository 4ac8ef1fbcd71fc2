#include "core/geometry/TrackGeometry.h"

#include <QJsonArray>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace athlos {

namespace {
constexpr double kPi = std::numbers::pi;
using math::wrapAngle;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

TrackGeometry::TrackGeometry() : TrackGeometry(Kind::Oval, OvalParams{}, {}, QStringLiteral("iaaf-400m")) {}

TrackGeometry::TrackGeometry(Kind kind, OvalParams oval, PolylineParams poly, QString name)
    : kind_(kind), name_(std::move(name)), oval_(oval), poly_(std::move(poly)) {
    if (kind_ == Kind::Polyline) buildPolyline();
}

TrackGeometry TrackGeometry::oval(const OvalParams& params, QString name) {
    return TrackGeometry(Kind::Oval, params, {}, std::move(name));
}

TrackGeometry TrackGeometry::polyline(PolylineParams params, QString name) {
    // Callers from JSON validate; programmatic callers get at least a degenerate 2-point line.
    if (params.points.size() < 2) params.points = {Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0)};
    return TrackGeometry(Kind::Polyline, OvalParams{}, std::move(params), std::move(name));
}

TrackGeometry TrackGeometry::iaaf400m() { return oval(OvalParams{}, QStringLiteral("iaaf-400m")); }

TrackGeometry TrackGeometry::indoor200m() {
    // World Athletics allows 17–19 m indoor bend radii; 17.20 m with straights chosen so that the
    // lane 1 running line (0.30 m out) is exactly 200 m. Lanes 0.90–1.10 m wide; 1.00 m here.
    OvalParams p;
    p.kerbRadius = 17.20;
    p.straightLength = (200.0 - 2.0 * kPi * (p.kerbRadius + p.firstLaneLine)) / 2.0;
    p.laneWidth = 1.00;
    p.lanes = 6;
    return oval(p, QStringLiteral("indoor-200m"));
}

QStringList TrackGeometry::builtinNames() { return {QStringLiteral("iaaf-400m"), QStringLiteral("indoor-200m")}; }

Expected<TrackGeometry> TrackGeometry::builtin(const QString& name) {
    if (name == QLatin1String("iaaf-400m")) return iaaf400m();
    if (name == QLatin1String("indoor-200m")) return indoor200m();
    return makeError(QStringLiteral("unknown built-in track geometry '%1' (known: %2)")
                         .arg(name, builtinNames().join(QStringLiteral(", "))));
}

Expected<TrackGeometry> TrackGeometry::resolve(const std::map<QString, QJsonObject>& projectGeometry,
                                               const QString& name) {
    if (auto it = projectGeometry.find(name); it != projectGeometry.end()) {
        auto g = fromJson(it->second);
        if (!g) return makeError(QStringLiteral("geometry '%1': %2").arg(name, g.message()));
        if (g->name_.isEmpty()) g->name_ = name;
        return g;
    }
    if (builtinNames().contains(name)) return builtin(name);
    QStringList known = builtinNames();
    for (const auto& [key, doc] : projectGeometry) known << key;
    return makeError(QStringLiteral("track geometry '%1' not found in the project or the built-ins (known: %2)")
                         .arg(name, known.join(QStringLiteral(", "))));
}

// ---- JSON -------------------------------------------------------------------------------------

Expected<TrackGeometry> TrackGeometry::fromJson(const QJsonObject& json) {
    const QString type = json.value(QStringLiteral("type")).toString();
    auto number = [&](const char* key, double def) { return json.value(QLatin1String(key)).toDouble(def); };
    TrackGeometry g;
    if (type == QLatin1String("track-oval") || type == QLatin1String("oval")) {
        OvalParams p;
        p.kerbRadius = number("kerb_radius", p.kerbRadius);
        p.straightLength = number("straight_length", p.straightLength);
        p.laneWidth = number("lane_width", p.laneWidth);
        p.lanes = json.value(QStringLiteral("lanes")).toInt(p.lanes);
        p.firstLaneLine = number("first_lane_line", p.firstLaneLine);
        p.otherLaneLine = number("other_lane_line", p.otherLaneLine);
        if (!(p.kerbRadius > 0) || !(p.straightLength >= 0) || !(p.laneWidth > 0) || p.lanes < 1)
            return makeError(
                QStringLiteral("track-oval needs kerb_radius > 0, straight_length >= 0, lane_width > 0, "
                               "lanes >= 1"));
        g = oval(p);
    } else if (type == QLatin1String("track-polyline") || type == QLatin1String("polyline")) {
        PolylineParams p;
        const QJsonArray points = json.value(QStringLiteral("points")).toArray();
        for (int i = 0; i < points.size(); ++i) {
            const QJsonArray xy = points.at(i).toArray();
            if (xy.size() < 2) return makeError(QStringLiteral("track-polyline point %1 is not [x, y]").arg(i));
            p.points.emplace_back(xy.at(0).toDouble(), xy.at(1).toDouble());
        }
        for (std::size_t i = 1; i < p.points.size(); ++i)
            if ((p.points[i] - p.points[i - 1]).norm() <= 0.0)
                return makeError(QStringLiteral("track-polyline points %1 and %2 coincide").arg(i - 1).arg(i));
        if (p.points.size() < 2) return makeError(QStringLiteral("track-polyline needs at least 2 points"));
        p.closed = json.value(QStringLiteral("closed")).toBool(false);
        p.laneWidth = number("lane_width", p.laneWidth);
        p.lanes = json.value(QStringLiteral("lanes")).toInt(p.lanes);
        g = polyline(std::move(p));
    } else {
        return makeError(
            QStringLiteral("unknown geometry type '%1' (expected track-oval or track-polyline)").arg(type));
    }
    g.name_ = json.value(QStringLiteral("name")).toString();
    const QJsonObject pose = json.value(QStringLiteral("pose")).toObject();
    g.setPose({pose.value(QStringLiteral("x")).toDouble(), pose.value(QStringLiteral("y")).toDouble(),
               pose.value(QStringLiteral("rotation")).toDouble()});
    return g;
}

QJsonObject TrackGeometry::toJson() const {
    QJsonObject json;
    json.insert(QStringLiteral("name"), name_);
    if (kind_ == Kind::Oval) {
        json.insert(QStringLiteral("type"), QStringLiteral("track-oval"));
        json.insert(QStringLiteral("kerb_radius"), oval_.kerbRadius);
        json.insert(QStringLiteral("straight_length"), oval_.straightLength);
        json.insert(QStringLiteral("lane_width"), oval_.laneWidth);
        json.insert(QStringLiteral("lanes"), oval_.lanes);
        json.insert(QStringLiteral("first_lane_line"), oval_.firstLaneLine);
        json.insert(QStringLiteral("other_lane_line"), oval_.otherLaneLine);
    } else {
        json.insert(QStringLiteral("type"), QStringLiteral("track-polyline"));
        QJsonArray points;
        for (const auto& p : poly_.points) points.append(QJsonArray{p.x(), p.y()});
        json.insert(QStringLiteral("points"), points);
        json.insert(QStringLiteral("closed"), poly_.closed);
        json.insert(QStringLiteral("lane_width"), poly_.laneWidth);
        json.insert(QStringLiteral("lanes"), poly_.lanes);
    }
    json.insert(QStringLiteral("pose"), QJsonObject{{QStringLiteral("x"), pose_.x},
                                                    {QStringLiteral("y"), pose_.y},
                                                    {QStringLiteral("rotation"), pose_.rotation}});
    return json;
}

// ---- basic properties -------------------------------------------------------------------------

void TrackGeometry::setPose(const TrackPose& pose) {
    pose_ = pose;
    const double c = std::cos(pose.rotation), s = std::sin(pose.rotation);
    rot_ << c, -s, s, c;
}

Eigen::Vector2d TrackGeometry::toLps(const Eigen::Vector2d& pTrack) const {
    return rot_ * pTrack + Eigen::Vector2d(pose_.x, pose_.y);
}

Eigen::Vector2d TrackGeometry::toTrack(const Eigen::Vector2d& pLps) const {
    return rot_.transpose() * (pLps - Eigen::Vector2d(pose_.x, pose_.y));
}

double TrackGeometry::referenceLength() const {
    if (kind_ == Kind::Oval) return 2.0 * oval_.straightLength + 2.0 * kPi * oval_.kerbRadius;
    return cumLength_.back();
}

double TrackGeometry::laneOffset(int lane) const {
    lane = std::max(lane, 1);
    if (kind_ == Kind::Oval)
        return lane == 1 ? oval_.firstLaneLine : (lane - 1) * oval_.laneWidth + oval_.otherLaneLine;
    return (lane - 0.5) * poly_.laneWidth;
}

double TrackGeometry::laneLength(int lane) const {
    if (kind_ == Kind::Oval) return 2.0 * oval_.straightLength + 2.0 * kPi * (oval_.kerbRadius + laneOffset(lane));
    return referenceLength();  // polyline offsets are not length-preserving; the reference is what we know
}

// ---- queries ----------------------------------------------------------------------------------

TrackQuery TrackGeometry::query(const Eigen::Vector2d& p) const {
    TrackQuery q = kind_ == Kind::Oval ? queryOvalLocal(toTrack(p)) : queryPolylineLocal(toTrack(p));
    q.nearest = toLps(q.nearest);
    q.heading = wrapAngle(q.heading + pose_.rotation);
    // p_track = Rᵀ (p − t) ⇒ ∇_p f = R ∇_track f.
    q.headingGradient = rot_ * q.headingGradient;
    q.curvatureGradient = rot_ * q.curvatureGradient;
    return q;
}

TrackQuery TrackGeometry::queryOvalLocal(const Eigen::Vector2d& p) const {
    const double halfL = 0.5 * oval_.straightLength, r0 = oval_.kerbRadius, L = oval_.straightLength;
    TrackQuery q;
    if (std::abs(p.x()) > halfL) {
        // Bend: heading tangent to the circle about the bend centre (eq. 4.21), curvature 1/ρ (eq. 4.20
        // uses ω = v/r_track with r_track = |p − p_c|).
        const bool first = p.x() > 0;
        const Eigen::Vector2d c(first ? halfL : -halfL, 0.0);
        const Eigen::Vector2d rel = p - c;
        const double rho2 = std::max(rel.squaredNorm(), 1e-12), rho = std::sqrt(rho2);
        double theta = std::atan2(rel.y(), rel.x());
        q.heading = wrapAngle(theta + kPi / 2);
        q.curvature = 1.0 / rho;
        q.headingGradient = Eigen::Vector2d(-rel.y(), rel.x()) / rho2;
        q.curvatureGradient = -rel / (rho2 * rho);
        q.d = rho - r0;
        q.nearest = c + rel / rho * r0;
        q.onBend = true;
        if (first) {
            q.segment = 0;
            q.s = r0 * (theta + kPi / 2);
        } else {
            if (theta < 0) theta += 2 * kPi;  // (π/2, 3π/2)
            q.segment = 2;
            q.s = kPi * r0 + L + r0 * (theta - kPi / 2);
        }
    } else if (p.y() >= 0) {  // back straight, running towards −x (eq. 4.19: φ = π for p_y > p_cy)
        q.segment = 1;
        q.heading = kPi;
        q.s = kPi * r0 + (halfL - p.x());
        q.d = p.y() - r0;
        q.nearest = Eigen::Vector2d(p.x(), r0);
    } else {  // home straight, towards +x (φ = 0)
        q.segment = 3;
        q.heading = 0.0;
        q.s = 2 * kPi * r0 + L + (p.x() + halfL);
        q.d = -p.y() - r0;
        q.nearest = Eigen::Vector2d(p.x(), -r0);
    }
    return q;
}

TrackPoint TrackGeometry::pointAt(double s, double d) const {
    TrackPoint local = kind_ == Kind::Oval ? pointOvalLocal(s, d) : pointPolylineLocal(s, d);
    local.position = toLps(local.position);
    local.heading = wrapAngle(local.heading + pose_.rotation);
    return local;
}

TrackPoint TrackGeometry::pointOvalLocal(double s, double d) const {
    const double halfL = 0.5 * oval_.straightLength, r0 = oval_.kerbRadius, L = oval_.straightLength;
    const double total = referenceLength();
    s = std::fmod(s, total);
    if (s < 0) s += total;
    const double r = r0 + d;
    TrackPoint pt;
    if (s < kPi * r0) {
        const double theta = s / r0 - kPi / 2;
        pt.position = Eigen::Vector2d(halfL + r * std::cos(theta), r * std::sin(theta));
        pt.heading = theta + kPi / 2;
        pt.curvature = 1.0 / r;
    } else if (s < kPi * r0 + L) {
        pt.position = Eigen::Vector2d(halfL - (s - kPi * r0), r);
        pt.heading = kPi;
    } else if (s < 2 * kPi * r0 + L) {
        const double theta = (s - kPi * r0 - L) / r0 + kPi / 2;
        pt.position = Eigen::Vector2d(-halfL + r * std::cos(theta), r * std::sin(theta));
        pt.heading = theta + kPi / 2;
        pt.curvature = 1.0 / r;
    } else {
        pt.position = Eigen::Vector2d(-halfL + (s - 2 * kPi * r0 - L), -r);
        pt.heading = 0.0;
    }
    pt.heading = wrapAngle(pt.heading);
    return pt;
}

// ---- polyline ---------------------------------------------------------------------------------

void TrackGeometry::buildPolyline() {
    const auto& pts = poly_.points;
    const std::size_t n = pts.size();
    const std::size_t segments = poly_.closed ? n : n - 1;
    cumLength_.assign(segments + 1, 0.0);
    segHeading_.assign(segments, 0.0);
    for (std::size_t i = 0; i < segments; ++i) {
        const Eigen::Vector2d delta = pts[(i + 1) % n] - pts[i];
        cumLength_[i + 1] = cumLength_[i] + delta.norm();
        segHeading_[i] = std::atan2(delta.y(), delta.x());
    }
    // Curvature of a segment: mean of the turning rates at its two vertices (turn angle over the
    // mean adjacent length); gives ω = v·κ for maps without a closed form.
    std::vector<double> vertexCurv(n, 0.0);
    for (std::size_t v = 0; v < n; ++v) {
        if (!poly_.closed && (v == 0 || v == n - 1)) continue;
        const std::size_t in = (v + segments - 1) % segments, out = v % segments;
        const double turn = wrapAngle(segHeading_[out] - segHeading_[in]);
        const double len = 0.5 * ((cumLength_[in + 1] - cumLength_[in]) + (cumLength_[out + 1] - cumLength_[out]));
        vertexCurv[v] = turn / len;
    }
    segCurvature_.assign(segments, 0.0);
    for (std::size_t i = 0; i < segments; ++i) segCurvature_[i] = 0.5 * (vertexCurv[i] + vertexCurv[(i + 1) % n]);
}

TrackQuery TrackGeometry::queryPolylineLocal(const Eigen::Vector2d& p) const {
    // Nearest segment (eq. in seed 001 §II-B: the orientation of the closest line segment). Linear
    // scan: track polylines have tens to hundreds of vertices.
    const auto& pts = poly_.points;
    const std::size_t n = pts.size(), segments = segHeading_.size();
    TrackQuery best;
    double bestDist = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < segments; ++i) {
        const Eigen::Vector2d a = pts[i], b = pts[(i + 1) % n];
        const Eigen::Vector2d ab = b - a;
        const double len = cumLength_[i + 1] - cumLength_[i];
        const double u = std::clamp((p - a).dot(ab) / (len * len), 0.0, 1.0);
        const Eigen::Vector2d nearest = a + u * ab;
        const double dist = (p - nearest).squaredNorm();
        if (dist < bestDist) {
            bestDist = dist;
            best.nearest = nearest;
            best.s = cumLength_[i] + u * len;
            best.d = -cross(ab / len, p - a);  // right of the running direction is positive
            best.heading = segHeading_[i];
            best.curvature = segCurvature_[i];
            best.segment = static_cast<int>(i);
        }
    }
    return best;
}

TrackPoint TrackGeometry::pointPolylineLocal(double s, double d) const {
    const double total = cumLength_.back();
    if (poly_.closed) {
        s = std::fmod(s, total);
        if (s < 0) s += total;
    } else {
        s = std::clamp(s, 0.0, total);
    }
    const auto it = std::upper_bound(cumLength_.begin(), cumLength_.end(), s);
    const std::size_t i =
        std::min<std::size_t>(std::max<std::ptrdiff_t>(it - cumLength_.begin() - 1, 0), segHeading_.size() - 1);
    const auto& pts = poly_.points;
    const Eigen::Vector2d a = pts[i], b = pts[(i + 1) % pts.size()];
    const double len = cumLength_[i + 1] - cumLength_[i];
    const Eigen::Vector2d dir = (b - a) / len;
    TrackPoint pt;
    pt.position = a + dir * (s - cumLength_[i]) + Eigen::Vector2d(dir.y(), -dir.x()) * d;
    pt.heading = segHeading_[i];
    pt.curvature = segCurvature_[i];
    return pt;
}

}  // namespace athlos
