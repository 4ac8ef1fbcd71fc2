#pragma once
// Square-root UKF (van der Merwe & Wan 2001; thesis §2.3.5): propagates a lower Cholesky factor S
// (P = S Sᵀ) through QR decompositions and rank-1 Cholesky updates, which keeps P positive definite
// by construction. Same weights, gating and interface as Ukf.
#include "core/estimation/Ukf.h"

#include <Eigen/QR>

namespace athlos::estimation {

template <class Model>
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
        const auto xi = sigmaPoints(model_, state_.x, state_.S, weights_.gamma);
        std::array<StateVector, kPoints> f;
        for (int i = 0; i < kPoints; ++i) f[i] = model_.predict(xi[i], T, t, nullptr);
        StateVector mean = StateVector::Zero();
        for (int i = 1; i < kPoints; ++i) mean += weights_.mean(i) * model_.difference(f[i], f[0]);
        StateVector x = f[0] + mean;
        model_.normalize(x);
        // S⁻ = qr([√w_i (ξ_{1:2d} − x̂), √Q]), then cholupdate(S⁻, ξ_0 − x̂, w0c).
        Matrix<N, 2 * N + N> A;
        const double sw = std::sqrt(weights_.wi);
        for (int i = 1; i < kPoints; ++i) A.col(i - 1) = sw * model_.difference(f[i], x);
        A.template rightCols<N>() = robustCholesky<N>(model_.processNoise(T, t));
        StateMatrix S = triangularFactor<N, 3 * N>(A);
        cholUpdate<N>(S, model_.difference(f[0], x), weights_.w0c);
        StateMatrix C = StateMatrix::Zero();
        for (int i = 0; i < kPoints; ++i)
            C += weights_.cov(i) * model_.difference(xi[i], state_.x) * model_.difference(f[i], x).transpose();
        state_ = {x, S};
        return C;
    }

    Innovation update(const Measurement& y, double t, double gate = kNoGate) {
        const auto xi = sigmaPoints(model_, state_.x, state_.S, weights_.gamma);
        std::array<Measurement, kPoints> h;
        for (int i = 0; i < kPoints; ++i) h[i] = model_.measure(xi[i], t);
        Measurement yHat = h[0];
        for (int i = 1; i < kPoints; ++i) yHat += weights_.mean(i) * model_.residual(h[i], h[0]);
        Matrix<M, 2 * N + M> A;
        const double sw = std::sqrt(weights_.wi);
        for (int i = 1; i < kPoints; ++i) A.col(i - 1) = sw * model_.residual(h[i], yHat);
        A.template rightCols<M>() = robustCholesky<M>(model_.measurementNoise(t));
        Matrix<M, M> Sy = triangularFactor<M, 2 * N + M>(A);
        cholUpdate<M>(Sy, model_.residual(h[0], yHat), weights_.w0c);
        Matrix<N, M> Pxy = Matrix<N, M>::Zero();
        for (int i = 0; i < kPoints; ++i)
            Pxy += weights_.cov(i) * model_.difference(xi[i], state_.x) * model_.residual(h[i], yHat).transpose();

        const Measurement z = model_.residual(y, yHat);
        Innovation innovation;
        innovation.mahalanobis2 = Measurement(Sy.template triangularView<Eigen::Lower>().solve(z)).squaredNorm();
        innovation.logDetSigma = 2.0 * Sy.diagonal().array().abs().log().sum();
        innovation.accepted = innovation.mahalanobis2 <= gate;
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
