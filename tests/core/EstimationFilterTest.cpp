// Estimation framework: EKF worked example, EKF/UKF/SRUKF agreement, RTS vs batch least squares,
// fixed-lag vs RTS, gating, time-grid output and innovation-likelihood noise estimation.
#include "core/estimation/Ekf.h"
#include "core/estimation/NoiseEstimator.h"
#include "core/estimation/SrUkf.h"
#include "core/estimation/TimeGridRunner.h"
#include "core/estimation/Ukf.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>
#include <random>

using namespace athlos::estimation;

namespace {

// 1D sprinter of thesis §2.3.3: x = [p, v], Φ = [[1, T], [0, 1]], C = [1 0]; Q per step (eq. 2.25).
struct Sprinter : ModelDefaults<2, 1> {
    StateMatrix Q = Vector<2>(0.5 * 0.5, 0.2 * 0.2).asDiagonal();
    double R = 0.6 * 0.6;
    StateVector predict(const StateVector& x, double T, double, StateMatrix* F) const {
        if (F) *F << 1, T, 0, 1;
        return StateVector(x[0] + T * x[1], x[1]);
    }
    StateMatrix processNoise(double, double) const { return Q; }
    Measurement measure(const StateVector& x, double) const { return Measurement(x[0]); }
    MeasurementJacobian measurementJacobian(const StateVector&, double) const { return MeasurementJacobian(1, 0); }
    MeasurementMatrix measurementNoise(double) const { return MeasurementMatrix::Constant(R); }
};

// 2D constant velocity with continuous white-noise acceleration (linear, Q ∝ T).
struct Cv2d : ModelDefaults<4, 2> {
    double q = 0.5, r = 0.04;
    StateVector predict(const StateVector& x, double T, double, StateMatrix* F) const {
        StateVector y = x;
        y.head<2>() += T * x.tail<2>();
        if (F) {
            F->setIdentity();
            (*F)(0, 2) = (*F)(1, 3) = T;
        }
        return y;
    }
    StateMatrix processNoise(double T, double) const {
        StateMatrix Q = StateMatrix::Zero();
        for (int a = 0; a < 2; ++a) {
            Q(a, a) = q * T * T * T / 3;
            Q(a, a + 2) = Q(a + 2, a) = q * T * T / 2;
            Q(a + 2, a + 2) = q * T;
        }
        return Q;
    }
    Measurement measure(const StateVector& x, double) const { return x.head<2>(); }
    MeasurementJacobian measurementJacobian(const StateVector&, double) const {
        MeasurementJacobian H = MeasurementJacobian::Zero();
        H(0, 0) = H(1, 1) = 1;
        return H;
    }
    MeasurementMatrix measurementNoise(double) const { return Vector<2>(r, r).asDiagonal(); }
};

// Nonlinear: a coordinated turn with range/bearing measurements (angles wrapped).
struct TurnRangeBearing : ModelDefaults<5, 2> {
    StateVector predict(const StateVector& x, double T, double, StateMatrix*) const {
        StateVector y = x;  // [px, py, v, φ, ω]
        y[0] += T * x[2] * std::cos(x[3] + 0.5 * x[4] * T);
        y[1] += T * x[2] * std::sin(x[3] + 0.5 * x[4] * T);
        y[3] += x[4] * T;
        return y;
    }
    StateMatrix processNoise(double T, double) const { return Vector<5>(0.01, 0.01, 0.1, 0.01, 0.05).asDiagonal() * T; }
    Measurement measure(const StateVector& x, double) const {
        return Measurement(std::hypot(x[0], x[1]), std::atan2(x[1], x[0]));
    }
    MeasurementMatrix measurementNoise(double) const { return Vector<2>(0.25, 0.01).asDiagonal(); }
    Measurement residual(const Measurement& a, const Measurement& b) const {
        Measurement d = a - b;
        d[1] = std::remainder(d[1], 2 * std::numbers::pi);
        return d;
    }
    StateVector difference(const StateVector& a, const StateVector& b) const {
        StateVector d = a - b;
        d[3] = std::remainder(d[3], 2 * std::numbers::pi);
        return d;
    }
};

// The models above meet the filters' requirements (KalmanTypes.h); the unscented-only model has no
// measurement Jacobian, so the EKF does not accept it.
static_assert(EkfModel<Sprinter> && EkfModel<Cv2d>);
static_assert(KalmanModel<TurnRangeBearing> && !EkfModel<TurnRangeBearing>);
static_assert(!KalmanModel<ModelDefaults<2, 1>>);  // the defaults alone are no model

struct Simulated {
    std::vector<double> t;
    std::vector<Vector<4>> truth;
    std::vector<Vector<2>> y;
    std::vector<bool> outlier;
};

Simulated simulateCv(const Cv2d& m, int n, std::uint64_t seed, double outlierFraction = 0.0) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0, 1);
    std::uniform_real_distribution<double> u(0, 1);
    Simulated s;
    Vector<4> x(0, 0, 3, 1);
    double t = 0;
    for (int k = 0; k < n; ++k) {
        const double T = 0.02 + 0.04 * u(rng);
        t += T;
        const Eigen::LLT<Matrix<4, 4>> L(m.processNoise(T, t));
        x = m.predict(x, T, t, nullptr) + L.matrixL() * Vector<4>(g(rng), g(rng), g(rng), g(rng));
        const bool out = u(rng) < outlierFraction;
        const double sd = out ? 7.0 : std::sqrt(m.r);
        s.t.push_back(t);
        s.truth.push_back(x);
        s.y.push_back(x.head<2>() + sd * Vector<2>(g(rng), g(rng)));
        s.outlier.push_back(out);
    }
    return s;
}

