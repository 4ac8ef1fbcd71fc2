#include "plugins/inertial/SegmentCalibration.h"

#include "core/math/Angles.h"
#include "core/math/PrincipalAxis.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace athlos::inertial {

using math::Vec3;

Expected<SegmentCalibration::Result> SegmentCalibration::calibrate(std::span<const Vec3> staticAcc,
                                                                   std::span<const Vec3> movementGyr,
                                                                   double movementDt) const {
    if (staticAcc.empty()) return makeError(QStringLiteral("the static (upright) window has no samples"));
    if (movementGyr.size() < 10) return makeError(QStringLiteral("the movement window has fewer than 10 samples"));
    Vec3 up = Vec3::Zero();
    for (const Vec3& a : staticAcc) up += a;
    up /= double(staticAcc.size());
    if (up.norm() < 5.0 || up.norm() > 15.0)
        return makeError(
            QStringLiteral("the mean acceleration in the static window is %1 m/s², not gravity: the sensor was "
                           "not at rest")
                .arg(up.norm(), 0, 'f', 2));
    Result r;
    r.superior = up.normalized();

    // PCA about the origin: a back-and-forth rotation has near-zero mean rate, and the second moment
    // (not the covariance) keeps a one-way turn on its axis too.
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    for (const Vec3& w : movementGyr) moment += w * w.transpose();
    const math::PrincipalAxis pca = math::principalAxisOfMoment(moment);
    if (pca.share == 0.0) return makeError(QStringLiteral("the segment does not rotate in the movement window"));
    r.axisShare = pca.share;
    if (r.axisShare < 0.5)
        return makeError(
            QStringLiteral("the movement has no dominant rotation axis (%1 % of the angular velocity on the main "
                           "axis); repeat slow sagittal movements (squats)")
                .arg(100.0 * r.axisShare, 0, 'f', 0));
    Vec3 axis = pca.axis;

    // The direction of the first clear turn fixes the sign (see the header).
    double turned = 0.0;
    for (const Vec3& w : movementGyr) {
        turned += w.dot(axis) * movementDt;
        if (std::abs(turned) >= params_.decisionAngle) break;
    }
    if (std::abs(turned) < params_.decisionAngle)
        return makeError(
            QStringLiteral("the segment turned less than %1° about the movement axis; the sign of the axis is "
                           "undetermined")
                .arg(params_.decisionAngle / math::kDeg, 0, 'f', 0));
    if (turned * params_.firstRotation < 0.0) axis = -axis;
    r.functional = axis;

    r.orthogonality = std::asin(std::clamp(std::abs(axis.dot(r.superior)), 0.0, 1.0));
    // Gravity is the more reliable axis: keep Y, make Z orthogonal to it, X completes the frame.
    const Vec3 f = (axis - axis.dot(r.superior) * r.superior).normalized();
    Vec3 x;
    if (params_.functionalAxis == 0) {
        x = f;  // X ⟂ Y; Z = X × Y
        r.mediolateral = x.cross(r.superior).normalized();
    } else {
        x = r.superior.cross(f).normalized();
        r.mediolateral = x.cross(r.superior).normalized();
    }
    Eigen::Matrix3d segmentInSensor;
    segmentInSensor << x, r.superior, r.mediolateral;
    r.mount = math::Quat(segmentInSensor).normalized();
    return r;
}

}  // namespace athlos::inertial
