#include "plugins/positioning/Ctra.h"

#include "core/math/Angles.h"

#include <cmath>
#include <numbers>

namespace athlos::positioning {

CtraIncrement ctraIncrement(double v, double a, double phi, double omega, double T) {
    CtraIncrement r;
    const double c0 = std::cos(phi), s0 = std::sin(phi);
    if (std::abs(omega * T) < 1e-3) {
        // cos(φ+ωt) ≈ cos φ − ωt sin φ − ½ω²t² cos φ (and likewise sin): relative error (ωT)³/6.
        const double I0 = v * T + 0.5 * a * T * T;
        const double I1 = 0.5 * v * T * T + a * T * T * T / 3.0;
        const double I2 = v * T * T * T / 3.0 + 0.25 * a * T * T * T * T;
        const double w2 = 0.5 * omega * omega;
        r.delta = {I0 * c0 - omega * I1 * s0 - w2 * I2 * c0, I0 * s0 + omega * I1 * c0 - w2 * I2 * s0};
        auto partial = [&](double d0, double d1, double d2) {
            return Eigen::Vector2d(d0 * c0 - omega * d1 * s0 - w2 * d2 * c0, d0 * s0 + omega * d1 * c0 - w2 * d2 * s0);
        };
        r.dV = partial(T, 0.5 * T * T, T * T * T / 3.0);
        r.dA = partial(0.5 * T * T, T * T * T / 3.0, 0.25 * T * T * T * T);
        r.dOmega = {-I1 * s0 - omega * I2 * c0, I1 * c0 - omega * I2 * s0};
        const double wT = omega * T, hw2 = 0.5 * wT * wT;
        r.direction = {c0 - wT * s0 - hw2 * c0, s0 + wT * c0 - hw2 * s0};
    } else {
        // Closed form (digest §2, standard CTRA).
        const double th = phi + omega * T, c1 = std::cos(th), s1 = std::sin(th);
        const double v1 = v + a * T, w = omega, w2 = w * w, w3 = w2 * w;
        const double A = v1 * w * s1 + a * c1 - v * w * s0 - a * c0;
        const double B = -v1 * w * c1 + a * s1 + v * w * c0 - a * s0;
        r.delta = {A / w2, B / w2};
        r.dV = {(s1 - s0) / w, (c0 - c1) / w};
        r.dA = {(w * T * s1 + c1 - c0) / w2, (-w * T * c1 + s1 - s0) / w2};
        const double dA = v1 * s1 + v1 * w * T * c1 - a * T * s1 - v * s0;
        const double dB = -v1 * c1 + v1 * w * T * s1 + a * T * c1 + v * c0;
        r.dOmega = {dA / w2 - 2.0 * A / w3, dB / w2 - 2.0 * B / w3};
        r.direction = {c1, s1};
    }
    r.dPhi = {-r.delta.y(), r.delta.x()};  // rotating the whole arc by dφ
    return r;
}

Vector<6> ctraPredict(const Vector<6>& x, double T, bool constantVelocity, Matrix<6, 6>* jacobian,
                      Eigen::Vector2d* direction) {
    const double a = constantVelocity ? 0.0 : x[kA];
    const CtraIncrement inc = ctraIncrement(x[kV], a, x[kPhi], x[kOmega], T);
    Vector<6> y;
    y << x[kPx] + inc.delta.x(), x[kPy] + inc.delta.y(), x[kV] + a * T, a, x[kPhi] + x[kOmega] * T, x[kOmega];
    if (direction) *direction = inc.direction;
    if (!jacobian) return y;
    Matrix<6, 6>& F = *jacobian;
    F.setIdentity();
    F.block<2, 1>(0, kV) = inc.dV;
    F.block<2, 1>(0, kA) = constantVelocity ? Eigen::Vector2d::Zero() : inc.dA;
    F.block<2, 1>(0, kPhi) = inc.dPhi;
    F.block<2, 1>(0, kOmega) = inc.dOmega;
    if (constantVelocity) {
        F(kA, kA) = 0.0;
    } else {
        F(kV, kA) = T;
    }
    F(kPhi, kOmega) = T;
    return y;
}

Matrix<6, 6> ctraProcessNoise(const CtraNoise& n, double T) {
    Vector<6> q;
    q << n.qPosition, n.qPosition, n.qSpeed, n.qAccel, n.qHeading, n.qTurnRate;
    return (q * T).asDiagonal();
}

Vector<6> ctraDifference(const Vector<6>& a, const Vector<6>& b) {
    Vector<6> d = a - b;
    d[kPhi] = math::wrapAngle(d[kPhi]);
    return d;
}

void ctraNormalize(Vector<6>& x) { x[kPhi] = math::wrapAngle(x[kPhi]); }

Kinematics CtraModel::kinematics(const StateVector& x) {
    if (x[kV] >= 0.0) return {x[kPx], x[kPy], x[kV], x[kPhi], x[kOmega], x[kA]};
    return {x[kPx], x[kPy], -x[kV], math::wrapAngle(x[kPhi] + std::numbers::pi), x[kOmega], -x[kA]};
}

CtraModel::StateVector CtraModel::predict(const StateVector& x, double T, double t, StateMatrix* jacobian) const {
    return ctraPredict(x, T, constantVelocity(t), jacobian);
}
CtraModel::StateMatrix CtraModel::processNoise(double T, double) const { return ctraProcessNoise(params_.noise, T); }
CtraModel::StateVector CtraModel::difference(const StateVector& a, const StateVector& b) const {
    return ctraDifference(a, b);
}
void CtraModel::normalize(StateVector& x) const { ctraNormalize(x); }

}  // namespace athlos::positioning
