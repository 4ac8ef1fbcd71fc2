#include "plugins/lps/BeaconGeometry.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace athlos::lps {

BeaconGeometryReport assessBeaconGeometry(const std::vector<Vector3>& beacons, const std::vector<Vector3>& area,
                                          const BeaconGeometryParams& params) {
    BeaconGeometryReport r;
    r.beacons = int(beacons.size());
    if (r.beacons < params.minBeacons) {
        r.tooFew = true;
        r.problems << QStringLiteral("only %1 beacons (a TDoA fix needs %2)").arg(r.beacons).arg(params.minBeacons);
        if (beacons.empty()) return r;
    }
    Vector3 centroid = Vector3::Zero();
    for (const auto& b : beacons) centroid += b;
    centroid /= double(beacons.size());
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (const auto& b : beacons) covariance += (b - centroid) * (b - centroid).transpose();
    covariance /= double(beacons.size());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> horizontal(covariance.topLeftCorner<2, 2>());
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> full(covariance);
    r.spreadMinor = std::sqrt(std::max(0.0, horizontal.eigenvalues()[0]));
    r.spreadMajor = std::sqrt(std::max(0.0, horizontal.eigenvalues()[1]));
    r.spreadVertical = std::sqrt(std::max(0.0, full.eigenvalues()[0]));
    if (!area.empty()) {
        double extent = 0.0;
        for (const auto& p : area) extent = std::max(extent, (p - centroid).head<2>().norm());
        r.areaExtent = extent;
        r.dilution = extent / std::max(r.spreadMinor, 1e-9);
    }
    const double extent = std::isfinite(r.areaExtent) ? r.areaExtent : 0.0;
    if (r.spreadMajor < params.minHorizontalSpread || extent > params.maxDilution * r.spreadMajor) {
        r.clustered = true;
        r.problems << (extent > 0.0
                           ? QStringLiteral("beacons clustered: horizontal spread σ %1 m for an area reaching %2 m "
                                            "from them (ratio %3 > %4)")
                                 .arg(r.spreadMajor, 0, 'f', 2)
                                 .arg(extent, 0, 'f', 1)
                                 .arg(extent / std::max(r.spreadMajor, 1e-9), 0, 'f', 0)
                                 .arg(params.maxDilution)
                           : QStringLiteral("beacons clustered: horizontal spread σ %1 m < %2 m")
                                 .arg(r.spreadMajor, 0, 'f', 2)
                                 .arg(params.minHorizontalSpread));
    } else if (r.spreadMinor < params.minHorizontalSpread || extent > params.maxDilution * r.spreadMinor) {
        r.collinear = true;
        r.problems << QStringLiteral(
                          "beacons nearly collinear: spread %1 m along, %2 m across their line (positions across "
                          "it are not observable)")
                          .arg(r.spreadMajor, 0, 'f', 2)
                          .arg(r.spreadMinor, 0, 'f', 2);
    }
    if (r.spreadVertical < params.minVerticalSpread) {
        r.coplanar = true;
        r.problems << QStringLiteral(
                          "beacons nearly coplanar (σ %1 m across their plane < %2 m): a 3D fix cannot tell the "
                          "tag from its reflection in that plane; use 2D fixes at a known height")
                          .arg(r.spreadVertical, 0, 'f', 2)
                          .arg(params.minVerticalSpread);
    }
    return r;
}

namespace {

// √trace of the position block of (HᵀH)⁻¹, rows (u_iᵀ[, −1]).
double dilution(const std::vector<Vector3>& beacons, const Vector3& tag, bool planar, bool offset) {
    const int dims = planar ? 2 : 3;
    Eigen::MatrixXd h(beacons.size(), dims + (offset ? 1 : 0));
    for (std::size_t i = 0; i < beacons.size(); ++i) {
        const Vector3 d = tag - beacons[i];
        const double n = d.norm();
        if (n < 1e-9) return std::numeric_limits<double>::infinity();
        for (int k = 0; k < dims; ++k) h(Eigen::Index(i), k) = d[k] / n;
        if (offset) h(Eigen::Index(i), dims) = -1.0;  // offset o
    }
    if (h.rows() < h.cols()) return std::numeric_limits<double>::infinity();
    const Eigen::MatrixXd normal = h.transpose() * h;
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(normal);
    if (lu.rank() < normal.rows()) return std::numeric_limits<double>::infinity();
    const Eigen::MatrixXd inverse = lu.inverse();
    double trace = 0.0;
    for (int k = 0; k < dims; ++k) trace += inverse(k, k);
    return trace >= 0.0 ? std::sqrt(trace) : std::numeric_limits<double>::infinity();
}

}  // namespace

double tdoaDop(const std::vector<Vector3>& beacons, const Vector3& tag, bool planar) {
    return dilution(beacons, tag, planar, true);
}

double toaDop(const std::vector<Vector3>& beacons, const Vector3& tag, bool planar) {
    return dilution(beacons, tag, planar, false);
}

}  // namespace athlos::lps
