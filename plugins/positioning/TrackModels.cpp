#include "plugins/positioning/TrackModels.h"

#include <cmath>

namespace athlos::positioning {

TrackConstraintField::TrackConstraintField(const TrackConstraintParams& params) : track_(params.track) {
    if (!track_) return;
    // The lanes lie right of the reference line (kerb or polyline): 0 ≤ d ≤ lanes · width.
    const bool oval = track_->kind() == TrackGeometry::Kind::Oval;
    const double width = oval ? track_->ovalParams().lanes * track_->ovalParams().laneWidth
                              : track_->polylineParams().lanes * track_->polylineParams().laneWidth;
    lowest_ = -params.insideMargin;
    highest_ = width + params.outsideMargin;
}

namespace {

// Running against the track's direction: heading + π and the turn changes sign.
TrackConstraint constraintFrom(const TrackConstraintField& field, const TrackQuery& q, double heading) {
    TrackConstraint c;
    if (q.d < field.lowest() || q.d > field.highest()) return c;
    c.active = true;
    const bool reverse = std::abs(TrackGeometry::wrapAngle(heading - q.heading)) > M_PI / 2;
    c.heading = reverse ? TrackGeometry::wrapAngle(q.heading + M_PI) : q.heading;
    c.curvature = reverse ? -q.curvature : q.curvature;
    c.headingGradient = q.headingGradient;
    c.curvatureGradient = reverse ? Eigen::Vector2d(-q.curvatureGradient) : q.curvatureGradient;
    return c;
}

}  // namespace

TrackConstraint trackConstraint(const TrackConstraintField& field, const Eigen::Vector2d& p, double heading) {
    if (!field.track()) return {};
    return constraintFrom(field, field.track()->field(p), heading);
}

TrackConstraint trackConstraint(const TrackConstraintField& field, const Eigen::Vector2d& p, double heading,
                                double predictedHeading, const Eigen::Vector2d& predictedDirection) {
    if (!field.track()) return {};
    return constraintFrom(field, field.track()->field(p, predictedHeading, predictedDirection), heading);
}

AugmentedTrackModel::StateVector AugmentedTrackModel::predict(const StateVector& x, double T, double t,
                                                             StateMatrix* jacobian) const {
    Eigen::Vector2d direction;
    StateVector y = ctraPredict(x, T, t > params_.cvAfter, jacobian, &direction);
    const TrackConstraint c = trackConstraint(field_, y.head<2>(), x[kPhi], y[kPhi], direction);
    if (!c.active) return y;  // off the track: generic CTRA
    y[kPhi] = c.heading;              // eq. 4.17
    y[kOmega] = x[kV] * c.curvature;  // eq. 4.18 (straights, κ = 0) / 4.20 (bends, κ = 1/r)
    if (jacobian) {
        StateMatrix& F = *jacobian;
        if (c.headingGradient.isZero(0.0) && c.curvatureGradient.isZero(0.0)) {
            // Straights: φ and κ do not depend on p, so φ' and ω' = v κ depend on v alone.
            F.row(kPhi).setZero();
            F.row(kOmega).setZero();
            F(kOmega, kV) = c.curvature;
        } else {
            // ∂p'/∂x = rows kPx, kPy of F (the track terms are evaluated at p'); those rows are not
            // overwritten, so the products are formed in place without a 2×6 temporary.
            F.row(kPhi).noalias() = c.headingGradient.transpose() * F.topRows<2>();
            F.row(kOmega).noalias() = (x[kV] * c.curvatureGradient).transpose() * F.topRows<2>();
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
        h[2] = TrackGeometry::wrapAngle(x[kPhi] - c.heading);
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