double rmse(const std::vector<Vector<4>>& a, const std::vector<Vector<4>>& b) {
    double sum = 0;
    for (std::size_t k = 0; k < a.size(); ++k) sum += (a[k].head<2>() - b[k].head<2>()).squaredNorm();
    return std::sqrt(sum / double(a.size()));
}

}  // namespace

TEST(EstimationEkf, SprinterWorkedExample) {
    // Thesis eqs. 2.26–2.30: P_1|0 = [[(2.06)², 0.10], [0.10, (1.02)²]], x_1|1 = [0.74, 0.02],
    // P_1|1 = [[(0.58)², 0.01], [0.01, (1.02)²]] (values as printed, 2 digits).
    Ekf<Sprinter> ekf{Sprinter{}};
    ekf.reset(Vector<2>(0, 0), Vector<2>(2.0 * 2.0, 1.0 * 1.0).asDiagonal());
    ekf.predict(0.1, 0.1);
    const Matrix<2, 2> P10 = ekf.covariance();
    EXPECT_NEAR(std::sqrt(P10(0, 0)), 2.06, 0.005);
    EXPECT_NEAR(P10(0, 1), 0.10, 0.005);
    EXPECT_NEAR(P10(1, 0), 0.10, 0.005);
    EXPECT_NEAR(std::sqrt(P10(1, 1)), 1.02, 0.005);
    const Innovation inn = ekf.update(Vector<1>(0.8), 0.1);
    EXPECT_TRUE(inn.accepted);
    EXPECT_NEAR(ekf.x()[0], 0.74, 0.005);
    EXPECT_NEAR(ekf.x()[1], 0.02, 0.005);
    const Matrix<2, 2> P11 = ekf.covariance();
    EXPECT_NEAR(std::sqrt(P11(0, 0)), 0.58, 0.005);
    EXPECT_NEAR(P11(0, 1), 0.01, 0.005);
    EXPECT_NEAR(std::sqrt(P11(1, 1)), 1.02, 0.005);
    // Exact values of the same computation (guards against a second rounding-level error).
    EXPECT_NEAR(P10(0, 0), 4.26, 1e-12);
    EXPECT_NEAR(ekf.x()[0], 0.8 * 4.26 / (4.26 + 0.36), 1e-12);
}

