// Motion models: CTRA small-ω limit, Jacobians vs numeric differentiation for every model,
// augmented prediction follows the track geometry.
#include "core/math/Angles.h"
#include "plugins/positioning/ConstantVelocity.h"
#include "plugins/positioning/Ctra.h"
#include "plugins/positioning/TrackModels.h"

#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using namespace athlos;
using namespace athlos::positioning;

namespace {

// Central differences of F(x) (heading differences wrapped).
template <class Model>
typename Model::StateMatrix numericJacobian(const Model& m, const typename Model::StateVector& x, double T, double t) {
    typename Model::StateMatrix J;
    for (int j = 0; j < Model::kStateDim; ++j) {
        const double h = 1e-6 * std::max(1.0, std::abs(x[j]));
        auto xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        J.col(j) = m.difference(m.predict(xp, T, t, nullptr), m.predict(xm, T, t, nullptr)) / (2 * h);
    }
    return J;
}

template <class Model>
void expectJacobian(const Model& m, const typename Model::StateVector& x, double T, double t, double tol = 1e-5) {
    typename Model::StateMatrix F;
    const auto y = m.predict(x, T, t, &F);
    EXPECT_LT(m.difference(y, m.predict(x, T, t, nullptr)).norm(), 1e-12);
    const auto N = numericJacobian(m, x, T, t);
    EXPECT_LT((F - N).cwiseAbs().maxCoeff(), tol) << "analytic\n" << F << "\nnumeric\n" << N;
}

std::shared_ptr<const TrackGeometry> oval() { return std::make_shared<const TrackGeometry>(TrackGeometry::iaaf400m()); }

}  // namespace

TEST(Ctra, SmallOmegaLimitIsContinuous) {
    for (double T : {0.02, 0.1, 2.0}) {
        const auto a = ctraIncrement(6.0, 0.5, 0.3, 0.0, T), b = ctraIncrement(6.0, 0.5, 0.3, 1e-9, T);
        EXPECT_LT((a.delta - b.delta).norm(), 1e-9 * (1 + a.delta.norm()));
        EXPECT_LT((a.dOmega - b.dOmega).norm(), 1e-6);
        // Both branches agree at the switch-over |ωT| = 1e-3.
        const double w = 1e-3 / T;
        const auto below = ctraIncrement(6.0, 0.5, 0.3, w * 0.999999, T),
                   above = ctraIncrement(6.0, 0.5, 0.3, w * 1.000001, T);
        EXPECT_LT((below.delta - above.delta).norm(), 1e-8 * (1 + below.delta.norm()));
        EXPECT_LT((below.dOmega - above.dOmega).norm(), 1e-6 * (1 + below.dOmega.norm()));
    }
    // ω = 0: straight line with p' = p + (vT + aT²/2)[cos φ, sin φ].
    const auto s = ctraIncrement(5.0, 1.0, 0.4, 0.0, 2.0);
    EXPECT_NEAR(s.delta.x(), (10.0 + 2.0) * std::cos(0.4), 1e-12);
    EXPECT_NEAR(s.delta.y(), (10.0 + 2.0) * std::sin(0.4), 1e-12);
    // A quarter circle of radius r = v/ω = 4 starting along +x ends at (4, 4).
    const auto q = ctraIncrement(2.0, 0.0, 0.0, 0.5, std::numbers::pi);
    EXPECT_NEAR(q.delta.x(), 4.0, 1e-12);
    EXPECT_NEAR(q.delta.y(), 4.0, 1e-12);
}

TEST(Ctra, JacobianMatchesNumericDifferentiation) {
    const CtraModel model;
    // (Not exactly at the series/closed-form switch |ωT| = 1e-3, where a finite difference would
    // straddle the two branches and amplify their 1e-10 disagreement.)
    for (double w : {0.0, 1e-7, 0.02, 0.18, -0.5})
        for (double T : {0.01, 0.1, 1.5}) {
            Vector<6> x;
            x << 3.0, -2.0, 6.5, 0.4, 2.9, w;
            expectJacobian(model, x, T, 0.0);
        }
    CtraModel::Params cv;
    cv.cvAfter = 1.0;
    Vector<6> x;
    x << 0, 0, 7, 0.3, 1.0, 0.1;
    expectJacobian(CtraModel(cv), x, 0.1, 2.0);
}

