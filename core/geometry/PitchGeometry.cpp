#include "core/geometry/PitchGeometry.h"

#include "core/geometry/LocalTangentPlane.h"

#include <Eigen/Geometry>
#include <QJsonArray>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

namespace athlos {

namespace {

constexpr double kPi = std::numbers::pi;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Proper intersection of segments p0p1 and q0q1 (touching at an end point counts too).
bool segmentsIntersect(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& q0,
                       const Eigen::Vector2d& q1) {
    const double d1 = cross(p1 - p0, q0 - p0), d2 = cross(p1 - p0, q1 - p0);
    const double d3 = cross(q1 - q0, p0 - q0), d4 = cross(q1 - q0, p1 - q0);
    return ((d1 > 0) != (d2 > 0) || d1 == 0 || d2 == 0) && ((d3 > 0) != (d4 > 0) || d3 == 0 || d4 == 0);
}

// Angle in (−π/2, π/2].
double halfTurn(double a) {
    a = std::remainder(a, kPi);
    return a <= -kPi / 2 ? a + kPi : a;
}

QJsonArray pairs(const std::vector<Eigen::Vector2d>& points) {
    QJsonArray array;
    for (const auto& p : points) array.append(QJsonArray{p.x(), p.y()});
    return array;
}

Expected<std::vector<Eigen::Vector2d>> readPairs(const QJsonObject& json, const char* key) {
    std::vector<Eigen::Vector2d> points;
    const QJsonArray array = json.value(QLatin1String(key)).toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QJsonArray xy = array.at(i).toArray();
        if (xy.size() != 2 || !xy.at(0).isDouble() || !xy.at(1).isDouble())
            return makeError(QStringLiteral("pitch: %1[%2] is not a pair of numbers").arg(QLatin1String(key)).arg(i));
        points.emplace_back(xy.at(0).toDouble(), xy.at(1).toDouble());
    }
    return points;
}

}  // namespace