TEST(EstimationUkf, AgreesWithEkfOnLinearSystem) {
    const Cv2d m;
    const Simulated s = simulateCv(m, 200, 3);
    Ekf<Cv2d> ekf(m);
    Ukf<Cv2d> ukf(m, {0.5, 2.0, 0.0});
    SrUkf<Cv2d> srukf(m, {1.0, 2.0, 0.0});
    const Vector<4> x0(0, 0, 0, 0);
    const Matrix<4, 4> P0 = Vector<4>(1, 1, 10, 10).asDiagonal();
    ekf.reset(x0, P0);
    ukf.reset(x0, P0);
    srukf.reset(x0, P0);
    double t = 0;
    for (std::size_t k = 0; k < s.t.size(); ++k) {
        const double T = s.t[k] - t;
        t = s.t[k];
        const Matrix<4, 4> Ce = ekf.predict(T, t), Cu = ukf.predict(T, t);
        srukf.predict(T, t);
        EXPECT_LT((Ce - Cu).norm(), 1e-9 * (1 + Ce.norm()));
        const Innovation ie = ekf.update(s.y[k], t), iu = ukf.update(s.y[k], t);
        srukf.update(s.y[k], t);
        EXPECT_NEAR(ie.mahalanobis2, iu.mahalanobis2, 1e-8 * (1 + ie.mahalanobis2));
        EXPECT_NEAR(ie.logDetSigma, iu.logDetSigma, 1e-8);
    }
    EXPECT_LT((ekf.x() - ukf.x()).norm(), 1e-8);
    EXPECT_LT((ekf.covariance() - ukf.covariance()).norm(), 1e-9);
    EXPECT_LT((ekf.x() - srukf.x()).norm(), 1e-8);
    EXPECT_LT((ekf.covariance() - srukf.covariance()).norm(), 1e-9);
}

TEST(EstimationSrUkf, EqualsUkfCovarianceOnNonlinearSystem) {
    // α = 1 (w0c > 0: Cholesky update) and α = 0.5 (w0c < 0: downdate path).
    for (double alpha : {1.0, 0.5}) {
        const TurnRangeBearing m;
        Ukf<TurnRangeBearing> ukf(m, {alpha, 2.0, 0.0});
        SrUkf<TurnRangeBearing> sr(m, {alpha, 2.0, 0.0});
        Vector<5> x0(10, 5, 4, 0.3, 0.2);
        const Matrix<5, 5> P0 = Vector<5>(1, 1, 0.5, 0.1, 0.05).asDiagonal();
        ukf.reset(x0, P0);
        sr.reset(x0, P0);
        std::mt19937_64 rng(5);
        std::normal_distribution<double> g(0, 1);
        Vector<5> truth = x0;
        for (int k = 1; k <= 100; ++k) {
            const double t = 0.1 * k;
            truth = m.predict(truth, 0.1, t, nullptr);
            ukf.predict(0.1, t);
            sr.predict(0.1, t);
            const Vector<2> y = m.measure(truth, t) + Vector<2>(0.5 * g(rng), 0.1 * g(rng));
            ukf.update(y, t);
            sr.update(y, t);
            ASSERT_LT((ukf.covariance() - sr.covariance()).norm(), 1e-8 * ukf.covariance().norm()) << "alpha " << alpha;
            ASSERT_LT(m.difference(ukf.x(), sr.x()).norm(), 1e-8) << "alpha " << alpha;
        }
    }
}

