#pragma once
// Track-constrained variants of the CTRA model (thesis §4.2, seed 001 §II-B):
//  - AugmentedTrackModel: the prior knowledge enters the PREDICTION. Position, speed and
//    acceleration follow CTRA; heading and turn rate are replaced by the track's:
//    φ_{k+1|k} = φ_track(p)  (eq. 4.17/4.19/4.21),  ω_{k+1|k} = v_{k|k} · κ_track(p)  (eq. 4.18/4.20,
//    κ = 1/r_track on bends, 0 on straights), evaluated at the predicted position; optionally a = 0
//    after the start phase (CA → CV). The EKF Jacobian carries ∂φ_track/∂p and ∂κ/∂p through ∂p'/∂x.
//  - PseudoTrackModel: the same constraints as PSEUDO-MEASUREMENTS (the literature baseline): the
//    measurement becomes [p_x, p_y, φ − φ_track(p), ω − v κ(p), a] with observed [x, y, 0, 0, 0]
//    and extra noise variances for the three pseudo rows.
// Both fall back to plain CTRA away from the track (a warm-up in the infield) and follow the track in
// either running direction (the sign is taken from the state's heading).
#include "core/geometry/TrackGeometry.h"
#include "core/math/Angles.h"
#include "plugins/positioning/Ctra.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace athlos::positioning {

struct TrackConstraintParams {
    std::shared_ptr<const TrackGeometry> track;
    double insideMargin = 3.0;   // m inside the kerb still counted as on the track
    double outsideMargin = 3.0;  // m outside the outermost lane line
};

// φ_track, signed κ and their gradients at p for a runner heading roughly `heading`.
struct TrackConstraint {
    bool active = false;
    bool varies = false;  // the gradients are non-zero (oval bends, polyline joints)
    double heading = 0.0;
    double curvature = 0.0;
    Eigen::Vector2d headingGradient = Eigen::Vector2d::Zero();
    Eigen::Vector2d curvatureGradient = Eigen::Vector2d::Zero();
};

// The constraint with the band of offsets that count as "on the track" precomputed, and for the
// oval the pose folded into LPS-frame constants (bend centres, straight axis and headings), so that
// the filter loop's query is closed form without rotations (eqs. 4.19, 4.21).
class TrackConstraintField {
public:
    explicit TrackConstraintField(const TrackConstraintParams& params);
    const TrackGeometry* track() const { return track_.get(); }
    double lowest() const { return lowest_; }
    double highest() const { return highest_; }

    // The constraint at a predicted position p. `heading` is the runner's heading before the step,
    // predictedHeading = heading + ωT the CTRA prediction and predictedDirection its [cos, sin]. On a
    // bend the tangent's heading is found relative to the predicted one, φ_pred + asin(u × t / ρ),
    // by a short series when the two are within 0.05 rad; that saves the atan2 that dominated the
    // augmented model's cost. Same result as trackConstraint() to 1e-12 rad (tested).
    // Forced inline: a call and a returned struct would cost a fifth of the query.
    EIGEN_ALWAYS_INLINE TrackConstraint at(const Eigen::Vector2d& p, double heading, double predictedHeading,
                                           const Eigen::Vector2d& predictedDirection) const;

private:
    std::shared_ptr<const TrackGeometry> track_;
    double lowest_ = 0.0, highest_ = 0.0;
    bool oval_ = false;
    Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();  // track centre (LPS)
    Eigen::Vector2d axis_ = Eigen::Vector2d::UnitX();   // track-frame x axis (LPS)
    Eigen::Vector2d centre_[2];                         // bend centres: +x (bend 1), −x (bend 2)
    double halfStraight_ = 0.0, kerbRadius_ = 0.0;
    double straightHeading_[2] = {0.0, 0.0};  // running direction: home (y < 0), back straight
    double reversedHeading_[2] = {0.0, 0.0};  // the same + π
};

TrackConstraint trackConstraint(const TrackConstraintField& field, const Eigen::Vector2d& p, double heading);