Expected<PitchGeometry> PitchGeometry::fit(const std::vector<Eigen::Vector2d>& corners, Kind kind, const Params& params,
                                           QString name) {
    if (!(params.maxResidual > 0.0) || !std::isfinite(params.maxResidual))
        return makeError(QStringLiteral("max_residual must be a positive number of metres"));
    if (!(params.minSide > 0.0) || !std::isfinite(params.minSide))
        return makeError(QStringLiteral("min_side must be a positive number of metres"));
    if (corners.size() != 4)
        return makeError(QStringLiteral("corners: a pitch needs 4 corners, got %1").arg(corners.size()));
    for (std::size_t i = 0; i < 4; ++i)
        if (!corners[i].allFinite())
            return makeError(QStringLiteral("corners: corner %1 is not a finite point").arg(i + 1));
    for (std::size_t i = 0; i < 4; ++i)
        for (std::size_t j = i + 1; j < 4; ++j)
            if ((corners[i] - corners[j]).norm() < params.minSide)
                return makeError(QStringLiteral("corners: corners %1 and %2 are %3 m apart, closer than min_side %4 m")
                                     .arg(i + 1)
                                     .arg(j + 1)
                                     .arg((corners[i] - corners[j]).norm(), 0, 'g', 3)
                                     .arg(params.minSide));
    // Cyclic order: the outline 1-2-3-4 must not cross itself (1-2 × 3-4, 2-3 × 4-1).
    if (segmentsIntersect(corners[0], corners[1], corners[2], corners[3]) ||
        segmentsIntersect(corners[1], corners[2], corners[3], corners[0]))
        return makeError(
            QStringLiteral("corners: the outline 1-2-3-4 crosses itself; give the corners in order going "
                           "round the pitch"));
    double area2 = 0.0;
    for (std::size_t i = 0; i < 4; ++i) area2 += cross(corners[i], corners[(i + 1) % 4]);
    // Counter-clockwise working order (a clockwise input is walked backwards).
    const std::array<std::size_t, 4> order =
        area2 > 0 ? std::array<std::size_t, 4>{0, 1, 2, 3} : std::array<std::size_t, 4>{0, 3, 2, 1};
    for (std::size_t k = 0; k < 4; ++k) {
        const Eigen::Vector2d& a = corners[order[k]];
        const Eigen::Vector2d& b = corners[order[(k + 1) % 4]];
        const Eigen::Vector2d& c = corners[order[(k + 2) % 4]];
        if (cross(b - a, c - b) <= 0.0)
            return makeError(QStringLiteral("corners: the outline is not convex at corner %1, so not a rectangle")
                                 .arg(order[(k + 1) % 4] + 1));
    }

    // Closed-form least squares (see the header).
    const Eigen::Vector2d centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
    constexpr std::array<double, 4> s = {-1, 1, 1, -1}, t = {-1, -1, 1, 1};
    std::complex<double> a, b;
    for (std::size_t k = 0; k < 4; ++k) {
        const Eigen::Vector2d q = corners[order[k]] - centre;
        a += s[k] * std::complex<double>(q.x(), q.y());
        b += t[k] * std::complex<double>(q.x(), q.y());
    }
    double theta = 0.5 * std::arg(a * a - b * b);
    const std::complex<double> back = std::polar(1.0, -theta);
    double hl = (a * back).real() / 4.0, hw = (b * back).imag() / 4.0;
    if (hl < 0) {
        theta += kPi;
        hl = -hl;
        hw = -hw;
    }
    if (!(hw > 0)) return makeError(QStringLiteral("corners: the 4 points are not near a rectangle"));

    PitchGeometry g;
    g.kind_ = kind;
    g.name_ = std::move(name);
    g.centre_ = centre;
    g.corners_ = corners;
    g.residuals_.assign(4, 0.0);
    const Eigen::Matrix2d r = Eigen::Rotation2Dd(theta).toRotationMatrix();
    for (std::size_t k = 0; k < 4; ++k)
        g.residuals_[order[k]] = (corners[order[k]] - (centre + r * Eigen::Vector2d(s[k] * hl, t[k] * hw))).norm();
    // x along the longer side.
    if (hw > hl) {
        std::swap(hl, hw);
        theta += kPi / 2;
    }
    g.length_ = 2 * hl;
    g.width_ = 2 * hw;
    g.rotation_ = halfTurn(theta);
    if (g.width_ < params.minSide)
        return makeError(QStringLiteral("corners: the rectangle is %1 m wide, narrower than min_side %2 m")
                             .arg(g.width_, 0, 'f', 2)
                             .arg(params.minSide));
    std::size_t worst = 0;
    for (std::size_t i = 1; i < 4; ++i)
        if (g.residuals_[i] > g.residuals_[worst]) worst = i;
    if (g.residuals_[worst] > params.maxResidual)
        return makeError(
            QStringLiteral("corners: corner %1 is %2 m from the best-fitting rectangle (max_residual %3 m): "
                           "the 4 points are not near a rectangle (a corner mistyped or out of order?)")
                .arg(worst + 1)
                .arg(g.residuals_[worst], 0, 'f', 2)
                .arg(params.maxResidual));
    return g;
}

Expected<PitchGeometry> PitchGeometry::fitGeodetic(const std::vector<Eigen::Vector2d>& latLon,
                                                   const GeodeticOrigin& origin, Kind kind, const Params& params,
                                                   QString name) {
    const LocalTangentPlane plane(origin.lat, origin.lon, origin.height);
    std::vector<Eigen::Vector2d> enu;
    for (std::size_t i = 0; i < latLon.size(); ++i) {
        const Eigen::Vector2d& p = latLon[i];
        if (!p.allFinite() || std::abs(p.x()) > 90.0 || std::abs(p.y()) > 180.0)
            return makeError(QStringLiteral("corners: corner %1 (%2, %3): latitude must be in [-90, 90], longitude in "
                                            "[-180, 180]")
                                 .arg(i + 1)
                                 .arg(p.x(), 0, 'g', 10)
                                 .arg(p.y(), 0, 'g', 10));
        enu.push_back(plane.toEnu(p.x(), p.y(), origin.height).head<2>());
    }
    // A pitch a few kilometres from the origin is fine; one on another continent is a typing error.
    for (std::size_t i = 0; i < enu.size(); ++i)
        if (enu[i].norm() > 50e3)
            return makeError(QStringLiteral("corners: corner %1 is %2 km from the project's geodetic origin (%3, %4)")
                                 .arg(i + 1)
                                 .arg(enu[i].norm() / 1e3, 0, 'f', 0)
                                 .arg(origin.lat)
                                 .arg(origin.lon));
    auto g = fit(enu, kind, params, std::move(name));
    if (!g) return g;
    g->cornersGeodetic_ = latLon;
    g->origin_ = origin;
    return g;
}