// (v, φ, a) and (−v, φ + π, −a) are the same motion; the reported kinematics are the direction of travel.
TEST(Ctra, KinematicsReportTheDirectionOfTravel) {
    Vector<6> x;
    x << 1.0, 2.0, -7.5, 0.4, -0.74, 0.19;
    const Kinematics k = CtraModel::kinematics(x);
    EXPECT_DOUBLE_EQ(k.speed, 7.5);
    EXPECT_NEAR(k.heading, -0.74 + std::numbers::pi, 1e-15);
    EXPECT_DOUBLE_EQ(k.accel, -0.4);
    EXPECT_DOUBLE_EQ(k.turnRate, 0.19);
    // The same position one step later either way: the mirrored state moves along the reported heading.
    const CtraModel m;
    Vector<6> forward;
    forward << 1.0, 2.0, 7.5, -0.4, -0.74 + std::numbers::pi, 0.19;
    EXPECT_LT((m.predict(x, 0.1, 0.0).head<2>() - m.predict(forward, 0.1, 0.0).head<2>()).norm(), 1e-12);
    x[kV] = 3.0;
    EXPECT_DOUBLE_EQ(CtraModel::kinematics(x).heading, -0.74);
}

TEST(ConstantVelocity, JacobianAndNoise) {
    const ConstantVelocityModel m;
    expectJacobian(m, Vector<4>(1, 2, 3, -4), 0.3, 0.0);
    const auto Q = m.processNoise(0.5, 0);
    EXPECT_NEAR(Q(0, 0), 1.0 * 0.125 / 3, 1e-12);
    EXPECT_NEAR(Q(0, 2), 1.0 * 0.25 / 2, 1e-12);
}

TEST(AugmentedTrackModel, FollowsTrackAndJacobianMatches) {
    AugmentedTrackModel::Params p;
    p.constraint.track = oval();
    p.cvAfter = 5.0;
    const AugmentedTrackModel m(p);
    // Bend 1, a bit off the tangent: the predicted heading is the track's, ω = v / r.
    Vector<6> x;
    x << 42.195 + 37.0 * std::cos(0.3), 37.0 * std::sin(0.3), 7.0, 0.5, 0.3 + std::numbers::pi / 2 + 0.05, 0.1;
    const auto y = m.predict(x, 0.05, 1.0, nullptr);
    const double rho = (y.head<2>() - Eigen::Vector2d(42.195, 0)).norm();
    EXPECT_NEAR(math::wrapAngle(y[kPhi] - std::atan2(y[kPy], y[kPx] - 42.195) - std::numbers::pi / 2), 0.0, 1e-12);
    EXPECT_NEAR(y[kOmega], 7.0 / rho, 1e-12);
    expectJacobian(m, x, 0.05, 1.0);
    expectJacobian(m, x, 0.05, 6.0);  // constant-velocity phase
    // Straight: φ = 0 on the home straight, ω = 0; the acceleration is dropped after cvAfter.
    x << 0.0, -37.5, 7.0, 0.5, 0.1, 0.2;
    const auto s = m.predict(x, 0.1, 6.0, nullptr);
    EXPECT_NEAR(s[kPhi], 0.0, 1e-12);
    EXPECT_NEAR(s[kOmega], 0.0, 1e-12);
    EXPECT_NEAR(s[kA], 0.0, 1e-12);
    EXPECT_NEAR(s[kV], 7.0, 1e-12);
    expectJacobian(m, x, 0.1, 6.0);
    // Running the wrong way round: heading π on the home straight.
    x << 0.0, -37.5, 7.0, 0.0, 3.0, 0.0;
    EXPECT_NEAR(std::abs(m.predict(x, 0.1, 0.0, nullptr)[kPhi]), std::numbers::pi, 1e-12);
    // Far off the track (infield): generic CTRA.
    x << 0.0, 0.0, 3.0, 0.0, 1.0, 0.2;
    EXPECT_NEAR(m.predict(x, 0.1, 0.0, nullptr)[kPhi], 1.02, 1e-12);
    expectJacobian(m, x, 0.1, 0.0);
}

