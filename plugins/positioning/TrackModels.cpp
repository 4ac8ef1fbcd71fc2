#include "plugins/positioning/TrackModels.h"

#include "core/math/Angles.h"

#include <cmath>
#include <numbers>

namespace athlos::positioning {

TrackConstraintField::TrackConstraintField(const TrackConstraintParams& params) : track_(params.track) {
    if (!track_) return;
    // The lanes lie right of the reference line (kerb or polyline): 0 ≤ d ≤ lanes · width.
    oval_ = track_->kind() == TrackGeometry::Kind::Oval;
    const double width = oval_ ? track_->ovalParams().lanes * track_->ovalParams().laneWidth
                               : track_->polylineParams().lanes * track_->polylineParams().laneWidth;
    lowest_ = -params.insideMargin;
    highest_ = width + params.outsideMargin;
    if (!oval_) return;
    const TrackPose& pose = track_->pose();
    halfStraight_ = 0.5 * track_->ovalParams().straightLength;
    kerbRadius_ = track_->ovalParams().kerbRadius;
    origin_ = {pose.x, pose.y};
    axis_ = {std::cos(pose.rotation), std::sin(pose.rotation)};
    centre_[0] = track_->toLps({halfStraight_, 0.0});
    centre_[1] = track_->toLps({-halfStraight_, 0.0});
    for (int back = 0; back < 2; ++back) {
        straightHeading_[back] = math::wrapAngle((back ? std::numbers::pi : 0.0) + pose.rotation);
        reversedHeading_[back] = math::wrapAngle(straightHeading_[back] + std::numbers::pi);
    }
}

TrackConstraint trackConstraint(const TrackConstraintField& field, const Eigen::Vector2d& p, double heading) {
    TrackConstraint c;
    if (!field.track()) return c;
    const TrackQuery q = field.track()->field(p);
    if (q.d < field.lowest() || q.d > field.highest()) return c;
    c.active = true;
    // Running against the track's direction: heading + π and the turn changes sign.
    const bool reverse = std::abs(math::wrapAngle(heading - q.heading)) > std::numbers::pi / 2;
    c.heading = reverse ? math::wrapAngle(q.heading + std::numbers::pi) : q.heading;
    c.curvature = reverse ? -q.curvature : q.curvature;
    c.headingGradient = q.headingGradient;
    c.curvatureGradient = reverse ? Eigen::Vector2d(-q.curvatureGradient) : q.curvatureGradient;
    c.varies = !c.headingGradient.isZero(0.0) || !c.curvatureGradient.isZero(0.0);
    return c;
}

AugmentedTrackModel::StateVector AugmentedTrackModel::predict(const StateVector& x, double T, double t,
                                                              StateMatrix* jacobian) const {
    Eigen::Vector2d direction;
    StateVector y = ctraPredict(x, T, t > params_.cvAfter, jacobian, &direction);
    const TrackConstraint c = field_.at(y.head<2>(), x[kPhi], y[kPhi], direction);
    if (!c.active) return y;          // off the track: generic CTRA
    y[kPhi] = c.heading;              // eq. 4.17
    y[kOmega] = x[kV] * c.curvature;  // eq. 4.18 (straights, κ = 0) / 4.20 (bends, κ = 1/r)
    if (jacobian) {
        StateMatrix& F = *jacobian;
        if (!c.varies) {
            // Straights: φ and κ do not depend on p, so φ' and ω' = v κ depend on v alone.
            F.row(kPhi).setZero();
            F.row(kOmega).setZero();
            F(kOmega, kV) = c.curvature;
        } else {
            // Bends: row φ = ∇φ_track · ∂p'/∂x and row ω = v ∇κ · ∂p'/∂x + κ e_v, where ∂p'/∂x is rows
            // kPx, kPy of F (the track terms are evaluated at p'). Those rows are the identity in the
            // position columns, so only the four CTRA columns need products.
            const Eigen::Vector2d& gPhi = c.headingGradient;
            const Eigen::Vector2d gOmega = x[kV] * c.curvatureGradient;
            F(kPhi, kPx) = gPhi.x();
            F(kPhi, kPy) = gPhi.y();
            F(kOmega, kPx) = gOmega.x();
            F(kOmega, kPy) = gOmega.y();
            const Matrix<2, 4> dP = F.block<2, 4>(kPx, kV);  // ∂p'/∂(v, a, φ, ω)
            F.block<1, 4>(kPhi, kV).noalias() = gPhi.transpose() * dP;
            F.block<1, 4>(kOmega, kV).noalias() = gOmega.transpose() * dP;
            F(kOmega, kV) += c.curvature;
        }
    }
    return y;
}

PseudoTrackModel::Measurement PseudoTrackModel::measure(const StateVector& x, double t) const {
    Measurement h = Measurement::Zero();
    h.head<2>() = x.head<2>();
    const TrackConstraint c = trackConstraint(field_, x.head<2>(), x[kPhi]);
    if (c.active) {
        h[2] = math::wrapAngle(x[kPhi] - c.heading);
        h[3] = x[kOmega] - x[kV] * c.curvature;
    }
    if (t > params_.cvAfter) h[4] = x[kA];
    return h;
}

PseudoTrackModel::MeasurementJacobian PseudoTrackModel::measurementJacobian(const StateVector& x, double t) const {
    MeasurementJacobian H = MeasurementJacobian::Zero();
    H(0, kPx) = H(1, kPy) = 1.0;
    const TrackConstraint c = trackConstraint(field_, x.head<2>(), x[kPhi]);
    if (c.active) {
        H.block<1, 2>(2, kPx) = -c.headingGradient.transpose();
        H(2, kPhi) = 1.0;
        H.block<1, 2>(3, kPx) = -x[kV] * c.curvatureGradient.transpose();
        H(3, kV) = -c.curvature;
        H(3, kOmega) = 1.0;
    }
    if (t > params_.cvAfter) H(4, kA) = 1.0;
    return H;
}

}  // namespace athlos::positioning
