#pragma once
// The unscented transform that Ukf and SrUkf share (thesis §2.3.4–2.3.5; Julier & Uhlmann 1997,
// Wan & van der Merwe 2000): weights, sigma points, and the sigma points pushed through the motion
// or measurement model. Angles in the state or measurement are averaged through the model's
// difference()/residual() relative to the central sigma point, so a heading near ±π does not
// average to 0. The two filters differ only in how they turn the spread into covariances (full
// matrix or square-root factor).
#include "core/estimation/KalmanTypes.h"

#include <array>
#include <cstddef>
#include <type_traits>

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

// The sigma points of (x, L) and their images g(ξ_i) under the motion (D = N) or measurement
// (D = M) model, both as deviations from their means: dx_i = ξ_i − x, d_i = g(ξ_i) − ĝ.
template <int N, int D>
struct SigmaSpread {
    static constexpr int kPoints = 2 * N + 1;
    std::array<Vector<N>, kPoints> dx;
    Vector<D> mean;  // ĝ: x̂⁻ after a prediction, ŷ for a measurement
    std::array<Vector<D>, kPoints> d;
};

// Time update: x̂⁻ = F(ξ_0) + Σ_{i>0} w_i (F(ξ_i) − F(ξ_0)), normalised.
template <class Model>
SigmaSpread<Model::kStateDim, Model::kStateDim> propagateSigmaPoints(
    const Model& model, const SigmaWeights<Model::kStateDim>& w, const Vector<Model::kStateDim>& x,
    const Matrix<Model::kStateDim, Model::kStateDim>& L, double T, double t) {
    constexpr int N = Model::kStateDim;
    using Spread = SigmaSpread<N, N>;
    const auto xi = sigmaPoints(model, x, L, w.gamma);
    std::array<Vector<N>, Spread::kPoints> f;
    for (int i = 0; i < Spread::kPoints; ++i) f[i] = model.predict(xi[i], T, t, nullptr);
    Vector<N> mean = Vector<N>::Zero();
    for (int i = 1; i < Spread::kPoints; ++i) mean += w.mean(i) * model.difference(f[i], f[0]);
    Spread s;
    s.mean = f[0] + mean;
    model.normalize(s.mean);
    for (int i = 0; i < Spread::kPoints; ++i) {
        s.dx[i] = model.difference(xi[i], x);
        s.d[i] = model.difference(f[i], s.mean);
    }
    return s;
}

// Measurement: ŷ = h(ξ_0) + Σ_{i>0} w_i (h(ξ_i) − h(ξ_0)).
template <class Model>
SigmaSpread<Model::kStateDim, Model::kMeasurementDim> measureSigmaPoints(
    const Model& model, const SigmaWeights<Model::kStateDim>& w, const Vector<Model::kStateDim>& x,
    const Matrix<Model::kStateDim, Model::kStateDim>& L, double t) {
    constexpr int N = Model::kStateDim;
    using Spread = SigmaSpread<N, Model::kMeasurementDim>;
    const auto xi = sigmaPoints(model, x, L, w.gamma);
    std::array<Vector<Model::kMeasurementDim>, Spread::kPoints> h;
    for (int i = 0; i < Spread::kPoints; ++i) h[i] = model.measure(xi[i], t);
    Spread s;
    s.mean = h[0];
    for (int i = 1; i < Spread::kPoints; ++i) s.mean += w.mean(i) * model.residual(h[i], h[0]);
    for (int i = 0; i < Spread::kPoints; ++i) {
        s.dx[i] = model.difference(xi[i], x);
        s.d[i] = model.residual(h[i], s.mean);
    }
    return s;
}

// sum + Σ_i w_c,i a_i b_iᵀ: the (cross-)covariance of two deviation sets, added to sum (Q, R or 0).
template <int N, int R, int C, std::size_t K>
Matrix<R, C> weightedOuterSum(const SigmaWeights<N>& w, const std::array<Vector<R>, K>& a,
                              const std::array<Vector<C>, K>& b,
                              std::type_identity_t<Matrix<R, C>> sum = Matrix<R, C>::Zero()) {
    for (int i = 0; i < int(K); ++i) sum += w.cov(i) * a[i] * b[i].transpose();
    return sum;
}

}  // namespace athlos::estimation
