#pragma once
// WGS84 geodetic coordinates ↔ a local East-North-Up frame whose origin is a reference fix
// (e.g. the first GNSS fix). Exact ECEF-based conversion (no flat-earth approximation), so it stays
// valid over a whole stadium and beyond.
#include <Eigen/Core>

namespace athlos {

class LocalTangentPlane {
public:
    // Origin: latitude, longitude (deg), ellipsoidal height (m).
    LocalTangentPlane(double latDeg, double lonDeg, double height);

    Eigen::Vector3d toEnu(double latDeg, double lonDeg, double height) const;
    // Inverse (iterative, mm accuracy after 3 iterations near the surface): (lat, lon deg, height m).
    Eigen::Vector3d toGeodetic(const Eigen::Vector3d& enu) const;
    // North-East-Down velocity → ENU.
    static Eigen::Vector3d nedToEnu(double vn, double ve, double vd) { return {ve, vn, -vd}; }

    static Eigen::Vector3d geodeticToEcef(double latDeg, double lonDeg, double height);

private:
    Eigen::Vector3d originEcef_;
    Eigen::Matrix3d ecefToEnu_;
};

}  // namespace athlos
