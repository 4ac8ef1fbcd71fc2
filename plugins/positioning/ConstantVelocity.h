#pragma once
// Constant velocity model x = [p_x p_y v_x v_y]ᵀ with continuous white-noise acceleration
// (Q per axis q·[[T³/3, T²/2], [T²/2, T]]): the simplest generic model, for comparison and for
// objects without a preferred direction. Linear, so EKF = KF.
#include "plugins/positioning/Ctra.h"

#include <cmath>

namespace athlos::positioning {

class ConstantVelocityModel : public estimation::ModelDefaults<4, 2> {
public:
    struct Params {
        double qAccel = 1.0;  // m²/s³, white-noise acceleration density per axis
        double rX = 0.01;     // m²
        double rY = 0.01;
    };

    ConstantVelocityModel() = default;
    explicit ConstantVelocityModel(Params params) : params_(params) {}

    StateVector predict(const StateVector& x, double T, double, StateMatrix* jacobian = nullptr) const {
        StateVector y = x;
        y.head<2>() += T * x.tail<2>();
        if (jacobian) {
            jacobian->setIdentity();
            (*jacobian)(0, 2) = (*jacobian)(1, 3) = T;
        }
        return y;
    }
    StateMatrix processNoise(double T, double) const {
        const double q = params_.qAccel, T2 = T * T;
        StateMatrix Q = StateMatrix::Zero();
        for (int axis = 0; axis < 2; ++axis) {
            Q(axis, axis) = q * T2 * T / 3.0;
            Q(axis, axis + 2) = Q(axis + 2, axis) = q * T2 / 2.0;
            Q(axis + 2, axis + 2) = q * T;
        }
        return Q;
    }
    Measurement measure(const StateVector& x, double) const { return x.head<2>(); }
    MeasurementJacobian measurementJacobian(const StateVector&, double) const {
        MeasurementJacobian C = MeasurementJacobian::Zero();
        C(0, 0) = C(1, 1) = 1.0;
        return C;
    }
    MeasurementMatrix measurementNoise(double) const { return Eigen::Vector2d(params_.rX, params_.rY).asDiagonal(); }

    static Measurement observation(const Eigen::Vector2d& p) { return p; }
    static Kinematics kinematics(const StateVector& x) {
        return {x[0], x[1], x.tail<2>().norm(), std::atan2(x[3], x[2]), 0.0, 0.0};
    }

private:
    Params params_;
};

}  // namespace athlos::positioning