EIGEN_ALWAYS_INLINE TrackConstraint TrackConstraintField::at(const Eigen::Vector2d& p, double heading,
                                                             double predictedHeading,
                                                             const Eigen::Vector2d& predictedDirection) const {
    if (!oval_) return trackConstraint(*this, p, heading);
    constexpr double pi = std::numbers::pi;
    TrackConstraint c;
    const Eigen::Vector2d r = p - origin_;
    const double along = axis_.dot(r);
    if (std::abs(along) <= halfStraight_) {
        // Straights (eq. 4.19): a constant heading, κ = 0 and no gradients.
        const double across = axis_.x() * r.y() - axis_.y() * r.x();
        const double d = std::abs(across) - kerbRadius_;
        if (d < lowest_ || d > highest_) return c;
        const int back = across >= 0.0 ? 1 : 0;
        const bool reverse = std::abs(math::wrapAngle(heading - straightHeading_[back])) > pi / 2;
        c.active = true;
        c.heading = reverse ? reversedHeading_[back] : straightHeading_[back];
        return c;
    }
    // Bends (eq. 4.21), in LPS coordinates: the running direction is the radius turned left.
    const Eigen::Vector2d rel = p - centre_[along > 0.0 ? 0 : 1];
    const double rho2 = std::max(rel.squaredNorm(), 1e-12);
    // 1/ρ² and √ρ² run in parallel; 1/ρ = ρ · 1/ρ² then costs a multiply instead of a division that
    // waits for the square root (the loop is latency-bound here).
    const double invRho2 = 1.0 / rho2, rho = std::sqrt(rho2), invRho = rho * invRho2;
    const double d = rho - kerbRadius_;
    if (d < lowest_ || d > highest_) return c;
    c.active = true;
    c.varies = true;
    const Eigen::Vector2d tangent(-rel.y(), rel.x());  // running direction × ρ
    // sin ∠(u, t) = (u × t)/ρ for the unit u. |sin| ≤ 0.05 keeps the s⁹ remainder of the asin series
    // below 1e-13; |ωT| < 1 rules out that the heading before the step is reversed against the tangent.
    const Eigen::Vector2d& u = predictedDirection;
    const double s = (u.x() * tangent.y() - u.y() * tangent.x()) * invRho;
    bool reverse = false;
    if (u.dot(tangent) > 0.0 && std::abs(s) <= 0.05 && std::abs(predictedHeading - heading) < 1.0) {
        const double s2 = s * s;
        c.heading =
            math::wrapAngle(predictedHeading + s * ((1.0 + s2 * (1.0 / 6)) + s2 * s2 * (3.0 / 40 + s2 * (5.0 / 112))));
    } else {
        const double tangentHeading = std::atan2(tangent.y(), tangent.x());
        reverse = std::abs(math::wrapAngle(heading - tangentHeading)) > pi / 2;
        c.heading = reverse ? math::wrapAngle(tangentHeading + pi) : tangentHeading;
    }
    c.curvature = reverse ? -invRho : invRho;
    c.headingGradient = tangent * invRho2;
    c.curvatureGradient = rel * ((reverse ? invRho2 : -invRho2) * invRho);
    return c;
}

class AugmentedTrackModel : public estimation::ModelDefaults<6, 2> {
public:
    struct Params {
        CtraNoise noise;
        TrackConstraintParams constraint;
        double cvAfter = std::numeric_limits<double>::infinity();
    };

    explicit AugmentedTrackModel(Params params) : params_(std::move(params)), field_(params_.constraint) {}

    StateVector predict(const StateVector& x, double T, double t, StateMatrix* jacobian = nullptr) const;
    StateMatrix processNoise(double T, double) const { return ctraProcessNoise(params_.noise, T); }
    Measurement measure(const StateVector& x, double) const { return x.head<2>(); }
    MeasurementJacobian measurementJacobian(const StateVector&, double) const {
        MeasurementJacobian C = MeasurementJacobian::Zero();
        C(0, kPx) = C(1, kPy) = 1.0;
        return C;
    }
    MeasurementMatrix measurementNoise(double) const {
        return Eigen::Vector2d(params_.noise.rX, params_.noise.rY).asDiagonal();
    }
    StateVector difference(const StateVector& a, const StateVector& b) const { return ctraDifference(a, b); }
    void normalize(StateVector& x) const { ctraNormalize(x); }

    static Measurement observation(const Eigen::Vector2d& p) { return p; }
    static Kinematics kinematics(const StateVector& x) { return CtraModel::kinematics(x); }
    const Params& params() const { return params_; }

private:
    Params params_;
    TrackConstraintField field_;
};

class PseudoTrackModel : public estimation::ModelDefaults<6, 5> {
public:
    struct Params {
        CtraNoise noise;
        TrackConstraintParams constraint;
        double cvAfter = std::numeric_limits<double>::infinity();  // a = 0 pseudo-measurement from here
        double rHeading = 0.01;                                    // rad², pseudo-measurement φ − φ_track
        double rTurnRate = 0.01;                                   // rad²/s², pseudo-measurement ω − v κ
        double rAccel = 0.1;                                       // m²/s⁴, pseudo-measurement a
    };

    explicit PseudoTrackModel(Params params) : params_(std::move(params)), field_(params_.constraint) {}

    StateVector predict(const StateVector& x, double T, double, StateMatrix* jacobian = nullptr) const {
        return ctraPredict(x, T, false, jacobian);
    }
    StateMatrix processNoise(double T, double) const { return ctraProcessNoise(params_.noise, T); }
    Measurement measure(const StateVector& x, double t) const;
    MeasurementJacobian measurementJacobian(const StateVector& x, double t) const;
    MeasurementMatrix measurementNoise(double) const {
        Measurement r;
        r << params_.noise.rX, params_.noise.rY, params_.rHeading, params_.rTurnRate, params_.rAccel;
        return r.asDiagonal();
    }
    Measurement residual(const Measurement& y, const Measurement& yHat) const {
        Measurement z = y - yHat;
        z[2] = math::wrapAngle(z[2]);
        return z;
    }
    StateVector difference(const StateVector& a, const StateVector& b) const { return ctraDifference(a, b); }
    void normalize(StateVector& x) const { ctraNormalize(x); }

    static Measurement observation(const Eigen::Vector2d& p) {
        Measurement y = Measurement::Zero();
        y.head<2>() = p;
        return y;
    }
    static Kinematics kinematics(const StateVector& x) { return CtraModel::kinematics(x); }
    const Params& params() const { return params_; }

private:
    Params params_;
    TrackConstraintField field_;
};

}  // namespace athlos::positioning
