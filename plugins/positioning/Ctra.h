#pragma once
// Constant turn rate and acceleration (CTRA) motion model for x = [p_x p_y v a φ ω]ᵀ (thesis §2.3.2,
// seed 001 eq. 1) with a variable step T and the exact closed-form position integral; for |ωT| → 0
// a second-order series in ω replaces the 1/ω² form, whose cancellation would otherwise destroy
// the result (continuity at ω = 0 is tested). Measurement: the LPS position h(x) = [p_x p_y]ᵀ (eq. 2).
#include "core/estimation/KalmanTypes.h"

#include <Eigen/Core>
#include <limits>

namespace athlos::positioning {

using estimation::Matrix;
using estimation::Vector;

enum StateIndex { kPx = 0, kPy = 1, kV = 2, kA = 3, kPhi = 4, kOmega = 5 };

// Position increment of one CTRA step and its partial derivatives.
struct CtraIncrement {
    Eigen::Vector2d delta;                 // Δp
    Eigen::Vector2d dV, dA, dPhi, dOmega;  // ∂Δp/∂v, ∂Δp/∂a, ∂Δp/∂φ, ∂Δp/∂ω
    Eigen::Vector2d direction;  // [cos, sin](φ + ωT), the predicted heading's direction (to (ωT)³/6 for small ωT)
};

// Δp = ∫₀ᵀ (v + a t) [cos(φ + ω t), sin(φ + ω t)]ᵀ dt
CtraIncrement ctraIncrement(double v, double a, double phi, double omega, double T);

// Process noise densities (per second: Q_k = diag(q)·T_k, so inserting output-grid steps does not
// change the total noise of an interval) and measurement noise variances.
struct CtraNoise {
    double qPosition = 1e-3;  // m²/s      (thesis: 0; estimated with noise=auto)
    double qSpeed = 0.1;      // m²/s³
    double qAccel = 1.0;      // m²/s⁵
    double qHeading = 0.01;   // rad²/s
    double qTurnRate = 0.05;  // rad²/s³
    double rX = 0.01;         // m²
    double rY = 0.01;         // m²
};

// Kinematic summary every positioning model can give for its output columns (speed ≥ 0, heading =
// direction of travel).
struct Kinematics {
    double x = 0, y = 0, speed = 0, heading = 0, turnRate = 0, accel = 0;
};

class CtraModel : public estimation::ModelDefaults<6, 2> {
public:
    struct Params {
        CtraNoise noise;
        double cvAfter = std::numeric_limits<double>::infinity();  // s: a = 0 from this time on (CA → CV)
    };

    CtraModel() = default;
    explicit CtraModel(Params params) : params_(params) {}

    StateVector predict(const StateVector& x, double T, double t, StateMatrix* jacobian = nullptr) const;
    StateMatrix processNoise(double T, double t) const;
    Measurement measure(const StateVector& x, double) const { return x.head<2>(); }
    MeasurementJacobian measurementJacobian(const StateVector&, double) const {
        MeasurementJacobian C = MeasurementJacobian::Zero();
        C(0, kPx) = C(1, kPy) = 1.0;
        return C;
    }
    MeasurementMatrix measurementNoise(double) const {
        return Eigen::Vector2d(params_.noise.rX, params_.noise.rY).asDiagonal();
    }
    StateVector difference(const StateVector& a, const StateVector& b) const;
    void normalize(StateVector& x) const;

    static Measurement observation(const Eigen::Vector2d& p) { return p; }
    // (v, φ, a) and (−v, φ + π, −a) are the same motion, and unscented filters do settle in the mirrored
    // one (seen: M-SRUKF with v = −7.5 m/s). Reported is the direction of travel: speed ≥ 0.
    static Kinematics kinematics(const StateVector& x);

    const Params& params() const { return params_; }
    bool constantVelocity(double t) const { return t > params_.cvAfter; }

private:
    Params params_;
};

// Shared CTRA pieces for the track-constrained models.
// F(x, T) and, when jacobian != nullptr, Φ = ∂F/∂x; when direction != nullptr, the predicted
// heading's direction vector (lets the track models avoid an atan2).
Vector<6> ctraPredict(const Vector<6>& x, double T, bool constantVelocity, Matrix<6, 6>* jacobian = nullptr,
                      Eigen::Vector2d* direction = nullptr);
Matrix<6, 6> ctraProcessNoise(const CtraNoise& noise, double T);
Vector<6> ctraDifference(const Vector<6>& a, const Vector<6>& b);
void ctraNormalize(Vector<6>& x);

}  // namespace athlos::positioning