PitchGeometry PitchGeometry::placed(Kind kind, double length, double width, const Eigen::Vector2d& centre,
                                    double rotation, QString name) {
    PitchGeometry g;
    g.kind_ = kind;
    g.name_ = std::move(name);
    g.length_ = length;
    g.width_ = width;
    g.centre_ = centre;
    g.rotation_ = rotation;
    return g;
}

Expected<std::vector<Eigen::Vector2d>> PitchGeometry::parsePoints(const QString& text, const QString& option, int count,
                                                                  const QString& noun) {
    std::vector<Eigen::Vector2d> points;
    const QStringList items = text.split(QLatin1Char(';'), Qt::SkipEmptyParts);
    for (qsizetype i = 0; i < items.size(); ++i) {
        const QStringList parts = items[i].split(QLatin1Char(','));
        bool ok0 = false, ok1 = false;
        const double v0 = parts.size() == 2 ? parts[0].trimmed().toDouble(&ok0) : 0.0;
        const double v1 = parts.size() == 2 ? parts[1].trimmed().toDouble(&ok1) : 0.0;
        if (!ok0 || !ok1 || !std::isfinite(v0) || !std::isfinite(v1))
            return makeError(QStringLiteral("%1: %2 %3 '%4' is not a pair of numbers A,B")
                                 .arg(option, noun)
                                 .arg(i + 1)
                                 .arg(items[i].trimmed()));
        points.emplace_back(v0, v1);
    }
    if (count > 0 && int(points.size()) != count)
        return makeError(QStringLiteral("%1: expected %2 %3s separated by ';', got %4")
                             .arg(option)
                             .arg(count)
                             .arg(noun)
                             .arg(points.size()));
    if (points.empty()) return makeError(QStringLiteral("%1: no %2s").arg(option, noun));
    return points;
}

Expected<std::vector<Eigen::Vector2d>> PitchGeometry::parseCorners(const QString& text, const QString& option) {
    return parsePoints(text, option, 4, QStringLiteral("corner"));
}

QString PitchGeometry::kindId(Kind kind) {
    switch (kind) {
        case Kind::Football:
            return QStringLiteral("football");
        case Kind::Rugby:
            return QStringLiteral("rugby");
        default:
            return QStringLiteral("rectangle");
    }
}

std::optional<PitchGeometry::Kind> PitchGeometry::kindFromId(const QString& id) {
    for (Kind k : {Kind::Football, Kind::Rugby, Kind::Rectangle})
        if (kindId(k) == id) return k;
    return std::nullopt;
}

QStringList PitchGeometry::kindIds() { return {kindId(Kind::Football), kindId(Kind::Rugby), kindId(Kind::Rectangle)}; }

bool PitchGeometry::isPitchJson(const QJsonObject& json) {
    return json.value(QStringLiteral("type")).toString() == QLatin1String("pitch");
}

Expected<PitchGeometry> PitchGeometry::fromJson(const QJsonObject& json) {
    if (!isPitchJson(json)) return makeError(QStringLiteral("not a pitch document (type is not 'pitch')"));
    const auto kind = kindFromId(json.value(QStringLiteral("kind")).toString());
    if (!kind)
        return makeError(QStringLiteral("pitch: kind '%1' is not one of %2")
                             .arg(json.value(QStringLiteral("kind")).toString(), kindIds().join(QStringLiteral(", "))));
    const double length = json.value(QStringLiteral("length")).toDouble(-1),
                 width = json.value(QStringLiteral("width")).toDouble(-1);
    const double rotation = json.value(QStringLiteral("rotation")).toDouble(std::nan(""));
    const QJsonArray centre = json.value(QStringLiteral("centre")).toArray();
    if (!(length > 0) || !(width > 0) || !std::isfinite(length) || !std::isfinite(width))
        return makeError(QStringLiteral("pitch: length and width must be positive (m)"));
    if (!std::isfinite(rotation)) return makeError(QStringLiteral("pitch: rotation (rad) is missing"));
    if (centre.size() != 2 || !centre.at(0).isDouble() || !centre.at(1).isDouble())
        return makeError(QStringLiteral("pitch: centre is not [x, y]"));
    PitchGeometry g = placed(*kind, length, width, {centre.at(0).toDouble(), centre.at(1).toDouble()}, rotation,
                             json.value(QStringLiteral("name")).toString());
    auto corners = readPairs(json, "corners");
    if (!corners) return corners.error();
    g.corners_ = std::move(*corners);
    for (const QJsonValue v : json.value(QStringLiteral("residuals")).toArray()) g.residuals_.push_back(v.toDouble());
    auto geodetic = readPairs(json, "corners_geodetic");
    if (!geodetic) return geodetic.error();
    g.cornersGeodetic_ = std::move(*geodetic);
    g.origin_ = GeodeticOrigin::fromJson(json.value(QStringLiteral("geodetic_origin")).toObject());
    return g;
}

