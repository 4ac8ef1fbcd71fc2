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
#include "plugins/positioning/Ctra.h"

#include <memory>

namespace athlos::positioning {

struct TrackConstraintParams {
    std::shared_ptr<const TrackGeometry> track;
    double insideMargin = 3.0;   // m inside the kerb still counted as on the track
    double outsideMargin = 3.0;  // m outside the outermost lane line
};

// The constraint with the band of offsets that count as "on the track" precomputed (filter loop).
class TrackConstraintField {
public:
    explicit TrackConstraintField(const TrackConstraintParams& params);
    const TrackGeometry* track() const { return track_.get(); }
    double lowest() const { return lowest_; }
    double highest() const { return highest_; }

private:
    std::shared_ptr<const TrackGeometry> track_;
    double lowest_ = 0.0, highest_ = 0.0;
};

// φ_track, signed κ and their gradients at p for a runner heading roughly `heading`.
struct TrackConstraint {
    bool active = false;
    double heading = 0.0;
    double curvature = 0.0;
    Eigen::Vector2d headingGradient = Eigen::Vector2d::Zero();
    Eigen::Vector2d curvatureGradient = Eigen::Vector2d::Zero();
};
TrackConstraint trackConstraint(const TrackConstraintField& field, const Eigen::Vector2d& p, double heading);
// The same at a predicted position p whose predicted heading (and its direction vector) is known:
// the track heading is then found relative to it without an atan2 (TrackGeometry::field).
TrackConstraint trackConstraint(const TrackConstraintField& field, const Eigen::Vector2d& p, double heading,
                                double predictedHeading, const Eigen::Vector2d& predictedDirection);

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
        double rHeading = 0.01;   // rad², pseudo-measurement φ − φ_track
        double rTurnRate = 0.01;  // rad²/s², pseudo-measurement ω − v κ
        double rAccel = 0.1;      // m²/s⁴, pseudo-measurement a
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
        z[2] = TrackGeometry::wrapAngle(z[2]);
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
