#pragma once
// Extended Kalman filter (thesis §2.3.3, eqs. 2.11–2.19) with Mahalanobis gating (eq. 4.1) and
// variable time steps. The filter owns its state; the robust runner drives predict()/update().
#include "core/estimation/KalmanTypes.h"

#include <Eigen/LU>
#include <utility>

namespace athlos::estimation {

template <EkfModel Model>
class Ekf {
public:
    static constexpr int N = Model::kStateDim;
    static constexpr int M = Model::kMeasurementDim;
    using ModelType = Model;
    using StateVector = Vector<N>;
    using StateMatrix = Matrix<N, N>;
    using Measurement = Vector<M>;

    struct Params {};  // the EKF has no tuning besides the model's noise

    struct State {
        StateVector x = StateVector::Zero();
        StateMatrix P = StateMatrix::Identity();
    };

    explicit Ekf(Model model, Params params = {}) : model_(std::move(model)), params_(params) {}

    void reset(const StateVector& x0, const StateMatrix& P0) { state_ = {x0, P0}; }

    // x_{k+1|k} = F(x_{k|k}, T_k), P_{k+1|k} = Φ P Φᵀ + Q (eqs. 2.11, 2.12). Returns the
    // cross-covariance C = cov(x_k, x_{k+1}) = P_{k|k} Φᵀ, which the RTS smoother needs.
    StateMatrix predict(double T, double t) {
        StateMatrix Phi;
        state_.x = model_.predict(state_.x, T, t, &Phi);
        model_.normalize(state_.x);
        // lazyProduct: coefficient-wise kernels beat the GEMM path at these small fixed sizes.
        const StateMatrix C = state_.P.lazyProduct(Phi.transpose());
        state_.P = Phi.lazyProduct(C) + model_.processNoise(T, t);
        return C;
    }

    // z = y − h(x), Σ = C P Cᵀ + R, d² = zᵀ Σ⁻¹ z; if d² ≤ gate: K = P Cᵀ Σ⁻¹, x += K z,
    // P = (I − K C) P (eqs. 2.15–2.19, 4.1).
    Innovation update(const Measurement& y, double t, double gate = kNoGate) {
        const Matrix<M, N> H = model_.measurementJacobian(state_.x, t);
        const Measurement z = model_.residual(y, model_.measure(state_.x, t));
        const Matrix<N, M> PHt = state_.P.lazyProduct(H.transpose());
        const Matrix<M, M> Sigma = H.lazyProduct(PHt) + model_.measurementNoise(t);
        Innovation innovation;
        Matrix<M, M> SigmaInv;
        if constexpr (M <= 4) {
            // Closed-form inverse of the small innovation covariance (the LPS case M = 2).
            SigmaInv = Sigma.inverse();
            innovation.logDetSigma = std::log(Sigma.determinant());
        } else {
            const Eigen::LLT<Matrix<M, M>> llt(Sigma);
            SigmaInv = llt.solve(Matrix<M, M>::Identity());
            innovation.logDetSigma = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
        }
        innovation.mahalanobis2 = z.dot(SigmaInv * z);
        innovation.accepted = innovation.mahalanobis2 <= gate;
        residual_ = z;
        if (!innovation.accepted) return innovation;
        const Matrix<N, M> K = PHt.lazyProduct(SigmaInv);
        state_.x += K * z;
        model_.normalize(state_.x);
        state_.P -= K.lazyProduct(PHt.transpose());
        state_.P = 0.5 * (state_.P + state_.P.transpose());
        return innovation;
    }

    // Scales the covariance (re-acquisition after the filter lost the track).
    void inflate(double factor) { state_.P *= factor; }
    // Innovation y − ŷ of the last update() (also when it was gated out).
    const Measurement& residual() const { return residual_; }
    const State& state() const { return state_; }
    const StateVector& x() const { return state_.x; }
    StateMatrix covariance() const { return state_.P; }
    const Model& model() const { return model_; }
    Model& model() { return model_; }

private:
    Model model_;
    Params params_;
    State state_;
    Measurement residual_ = Measurement::Zero();
};

}  // namespace athlos::estimation