QJsonObject PitchGeometry::toJson() const {
    QJsonObject json{
        {QStringLiteral("type"), QStringLiteral("pitch")},
        {QStringLiteral("name"), name_},
        {QStringLiteral("kind"), kindId(kind_)},
        {QStringLiteral("length"), length_},
        {QStringLiteral("width"), width_},
        {QStringLiteral("rotation"), rotation_},
        {QStringLiteral("centre"), QJsonArray{centre_.x(), centre_.y()}},
        {QStringLiteral("frame"), QStringLiteral("enu")},
        {QStringLiteral("pitch_frame"), QStringLiteral("pitch")},
        {QStringLiteral("units"), QJsonObject{{QStringLiteral("length"), QStringLiteral("m")},
                                              {QStringLiteral("width"), QStringLiteral("m")},
                                              {QStringLiteral("centre"), QStringLiteral("m")},
                                              {QStringLiteral("corners"), QStringLiteral("m")},
                                              {QStringLiteral("residuals"), QStringLiteral("m")},
                                              {QStringLiteral("rotation"), QStringLiteral("rad")},
                                              {QStringLiteral("corners_geodetic"), QStringLiteral("deg")}}},
        {QStringLiteral("rotation_convention"),
         QStringLiteral("pitch x axis (along the length) from ENU x (East), counter-clockwise; "
                        "p_enu = R(rotation) * p_pitch + centre; pitch origin at the centre spot, z up")},
        {QStringLiteral("corners"), pairs(corners_)}};
    QJsonArray residuals;
    for (double r : residuals_) residuals.append(r);
    json.insert(QStringLiteral("residuals"), residuals);
    if (!cornersGeodetic_.empty()) json.insert(QStringLiteral("corners_geodetic"), pairs(cornersGeodetic_));
    if (origin_) json.insert(QStringLiteral("geodetic_origin"), origin_->toJson());
    return json;
}

std::optional<PitchGeometry> PitchGeometry::firstOf(const std::map<QString, QJsonObject>& projectGeometry) {
    for (const auto& [name, json] : projectGeometry) {
        if (!isPitchJson(json)) continue;
        auto g = fromJson(json);
        if (!g) continue;
        if (g->name_.isEmpty()) g->name_ = name;
        return std::move(*g);
    }
    return std::nullopt;
}

double PitchGeometry::maxResidual() const {
    double m = 0.0;
    for (double r : residuals_) m = std::max(m, r);
    return m;
}

QStringList PitchGeometry::notes() const {
    QStringList notes;
    auto range = [&](const char* what, double v, double lo, double hi, const char* law) {
        if (v < lo - 0.5 || v > hi + 0.5)
            notes << QStringLiteral("%1 %2 m is outside %3 (%4-%5 m)")
                         .arg(QLatin1String(what))
                         .arg(v, 0, 'f', 1)
                         .arg(QLatin1String(law))
                         .arg(lo)
                         .arg(hi);
    };
    if (kind_ == Kind::Football) {
        range("length", length_, 90, 120, "IFAB Law 1");
        range("width", width_, 45, 90, "IFAB Law 1");
    } else if (kind_ == Kind::Rugby) {
        range("length", length_, 94, 100, "World Rugby Law 1 (field of play)");
        range("width", width_, 68, 70, "World Rugby Law 1");
    }
    return notes;
}

Eigen::Vector2d PitchGeometry::toPitch(const Eigen::Vector2d& enu) const {
    return Eigen::Rotation2Dd(-rotation_) * (enu - centre_);
}

Eigen::Vector2d PitchGeometry::toEnu(const Eigen::Vector2d& pitch) const {
    return Eigen::Rotation2Dd(rotation_) * pitch + centre_;
}

}  // namespace athlos
