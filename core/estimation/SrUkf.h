#pragma once
// Square-root UKF (van der Merwe & Wan 2001; thesis §2.3.5): propagates a lower Cholesky factor S
// (P = S Sᵀ) through QR decompositions and rank-1 Cholesky updates, which keeps P positive definite
// by construction. Same weights, gating and interface as Ukf.
#include "core/estimation/UnscentedTransform.h"

#include <Eigen/QR>
#include <utility>

namespace athlos::estimation {

template <KalmanModel Model>
class SrUkf {
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
        StateMatrix S = StateMatrix::Identity();  // lower triangular, P = S Sᵀ
    };

    explicit SrUkf(Model model, Params params = {}) : model_(std::move(model)), weights_(params) {}

    void reset(const StateVector& x0, const StateMatrix& P0) { state_ = {x0, robustCholesky<N>(P0)}; }

    StateMatrix predict(double T, double t) {
        const auto s = propagateSigmaPoints(model_, weights_, state_.x, state_.S, T, t);
        const StateMatrix S = spreadFactor<N>(s.d, model_.processNoise(T, t));
        const StateMatrix C = weightedOuterSum(weights_, s.dx, s.d);
        state_ = {s.mean, S};
        return C;
    }

    Innovation update(const Measurement& y, double t, double gate = kNoGate) {
        const auto s = measureSigmaPoints(model_, weights_, state_.x, state_.S, t);
        const Matrix<M, M> Sy = spreadFactor<M>(s.d, model_.measurementNoise(t));
        const Matrix<N, M> Pxy = weightedOuterSum(weights_, s.dx, s.d);
        const Measurement z = model_.residual(y, s.mean);
        const Innovation innovation = innovationFromFactor<M>(Sy, z, gate);
        residual_ = z;
        if (!innovation.accepted) return innovation;
        // K = (Pxy / Syᵀ) / Sy; U = K Sy; S = cholupdate(S, U, −1) column by column.
        const Matrix<M, N> tmp = Sy.template triangularView<Eigen::Lower>().solve(Pxy.transpose());
        const Matrix<N, M> K = Sy.transpose().template triangularView<Eigen::Upper>().solve(tmp).transpose();
        state_.x += K * z;
        model_.normalize(state_.x);
        const Matrix<N, M> U = K * Sy;
        for (int j = 0; j < M; ++j) cholUpdate<N>(state_.S, U.col(j), -1.0);
        return innovation;
    }

    // Scales the covariance (re-acquisition after the filter lost the track).
    void inflate(double factor) { state_.S *= std::sqrt(factor); }
    // Innovation y − ŷ of the last update() (also when it was gated out).
    const Measurement& residual() const { return residual_; }
    const State& state() const { return state_; }
    const StateVector& x() const { return state_.x; }
    StateMatrix covariance() const { return state_.S * state_.S.transpose(); }
    const Model& model() const { return model_; }
    Model& model() { return model_; }

private:
    // Lower factor of Σ_i w_c,i d_i d_iᵀ + noise: qr([√w_i d_{1:2N}, √noise]), then
    // cholupdate(·, d_0, w0c) (a downdate when w0c < 0).
    template <int D>
    Matrix<D, D> spreadFactor(const std::array<Vector<D>, kPoints>& d, const Matrix<D, D>& noise) const {
        Matrix<D, 2 * N + D> A;
        const double sw = std::sqrt(weights_.wi);
        for (int i = 1; i < kPoints; ++i) A.col(i - 1) = sw * d[i];
        A.template rightCols<D>() = robustCholesky<D>(noise);
        Matrix<D, D> S = triangularFactor<D, 2 * N + D>(A);
        cholUpdate<D>(S, d[0], weights_.w0c);
        return S;
    }

    // Lower factor L with L Lᵀ = A Aᵀ, from the QR decomposition of Aᵀ (positive diagonal).
    template <int R, int C>
    static Matrix<R, R> triangularFactor(const Matrix<R, C>& A) {
        Eigen::HouseholderQR<Matrix<C, R>> qr(A.transpose());
        Matrix<R, R> upper = qr.matrixQR().template topRows<R>().template triangularView<Eigen::Upper>();
        for (int i = 0; i < R; ++i)
            if (upper(i, i) < 0) upper.row(i) *= -1.0;
        return upper.transpose();
    }

    // S Sᵀ + w v vᵀ; a failed downdate (loss of definiteness by rounding) falls back to a
    // re-factorisation of the explicit covariance.
    template <int R>
    static void cholUpdate(Matrix<R, R>& S, const Vector<R>& v, double w) {
        if (w == 0.0) return;
        const double sign = w > 0 ? 1.0 : -1.0;
        if (!choleskyRankOne<R>(S, std::sqrt(std::abs(w)) * v, sign)) {
            const Matrix<R, R> P = S * S.transpose() + w * v * v.transpose();
            S = robustCholesky<R>(0.5 * (P + P.transpose()));
        }
    }

    Model model_;
    SigmaWeights<N> weights_;
    State state_;
    Measurement residual_ = Measurement::Zero();
};

}  // namespace athlos::estimation
