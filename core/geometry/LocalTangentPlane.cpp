#include "core/geometry/LocalTangentPlane.h"

#include "core/math/Angles.h"

#include <cmath>

namespace athlos {

namespace {
constexpr double kA = 6378137.0;            // WGS84 semi-major axis (m)
constexpr double kF = 1.0 / 298.257223563;  // flattening
constexpr double kE2 = kF * (2.0 - kF);     // first eccentricity squared
}  // namespace

Eigen::Vector3d LocalTangentPlane::geodeticToEcef(double latDeg, double lonDeg, double h) {
    const double lat = latDeg * math::kDeg, lon = lonDeg * math::kDeg;
    const double n = kA / std::sqrt(1.0 - kE2 * std::sin(lat) * std::sin(lat));  // prime vertical radius
    return {(n + h) * std::cos(lat) * std::cos(lon), (n + h) * std::cos(lat) * std::sin(lon),
            (n * (1.0 - kE2) + h) * std::sin(lat)};
}

LocalTangentPlane::LocalTangentPlane(double latDeg, double lonDeg, double height) {
    originEcef_ = geodeticToEcef(latDeg, lonDeg, height);
    const double lat = latDeg * math::kDeg, lon = lonDeg * math::kDeg;
    const double sl = std::sin(lat), cl = std::cos(lat), so = std::sin(lon), co = std::cos(lon);
    ecefToEnu_ << -so, co, 0.0, -sl * co, -sl * so, cl, cl * co, cl * so, sl;
}

Eigen::Vector3d LocalTangentPlane::toEnu(double latDeg, double lonDeg, double height) const {
    return ecefToEnu_ * (geodeticToEcef(latDeg, lonDeg, height) - originEcef_);
}

Eigen::Vector3d LocalTangentPlane::toGeodetic(const Eigen::Vector3d& enu) const {
    const Eigen::Vector3d e = originEcef_ + ecefToEnu_.transpose() * enu;
    const double lon = std::atan2(e.y(), e.x());
    const double p = std::hypot(e.x(), e.y());
    double lat = std::atan2(e.z(), p * (1.0 - kE2));
    double h = 0.0;
    for (int i = 0; i < 5; ++i) {
        const double n = kA / std::sqrt(1.0 - kE2 * std::sin(lat) * std::sin(lat));
        h = p / std::cos(lat) - n;
        lat = std::atan2(e.z(), p * (1.0 - kE2 * n / (n + h)));
    }
    return {lat / math::kDeg, lon / math::kDeg, h};
}

}  // namespace athlos
