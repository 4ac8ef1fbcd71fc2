#pragma once
// Unscented Kalman filter (thesis §2.3.4; Julier & Uhlmann 1997, Wan & van der Merwe 2000) with
// additive noise, Mahalanobis gating and variable time steps; the transform itself (and its angle
// handling) is in UnscentedTransform.h.
#include "core/estimation/UnscentedTransform.h"

#include <utility>

namespace athlos::estimation {

template <KalmanModel Model>
class Ukf {
public:
    static constexpr int N = Model::kStateDim;
    static constexpr int M = Model::kMeasurementDim;
    static constexpr int kPoints = 2 * N + 1;
    using ModelType = Model;
    using StateVector = Vector<N>;
    using StateMatrix = Matrix<N, N>;
    using Measurement = Vector<M>;
    using Params = UnscentedParams;

    struct State {
        StateVector x = StateVector::Zero();
        StateMatrix P = StateMatrix::Identity();
    };

    explicit Ukf(Model model, Params params = {}) : model_(std::move(model)), weights_(params) {}

    void reset(const StateVector& x0, const StateMatrix& P0) { state_ = {x0, P0}; }

    // Propagates the sigma points through F; returns C = Σ w_c (ξ_i − x̂)(F(ξ_i) − x̂')ᵀ for the
    // (unscented) RTS smoother.
    StateMatrix predict(double T, double t) {
        const auto s = propagateSigmaPoints(model_, weights_, state_.x, robustCholesky<N>(state_.P), T, t);
        const StateMatrix P = weightedOuterSum(weights_, s.d, s.d, model_.processNoise(T, t));
        const StateMatrix C = weightedOuterSum(weights_, s.dx, s.d);
        state_ = {s.mean, 0.5 * (P + P.transpose())};
        return C;
    }

    Innovation update(const Measurement& y, double t, double gate = kNoGate) {
        const auto s = measureSigmaPoints(model_, weights_, state_.x, robustCholesky<N>(state_.P), t);
        const Matrix<M, M> Sigma = weightedOuterSum(weights_, s.d, s.d, model_.measurementNoise(t));
        const Matrix<N, M> Pxy = weightedOuterSum(weights_, s.dx, s.d);
        const Measurement z = model_.residual(y, s.mean);
        const Eigen::LLT<Matrix<M, M>> llt(Sigma);
        const Innovation innovation = innovationFromFactor<M>(llt.matrixLLT(), z, gate);
        residual_ = z;
        if (!innovation.accepted) return innovation;
        const Matrix<N, M> K = llt.solve(Pxy.transpose()).transpose();
        state_.x += K * z;
        model_.normalize(state_.x);
        state_.P -= K * Sigma * K.transpose();
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
    SigmaWeights<N> weights_;
    State state_;
    Measurement residual_ = Measurement::Zero();
};

}  // namespace athlos::estimation