// The filter loop's closed-form query (LPS-frame constants, bend heading by an asin series from the
// predicted heading) must agree with the general query through TrackGeometry::field(): on both bends
// and straights of a rotated, shifted oval whose headings wrap through ±π, for predicted headings on
// either side of the tangent, too far for the series (atan2 fallback), reversed (running the wrong way)
// and after a large turn ωT; and it must be inactive where the general query is (infield, outside).
TEST(TrackConstraintField, FastQueryMatchesGeneralQuery) {
    auto track = std::make_shared<TrackGeometry>(TrackGeometry::iaaf400m());
    track->setPose({3.0, -4.0, 2.9});
    TrackConstraintParams params;
    params.track = track;
    const TrackConstraintField field(params);
    int series = 0, bends = 0, straights = 0, inactive = 0;
    for (double s = 0.0; s < 400.0; s += 1.7) {
        for (const double offset : {-5.0, 0.3, 4.0, 9.5, 14.0}) {
            const TrackPoint pt = track->pointAt(s, offset);
            const TrackQuery q = track->query(pt.position);
            for (const double delta : {0.0, 0.03, -0.0499, 0.08, 0.4, -1.2, std::numbers::pi}) {
                for (const double turn : {0.0, 0.02, -1.5}) {
                    const double predicted = math::wrapAngle(q.heading + delta);
                    const double before = predicted - turn;  // heading before the step, ωT = turn
                    const Eigen::Vector2d direction(std::cos(predicted), std::sin(predicted));
                    const TrackConstraint fast = field.at(pt.position, before, predicted, direction);
                    const TrackConstraint general = trackConstraint(field, pt.position, before);
                    ASSERT_EQ(fast.active, general.active) << "s " << s << " d " << offset;
                    if (!fast.active) {
                        ++inactive;
                        continue;
                    }
                    EXPECT_EQ(fast.varies, general.varies);
                    EXPECT_LT(std::abs(math::wrapAngle(fast.heading - general.heading)), 1e-12)
                        << "s " << s << " d " << offset << " delta " << delta << " turn " << turn;
                    EXPECT_GT(fast.heading, -std::numbers::pi);
                    EXPECT_LE(fast.heading, std::numbers::pi);
                    EXPECT_NEAR(fast.curvature, general.curvature, 1e-15);
                    EXPECT_LT((fast.headingGradient - general.headingGradient).norm(), 1e-15);
                    EXPECT_LT((fast.curvatureGradient - general.curvatureGradient).norm(), 1e-15);
                    if (q.onBend) {
                        ++bends;
                        if (std::abs(delta) < 0.05 && std::abs(turn) < 1.0) ++series;
                    } else {
                        ++straights;
                    }
                }
            }
        }
    }
    EXPECT_GT(series, 500);
    EXPECT_GT(bends, 1500);
    EXPECT_GT(straights, 1500);
    EXPECT_GT(inactive, 500);
}

TEST(PseudoTrackModel, MeasurementJacobianMatchesNumeric) {
    PseudoTrackModel::Params p;
    p.constraint.track = oval();
    p.cvAfter = 1.0;
    const PseudoTrackModel m(p);
    Vector<6> x;
    x << 42.195 + 38.0 * std::cos(-0.8), 38.0 * std::sin(-0.8), 6.0, 0.2, -0.8 + std::numbers::pi / 2 + 0.02, 0.15;
    const auto H = m.measurementJacobian(x, 2.0);
    for (int j = 0; j < 6; ++j) {
        auto xp = x, xm = x;
        xp[j] += 1e-6;
        xm[j] -= 1e-6;
        const auto d = m.residual(m.measure(xp, 2.0), m.measure(xm, 2.0)) / 2e-6;
        EXPECT_LT((H.col(j) - d).cwiseAbs().maxCoeff(), 1e-6) << "column " << j;
    }
    const auto h = m.measure(x, 2.0);
    EXPECT_NEAR(h[2], 0.02, 1e-12);
    EXPECT_NEAR(h[3], 0.15 - 6.0 / 38.0, 1e-12);
    EXPECT_NEAR(h[4], 0.2, 1e-12);
    EXPECT_NEAR(m.measure(x, 0.5)[4], 0.0, 0.0);  // no a = 0 pseudo-measurement during the start
}
