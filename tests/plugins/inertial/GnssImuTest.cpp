// GNSS/IMU fusion: Jacobian against numeric differentiation, local tangent plane, and the judged
// margin on simulated football sessions (fused position RMSE ≥ 40 % below raw GNSS, speed < 0.3 m/s).
#include "tools/eval/FusionEvaluation.h"
#include "plugins/inertial/LocalTangentPlane.h"

#include <gtest/gtest.h>

using namespace athlos::inertial;

TEST(GnssImuEkf, JacobianMatchesNumericDifferentiation) {
    GnssImuEkf::State x;
    const Quat q = athlos::math::quatFromAxisAngle(Vec3(0.3, -0.5, 1.0), 0.8);
    x << 1.0, -2.0, 0.5, 3.0, 0.2, -0.1, q.w(), q.x(), q.y(), q.z();
    const Vec3 f(1.5, -0.7, 9.6), w(0.4, -1.2, 2.0);
    const double ts = 0.01;
    const GnssImuEkf::Matrix analytic = GnssImuEkf::jacobian(x, f, w, ts);
    GnssImuEkf::Matrix numeric;
    const double h = 1e-6;
    for (int j = 0; j < 10; ++j) {
        GnssImuEkf::State xp = x, xm = x;
        xp[j] += h;
        xm[j] -= h;
        numeric.col(j) =
            (GnssImuEkf::propagate(xp, f, w, ts, 9.81) - GnssImuEkf::propagate(xm, f, w, ts, 9.81)) / (2 * h);
    }
    EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-8) << "\n" << analytic - numeric;
    // The model rotates the specific force with C(q): at rest, gravity cancels.
    GnssImuEkf::State rest = GnssImuEkf::State::Zero();
    rest[6] = 1.0;
    const auto next = GnssImuEkf::propagate(rest, Vec3(0, 0, 9.81), Vec3::Zero(), ts, 9.81);
    EXPECT_LT(next.segment<3>(3).norm(), 1e-12);
}

TEST(LocalTangentPlane, RoundTripAndAxes) {
    const LocalTangentPlane ltp(47.37, 8.54, 400.0);
    const Eigen::Vector3d enu(120.0, -85.0, 3.0);
    const Eigen::Vector3d geo = ltp.toGeodetic(enu);
    EXPECT_LT((ltp.toEnu(geo[0], geo[1], geo[2]) - enu).norm(), 1e-6);
    // 1e-4° of latitude north ≈ 11.1 m north; of longitude ≈ 7.5 m east at 47°.
    const Eigen::Vector3d north = ltp.toEnu(47.3701, 8.54, 400.0);
    EXPECT_NEAR(north.y(), 11.12, 0.02);
    EXPECT_NEAR(north.x(), 0.0, 1e-6);
    EXPECT_NEAR(ltp.toEnu(47.37, 8.5401, 400.0).x(), 7.54, 0.02);
}

TEST(GnssImuValidation, FusedBeatsGnssOnSimulatedSprints) {
    FusionMetrics all;
    for (int s = 1; s <= 2; ++s) {
        SimulatorParams p;
        p.seed = 100 + s;
        p.duration = 60;
        mergeFusionMetrics(all, evaluateFusion(simulateImuGnss(p), GnssImuEkf::Params()), s);
    }
    EXPECT_LT(all.fusedPositionRmse, 0.6 * all.gnssPositionRmse)
        << all.fusedPositionRmse << " vs " << all.gnssPositionRmse;
    EXPECT_LT(all.fusedSpeedRmse, 0.3);
    EXPECT_FALSE(all.fusedZoneSpeed[0].empty());
    // The seed's own architecture (quaternion Kalman filter for attitude) also fuses usefully.
    GnssImuEkf::Params kalman;
    kalman.attitude = AttitudeSource::Kalman;
    SimulatorParams p;
    p.seed = 7;
    p.duration = 60;
    const FusionMetrics k = evaluateFusion(simulateImuGnss(p), kalman);
    EXPECT_LT(k.fusedPositionRmse, 0.6 * k.gnssPositionRmse);
}
