#pragma once
// Shared types of the estimation framework (EKF, UKF, SRUKF, RTS / fixed-lag smoothing, robust
// runner, noise estimation). Filters are templates over a motion/measurement Model with fixed
// sizes, so that the inner loop works on stack matrices (Eigen fixed-size) without allocation.
//
// What a model must provide is the concept KalmanModel below (EkfModel adds the measurement
// Jacobian); ModelDefaults<N, M> supplies the types, plain-subtraction residual/difference and a
// no-op normalize, so a model usually writes predict, processNoise, measure, measurementNoise
// (and measurementJacobian for the EKF).
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <cmath>
#include <concepts>
#include <limits>

namespace athlos::estimation {

template <int N>
using Vector = Eigen::Matrix<double, N, 1>;
template <int R, int C>
using Matrix = Eigen::Matrix<double, R, C>;

template <int N, int M>
struct ModelDefaults {
    static constexpr int kStateDim = N;
    static constexpr int kMeasurementDim = M;
    using StateVector = Vector<N>;
    using StateMatrix = Matrix<N, N>;
    using Measurement = Vector<M>;
    using MeasurementMatrix = Matrix<M, M>;
    using MeasurementJacobian = Matrix<M, N>;

    Measurement residual(const Measurement& y, const Measurement& yHat) const { return y - yHat; }
    StateVector difference(const StateVector& a, const StateVector& b) const { return a - b; }
    void normalize(StateVector&) const {}
};

// The model requirement of Ukf, SrUkf and RtsSmoother (all members const; t = time at the end of
// the step in s, T = step in s):
//   kStateDim, kMeasurementDim                   N and M (static constexpr int)
//   predict(x, T, t, jacobian)                   F(x, T) (eq. 2.10); fills Φ = ∂F/∂x when jacobian !=
//                                                nullptr (EKF). One call for both because the Jacobian
//                                                reuses the prediction's trigonometry and map queries.
//   processNoise(T, t)                           Q_k
//   measure(x, t)                                h(x)
//   measurementNoise(t)                          R
//   residual(y, yHat)                            y − ŷ (wraps angles)
//   difference(a, b)                             a − b of two states (wraps angles)
//   normalize(x)                                 puts x back in its domain, e.g. wraps the heading
// The motion half alone (what the RTS smoother needs): prediction, process noise and state algebra.
// Filters that bring their own measurement model (per-measurement beacons, see
// plugins/positioning/RangeFilter.h) only need this.
template <class Model>
concept MotionModel = requires(const Model& model, Vector<Model::kStateDim>& x,
                               Matrix<Model::kStateDim, Model::kStateDim>* jacobian, double T, double t) {
    requires Model::kStateDim >
    0;
    { model.predict(x, T, t, jacobian) } -> std::convertible_to<Vector<Model::kStateDim>>;
    { model.processNoise(T, t) } -> std::convertible_to<Matrix<Model::kStateDim, Model::kStateDim>>;
    { model.difference(x, x) } -> std::convertible_to<Vector<Model::kStateDim>>;
    model.normalize(x);
};

template <class Model>
concept KalmanModel = MotionModel<Model> &&
    requires(const Model& model, const Vector<Model::kStateDim>& x, const Vector<Model::kMeasurementDim>& y, double t) {
    requires Model::kMeasurementDim >
    0;
    { model.measure(x, t) } -> std::convertible_to<Vector<Model::kMeasurementDim>>;
    { model.measurementNoise(t) } -> std::convertible_to<Matrix<Model::kMeasurementDim, Model::kMeasurementDim>>;
    { model.residual(y, y) } -> std::convertible_to<Vector<Model::kMeasurementDim>>;
};

// The EKF's requirement: a KalmanModel with the measurement Jacobian C = ∂h/∂x (M × N).
template <class Model>
concept EkfModel = KalmanModel<Model> && requires(const Model& model, const Vector<Model::kStateDim>& x, double t) {
    { model.measurementJacobian(x, t) } -> std::convertible_to<Matrix<Model::kMeasurementDim, Model::kStateDim>>;
};

// Outcome of one measurement update (also reported when the update was gated out).
struct Innovation {
    double mahalanobis2 = 0.0;  // d_k² = z_kᵀ Σ_k⁻¹ z_k                              (eq. 4.1, squared)
    double logDetSigma = 0.0;   // log det Σ_k, for the innovation likelihood (eq. 4.9)
    bool accepted = true;       // false: d_k² > α, update skipped (outlier)
};

constexpr double kNoGate = std::numeric_limits<double>::infinity();

// The gated innovation of z from a lower Cholesky factor L of Σ (only L's lower triangle is read):
// d² = |L⁻¹ z|², log det Σ = 2 Σ log|L_ii| (the unscented filters; the EKF inverts Σ directly).
template <int M>
Innovation innovationFromFactor(const Matrix<M, M>& L, const Vector<M>& z, double gate) {
    Innovation innovation;
    innovation.mahalanobis2 = Vector<M>(L.template triangularView<Eigen::Lower>().solve(z)).squaredNorm();
    innovation.logDetSigma = 2.0 * L.diagonal().array().abs().log().sum();
    innovation.accepted = innovation.mahalanobis2 <= gate;
    return innovation;
}

// In-place rank-1 Cholesky update/downdate of a lower-triangular factor: L Lᵀ + sign·v vᵀ.
// Returns false when a downdate would lose positive definiteness (L is then left unchanged).
template <int N>
bool choleskyRankOne(Matrix<N, N>& L, Vector<N> v, double sign) {
    const Matrix<N, N> backup = L;
    for (int k = 0; k < N; ++k) {
        const double r2 = L(k, k) * L(k, k) + sign * v(k) * v(k);
        if (!(r2 > 0.0)) {
            L = backup;
            return false;
        }
        const double r = std::sqrt(r2), c = r / L(k, k), s = v(k) / L(k, k);
        L(k, k) = r;
        if (k + 1 < N) {
            const int rest = N - k - 1;
            L.col(k).tail(rest) = (L.col(k).tail(rest) + sign * s * v.tail(rest)) / c;
            v.tail(rest) = c * v.tail(rest) - s * L.col(k).tail(rest);
        }
    }
    return true;
}

// Lower Cholesky factor with a tiny diagonal jitter fallback for semi-definite matrices
// (Q with zero position entries, predicted covariances right after a reset of a constrained state).
template <int N>
Matrix<N, N> robustCholesky(const Matrix<N, N>& P) {
    Eigen::LLT<Matrix<N, N>> llt(P);
    double jitter = 1e-12 * std::max(P.diagonal().cwiseAbs().maxCoeff(), 1e-12);
    while (llt.info() != Eigen::Success && jitter < 1e6) {
        llt.compute(P + jitter * Matrix<N, N>::Identity());
        jitter *= 10.0;
    }
    return llt.matrixL();
}

}  // namespace athlos::estimation