TEST(EstimationRts, MatchesBatchLeastSquaresOnLinearGaussian) {
    const Cv2d m;
    const Simulated s = simulateCv(m, 25, 11);
    const Vector<4> x0(0, 0, 2, 0);
    const Matrix<4, 4> P0 = Vector<4>(4, 4, 9, 9).asDiagonal();
    Ekf<Cv2d> ekf(m);
    ekf.reset(x0, P0);
    TimeGridRunner<Ekf<Cv2d>>::Params params;
    params.smoothing = Smoothing::Rts;
    params.reacquireCount = 0;
    // t0 = first measurement time: the prior applies to the state at t_0.
    const auto out = TimeGridRunner<Ekf<Cv2d>>(params).run(ekf, s.t[0], s.t, s.y, {});

    // argmin |x_0 − x̂0|²_{P0⁻¹} + Σ |x_k − Φ x_{k−1}|²_{Q⁻¹} + Σ |y_k − H x_k|²_{R⁻¹} by normal equations.
    const int K = static_cast<int>(s.t.size()), n = 4 * K;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    Eigen::VectorXd b = Eigen::VectorXd::Zero(n);
    const Matrix<4, 4> P0i = P0.inverse();
    A.block<4, 4>(0, 0) += P0i;
    b.segment<4>(0) += P0i * x0;
    const Matrix<2, 4> H = m.measurementJacobian(x0, 0);
    const Matrix<2, 2> Ri = m.measurementNoise(0).inverse();
    for (int k = 0; k < K; ++k) {
        A.block<4, 4>(4 * k, 4 * k) += H.transpose() * Ri * H;
        b.segment<4>(4 * k) += H.transpose() * Ri * s.y[k];
        if (k == 0) continue;
        const double T = s.t[k] - s.t[k - 1];
        Matrix<4, 4> F;
        m.predict(x0, T, 0, &F);
        const Matrix<4, 4> Qi = m.processNoise(T, 0).inverse();
        A.block<4, 4>(4 * k, 4 * k) += Qi;
        A.block<4, 4>(4 * (k - 1), 4 * (k - 1)) += F.transpose() * Qi * F;
        A.block<4, 4>(4 * k, 4 * (k - 1)) -= Qi * F;
        A.block<4, 4>(4 * (k - 1), 4 * k) -= F.transpose() * Qi;
    }
    const Eigen::VectorXd xs = A.ldlt().solve(b);
    for (int k = 0; k < K; ++k) EXPECT_LT((out.x[k] - xs.segment<4>(4 * k)).norm(), 1e-6) << "k = " << k;
}

TEST(EstimationRts, ReducesErrorAndFixedLagConvergesToRts) {
    const Cv2d m;
    const Simulated s = simulateCv(m, 1500, 21);
    auto runWith = [&](Smoothing smoothing, double lag) {
        Ekf<Cv2d> ekf(m);
        ekf.reset(Vector<4>(s.y[0][0], s.y[0][1], 0, 0), Vector<4>(1, 1, 25, 25).asDiagonal());
        TimeGridRunner<Ekf<Cv2d>>::Params p;
        p.smoothing = smoothing;
        p.lag = lag;
        p.covariance = true;
        return TimeGridRunner<Ekf<Cv2d>>(p).run(ekf, s.t[0], s.t, s.y, {});
    };
    const auto filtered = runWith(Smoothing::None, 0), smoothed = runWith(Smoothing::Rts, 0);
    const auto lag05 = runWith(Smoothing::FixedLag, 0.5), lagInf = runWith(Smoothing::FixedLag, 1e9);
    const double ef = rmse(filtered.x, s.truth), es = rmse(smoothed.x, s.truth), el = rmse(lag05.x, s.truth);
    EXPECT_LT(es, 0.85 * ef);
    EXPECT_LT(el, ef);
    EXPECT_GE(el, es * 0.999);
    for (std::size_t k = 0; k < s.t.size(); ++k) {
        ASSERT_LT((lagInf.x[k] - smoothed.x[k]).norm(), 1e-9);
        ASSERT_LT((lagInf.P[k] - smoothed.P[k]).norm(), 1e-9);
    }
}

