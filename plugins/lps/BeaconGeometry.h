#pragma once
// Beacon geometry checks (issue #16 item 3): is a calibration or a fix observable at all with these
// beacons? Plain functions with no state, for lps-calibration and, later, the positioning.
//
// Layout check (assessBeaconGeometry): principal standard deviations of the beacon positions —
// horizontal σ_major ≥ σ_minor (eigenvalues of the xy covariance) and σ_vertical (the smallest of
// the 3D covariance) — against absolute limits and, when the tag's area of operation is known
// (e.g. the calibration walk), against its extent: a fix at distance R from beacons spread by σ has
// its error multiplied by about R/σ (the dilution of precision grows like the inverse of the angle
// the beacons subtend as seen from the tag).
//   - fewer than minBeacons beacons: neither 2D nor 3D (TDoA: x, y, offset need 3 differences + 1);
//   - clustered: σ_major < minHorizontalSpread, or R/σ_major > maxDilution;
//   - collinear: σ_minor < minHorizontalSpread, or R/σ_minor > maxDilution (the direction across
//     the line is not observable);
//   - coplanar: σ_vertical < minVerticalSpread: a 3D fix cannot tell a tag from its reflection in
//     the beacons' plane, and its height is unobservable near it (2D fixes at a known height are
//     unaffected). A planar calibration walk has the same ambiguity for the beacons (LpsCalibration.h).
//
// Per-fix dilution (tdoaDop): the TDoA design matrix of a fix at m has rows (u_iᵀ, −1), u_i the
// unit vector from beacon i to m, over (position, offset); DOP = √trace of the position block of
// (HᵀH)⁻¹ (position error σ_pos ≈ DOP · σ_range). planar: position = (x, y) only.
#include "plugins/lps/Tdoa.h"

#include <QStringList>
#include <limits>
#include <vector>

namespace athlos::lps {

struct BeaconGeometryParams {
    int minBeacons = 4;
    double minHorizontalSpread = 1.0;  // m, least principal σ in the horizontal plane
    double minVerticalSpread = 0.3;    // m, least σ across the beacons' best-fit plane (3D fixes)
    double maxDilution = 50.0;         // largest R/σ (area extent over beacon spread)
};

struct BeaconGeometryReport {
    int beacons = 0;
    double spreadMajor = 0.0;     // m, horizontal principal σ (largest)
    double spreadMinor = 0.0;     // m, horizontal principal σ (smallest)
    double spreadVertical = 0.0;  // m, smallest 3D principal σ (across the best-fit plane)
    double areaExtent = std::numeric_limits<double>::quiet_NaN();  // m, R: farthest area point from the centroid
    double dilution = std::numeric_limits<double>::quiet_NaN();    // R / σ_minor
    bool clustered = false, collinear = false, coplanar = false, tooFew = false;
    bool observable2d() const { return !tooFew && !clustered && !collinear; }
    bool observable3d() const { return observable2d() && !coplanar; }
    QStringList problems;  // human-readable reasons, empty when fine
    QString reason() const { return problems.join(QStringLiteral("; ")); }
};

// area: tag positions the beacons must serve (may be empty: absolute limits only).
BeaconGeometryReport assessBeaconGeometry(const std::vector<Vector3>& beacons, const std::vector<Vector3>& area = {},
                                          const BeaconGeometryParams& params = {});

// Dilution of precision of one TDoA fix at `tag` (see header); +inf when singular.
double tdoaDop(const std::vector<Vector3>& beacons, const Vector3& tag, bool planar);
// The same for a ToA (two-way ranging) fix: rows u_iᵀ, no offset column.
double toaDop(const std::vector<Vector3>& beacons, const Vector3& tag, bool planar);

}  // namespace athlos::lps
