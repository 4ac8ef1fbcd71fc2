#pragma once
// Unscented Kalman filter (thesis §2.3.4; Julier & Uhlmann 1997, Wan & van der Merwe 2000) with
// additive noise, Mahalanobis gating and variable time steps. Angles in the state or measurement are
// averaged through the model's difference()/residual() relative to the central sigma point, so a
// heading near ±π does not average to 0.
#include "core/estimation/KalmanTypes.h"

#include <array>
#include <utility>

namespace athlos::estimation {

// Scaled unscented transform weights: λ = α²(d + κ) − d; w0m = λ/(d + λ),
// w0c = w0m + (1 − α² + β), wi = 1/(2(d + λ)) (digest §2; the thesis omits the −d).
struct UnscentedParams {
    double alpha = 1.0;  // spread; 1 keeps w0c > 0 (no SRUKF downdate) for d = 6
    double beta = 2.0;   // optimal for Gaussians
    double kappa = 0.0;
};

template <int N>
struct SigmaWeights {
    double gamma = 0.0;  // √(d + λ)
    double w0m = 0.0, w0c = 0.0, wi = 0.0;

    explicit SigmaWeights(const UnscentedParams& p) {
        const double lambda = p.alpha * p.alpha * (N + p.kappa) - N;
        gamma = std::sqrt(N + lambda);
        w0m = lambda / (N + lambda);
        w0c = w0m + (1.0 - p.alpha * p.alpha + p.beta);
        wi = 1.0 / (2.0 * (N + lambda));
    }
    double mean(int i) const { return i == 0 ? w0m : wi; }
    double cov(int i) const { return i == 0 ? w0c : wi; }
};

// ξ_0 = x, ξ_i = x + γ L_i, ξ_{i+d} = x − γ L_i with L a square root of P (columns).
template <class Model>
std::array<Vector<Model::kStateDim>, 2 * Model::kStateDim + 1> sigmaPoints(
    const Model& model, const Vector<Model::kStateDim>& x, const Matrix<Model::kStateDim, Model::kStateDim>& L,
    double gamma) {
    constexpr int N = Model::kStateDim;
    std::array<Vector<N>, 2 * N + 1> xi;
    xi[0] = x;
    for (int i = 0; i < N; ++i) {
        xi[1 + i] = x + gamma * L.col(i);
        xi[1 + N + i] = x - gamma * L.col(i);
        model.normalize(xi[1 + i]);
        model.normalize(xi[1 + N + i]);
    }
    return xi;
}

template <class Model>
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
        const auto xi = sigmaPoints(model_, state_.x, robustCholesky<N>(state_.P), weights_.gamma);
        std::array<StateVector, kPoints> f;
        for (int i = 0; i < kPoints; ++i) f[i] = model_.predict(xi[i], T, t, nullptr);
        StateVector mean = StateVector::Zero();
        for (int i = 1; i < kPoints; ++i) mean += weights_.mean(i) * model_.difference(f[i], f[0]);
        StateVector x = f[0] + mean;
        model_.normalize(x);
        StateMatrix P = model_.processNoise(T, t);
        StateMatrix C = StateMatrix::Zero();
        for (int i = 0; i < kPoints; ++i) {
            const StateVector df = model_.difference(f[i], x);
            P += weights_.cov(i) * df * df.transpose();
            C += weights_.cov(i) * model_.difference(xi[i], state_.x) * df.transpose();
        }
        state_ = {x, 0.5 * (P + P.transpose())};
        return C;
    }

    Innovation update(const Measurement& y, double t, double gate = kNoGate) {
        const auto xi = sigmaPoints(model_, state_.x, robustCholesky<N>(state_.P), weights_.gamma);
        std::array<Measurement, kPoints> h;
        for (int i = 0; i < kPoints; ++i) h[i] = model_.measure(xi[i], t);
        Measurement yHat = h[0];
        for (int i = 1; i < kPoints; ++i) yHat += weights_.mean(i) * model_.residual(h[i], h[0]);
        Matrix<M, M> Sigma = model_.measurementNoise(t);
        Matrix<N, M> Pxy = Matrix<N, M>::Zero();
        for (int i = 0; i < kPoints; ++i) {
            const Measurement dh = model_.residual(h[i], yHat);
            Sigma += weights_.cov(i) * dh * dh.transpose();
            Pxy += weights_.cov(i) * model_.difference(xi[i], state_.x) * dh.transpose();
        }
        const Measurement z = model_.residual(y, yHat);
        const Eigen::LLT<Matrix<M, M>> llt(Sigma);
        Innovation innovation;
        innovation.mahalanobis2 = Measurement(llt.matrixL().solve(z)).squaredNorm();
        innovation.logDetSigma = 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
        innovation.accepted = innovation.mahalanobis2 <= gate;
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