TEST(EstimationRunner, GatingFlagsInjectedOutliers) {
    const Cv2d m;
    const Simulated s = simulateCv(m, 3000, 31, 0.05);
    Ekf<Cv2d> ekf(m);
    ekf.reset(Vector<4>(0, 0, 3, 1), Vector<4>(0.1, 0.1, 0.1, 0.1).asDiagonal());
    TimeGridRunner<Ekf<Cv2d>>::Params p;
    p.gate = 13.8;  // χ²₂ 99.9 %
    const auto out = TimeGridRunner<Ekf<Cv2d>>(p).run(ekf, 0.0, s.t, s.y, {});
    int tp = 0, fn = 0, tn = 0, fp = 0;
    for (std::size_t k = 0; k < s.t.size(); ++k) {
        const bool flagged = !out.samples[k].accepted;
        (s.outlier[k] ? (flagged ? tp : fn) : (flagged ? fp : tn))++;
    }
    EXPECT_GE(double(tp) / (tp + fn), 0.95);
    EXPECT_GE(double(tn) / (tn + fp), 0.99);
}

TEST(EstimationRunner, OutputGridPredictsBetweenObservations) {
    const Cv2d m;
    Ekf<Cv2d> ekf(m);
    ekf.reset(Vector<4>(0, 0, 1, 0), Matrix<4, 4>::Identity() * 1e-6);
    const std::vector<double> tIn = {0.1, 0.2, 5.0};
    const std::vector<Vector<2>> y = {{0.1, 0}, {0.2, 0}, {5.0, 0}};
    const std::vector<double> grid = {0.0, 0.5, 1.0, 2.0, 3.0, 4.0};
    TimeGridRunner<Ekf<Cv2d>>::Params p;
    p.maxStep = 0.05;
    const auto out = TimeGridRunner<Ekf<Cv2d>>(p).run(ekf, 0.0, tIn, y, grid);
    ASSERT_EQ(out.x.size(), grid.size());
    ASSERT_EQ(out.samples.size(), tIn.size());
    for (std::size_t k = 0; k < grid.size(); ++k) EXPECT_NEAR(out.x[k][0], grid[k], 1e-3) << grid[k];
}

TEST(EstimationNoise, TukeyPenaltyAndObjective) {
    EXPECT_DOUBLE_EQ(tukeyPenalty({1, 2, 3, 4, 5}), 3 + 1.5 * 2);  // median 3, q1 2, q3 4
    const std::vector<double> d2 = {1, 2, 3, 4, 100}, logdet = {0.5, 0.5, 0.5, 0.5, 0.5};
    const double beta = tukeyPenalty(d2);
    EXPECT_DOUBLE_EQ(robustInnovationObjective(d2, logdet, 10.0), 2.5 + 1 + 2 + 3 + 4 + beta);
    EXPECT_DOUBLE_EQ(robustInnovationObjective(d2, logdet, 1e9), 2.5 + 110);
}

TEST(EstimationNoise, RecoversMeasurementNoiseWithinFactorTwo) {
    Cv2d truth;
    truth.q = 0.5;
    truth.r = 0.04;
    const Simulated s = simulateCv(truth, 2500, 41, 0.05);
    const NoiseEstimator estimator({{"q", 0.05, 1e-4, 1e2}, {"r", 1.0, 1e-4, 1e2}, {"gate", 50.0, 2.0, 1e4}},
                                   NoiseEstimator::Params{});
    const auto best = estimator.minimize([&](const std::vector<double>& v) {
        Cv2d m;
        m.q = v[0];
        m.r = v[1];
        Ekf<Cv2d> ekf(m);
        ekf.reset(Vector<4>(s.y[0][0], s.y[0][1], 0, 0), Vector<4>(1, 1, 25, 25).asDiagonal());
        TimeGridRunner<Ekf<Cv2d>>::Params p;
        p.gate = v[2];
        const auto out = TimeGridRunner<Ekf<Cv2d>>(p).run(ekf, s.t[0], s.t, s.y, {});
        std::vector<double> d2, ld;
        for (const auto& d : out.samples) {
            d2.push_back(d.mahalanobis2);
            ld.push_back(d.logDetSigma);
        }
        return robustInnovationObjective(d2, ld, v[2]);
    });
    EXPECT_GT(best.values[1], truth.r / 2);
    EXPECT_LT(best.values[1], truth.r * 2);
    EXPECT_GT(best.values[0], truth.q / 5);
    EXPECT_LT(best.values[0], truth.q * 5);
    EXPECT_GT(best.evaluations, 10);
}
