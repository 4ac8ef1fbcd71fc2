// Velocity resets (plugins/inertial/VelocityReset.h): an exact case (a constant accelerometer bias
// integrates to a linear velocity drift, which the resets must remove), the cross-country ski
// simulator (every thrust found, cycle speeds against the truth) and the foot simulator (stance
// phases and stride lengths against the truth), and the processor's outputs and refusals. Figures:
// docs/validation/drift-reduction.md ("Velocity resets").
#include "plugins/inertial/VelocityReset.h"
#include "plugins/inertial/VelocityResetProcessor.h"
#include "tools/eval/VelocityEvaluation.h"

#include "core/model/Project.h"
#include "core/processing/OutputStreams.h"
#include "core/processing/ProcessorRunner.h"

#include <QTemporaryDir>
#include <cmath>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::inertial;
using math::Quat;
using math::Vec3;

namespace {

// Still for `still` s, then a minimum-jerk move of `length` m along x in `move` s, `cycles` times, then
// still again. The accelerometer reads s'' + bias along x and g up; the gyroscope reads 3 rad/s about y
// while moving (seen only by the detector: the orientation is given and not bridged).
struct Synthetic {
    std::vector<Quat> q;
    std::vector<Vec3> acc, gyr, velocity;  // velocity: truth
    double ts = 0.01;
};
Synthetic synthetic(int cycles, double bias, double length = 1.0, double still = 0.5, double move = 0.6) {
    Synthetic s;
    const auto stillN = std::size_t(still / s.ts), moveN = std::size_t(move / s.ts);
    const auto push = [&](double a, double v, double w) {
        s.q.push_back(Quat::Identity());
        s.acc.push_back(Vec3(a + bias, 0.0, 9.81));
        s.gyr.push_back(Vec3(0.0, w, 0.0));
        s.velocity.push_back(Vec3(v, 0.0, 0.0));
    };
    for (int c = 0; c < cycles; ++c) {
        for (std::size_t k = 0; k < stillN; ++k) push(0.0, 0.0, 0.0);
        for (std::size_t k = 0; k < moveN; ++k) {
            const double u = double(k) / double(moveN);
            push(length / (move * move) * (60 * u - 180 * u * u + 120 * u * u * u),
                 length / move * (30 * u * u - 60 * u * u * u + 30 * u * u * u * u), 3.0);
        }
    }
    for (std::size_t k = 0; k < stillN; ++k) push(0.0, 0.0, 0.0);
    return s;
}

VelocityReset::Params exactParams() {
    VelocityReset::Params p = VelocityReset::foot();
    p.gyroBridge = false;
    p.inclinationReset = false;
    p.gravity = 9.81;
    return p;
}

}  // namespace

TEST(VelocityReset, RemovesTheDriftOfAnAccelerometerBias) {
    const int cycles = 6;
    const Synthetic s = synthetic(cycles, 0.2);
    const VelocityReset::Result r = VelocityReset(exactParams()).run(s.q, s.acc, s.gyr, s.ts);
    ASSERT_EQ(r.phases.size(), std::size_t(cycles + 1));
    ASSERT_LT(r.first, r.last);
    // Without resets the bias integrates to 0.2 m/s² × 7 s; with them the velocity is the truth.
    double worst = 0.0, worstRaw = 0.0;
    Vec3 raw = Vec3::Zero();
    for (std::size_t k = r.first; k <= r.last; ++k) {
        if (k > r.first) raw += 0.5 * s.ts * (r.acceleration[k - 1] + r.acceleration[k]);
        worst = std::max(worst, (r.velocity[k] - s.velocity[k]).norm());
        worstRaw = std::max(worstRaw, (raw - s.velocity[k]).norm());
    }
    EXPECT_LT(worst, 0.01);
    EXPECT_GT(worstRaw, 1.0);
    // Each cycle moves the sensor by 1 m along x, between consecutive phase centres.
    for (std::size_t i = 0; i + 1 < r.phases.size(); ++i) {
        const std::size_t a = (r.phases[i].begin + r.phases[i].end - 1) / 2,
                          b = (r.phases[i + 1].begin + r.phases[i + 1].end - 1) / 2;
        EXPECT_NEAR(r.position[b].x() - r.position[a].x(), 1.0, 0.01) << "cycle " << i;
        EXPECT_NEAR(r.position[b].y() - r.position[a].y(), 0.0, 1e-9);
        EXPECT_NEAR(r.phases[i + 1].drift.x() - r.phases[i].drift.x(), 0.2 * 1.1, 0.01) << "drift of cycle " << i;
    }
    // Outside the anchored span nothing is claimed.
    EXPECT_TRUE(std::isnan(r.velocity.front().x()));
    EXPECT_TRUE(std::isnan(r.position.back().x()));
}

TEST(VelocityReset, FindsOnePhasePerStillInterval) {
    const Synthetic s = synthetic(4, 0.0);
    const std::vector<VelocityReset::Phase> phases = VelocityReset(exactParams()).detect(s.acc, s.gyr, s.ts);
    ASSERT_EQ(phases.size(), 5u);
    for (std::size_t i = 0; i < phases.size(); ++i) {
        // Still interval i is [1.1 i, 1.1 i + 0.5) s; the detector's window blurs the edges by < 0.06 s.
        EXPECT_NEAR(double(phases[i].begin) * s.ts, 1.1 * double(i), 0.06) << i;
        EXPECT_NEAR(double(phases[i].end) * s.ts, 1.1 * double(i) + 0.5, 0.06) << i;
    }
    // A sensor that never stops has no phase.
    const Synthetic moving = synthetic(1, 0.0, 1.0, 0.0, 3.0);
    EXPECT_TRUE(VelocityReset(exactParams()).detect(moving.acc, moving.gyr, moving.ts).empty());
}

TEST(VelocityReset, CrossCountrySkiThrustsAndCycleSpeeds) {
    const SkiVelocityScore score = evaluateSkiVelocity(7, 20, VelocityReset::crossCountrySki());
    EXPECT_EQ(score.matchedThrusts, score.truthThrusts);
    EXPECT_EQ(score.truthThrusts, 19);
    EXPECT_EQ(score.extraPhases, 0);
    ASSERT_EQ(score.cycleSpeedPct.v.size(), 19u);
    EXPECT_LT(score.cycleSpeedPct.meanAbs(), 0.5);
    EXPECT_LT(score.cycleSpeedPct.maxAbs(), 1.5);
    EXPECT_LT(std::abs(score.thrustStart.mean()), 0.01);
    EXPECT_LT(std::abs(score.thrustEnd.mean()), 0.01);
    EXPECT_LT(score.speedRmse, 0.05);
    // The resets are what makes it right: the same acceleration integrated without them drifts.
    EXPECT_GT(score.speedRmseNoReset, 0.5);
    std::printf("[ figures  ] xc ski: cycle speed mean |e| %.3f %%, speed RMSE %.4f m/s (%.2f without resets)\n",
                score.cycleSpeedPct.meanAbs(), score.speedRmse, score.speedRmseNoReset);
}

TEST(VelocityReset, FootStancesAndStrideLengths) {
    events::SimConfig config = footWalkConfig(3);
    config.accBias += Eigen::Vector3d(0.3, -0.3, 0.15);
    const FootVelocityScore score = evaluateFootVelocity(config, VelocityReset::foot());
    EXPECT_EQ(score.matchedStances, score.truthStrides);
    EXPECT_EQ(score.extraPhases, 0);
    ASSERT_EQ(score.strideLengthPct.v.size(), 12u);
    EXPECT_LT(score.strideLengthPct.meanAbs(), 0.5);
    EXPECT_LT(score.strideLengthPct.maxAbs(), 1.5);
    std::printf("[ figures  ] foot: stride length mean |e| %.3f %%, worst %.3f %%\n", score.strideLengthPct.meanAbs(),
                score.strideLengthPct.maxAbs());
}

TEST(VelocityReset, ProcessorWritesTrajectoryAndPhasesAndRefusesWithoutPhases) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    ASSERT_TRUE(project);
    const auto store = [&](const Synthetic& s, const QString& rec) {
        StreamData imu(s.q.size(), 6), q(s.q.size(), 4);
        for (std::size_t k = 0; k < s.q.size(); ++k) {
            imu.t[k] = q.t[k] = double(k) * s.ts;
            for (int a = 0; a < 3; ++a) {
                imu.at(k, a) = s.acc[k][a];
                imu.at(k, 3 + a) = s.gyr[k][a];
            }
            q.at(k, 0) = 1.0;
        }
        project->putStream(rec + QStringLiteral("/imu"),
                           outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                                        columnsOf({"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"},
                                                  {"m/s^2", "m/s^2", "m/s^2", "rad/s", "rad/s", "rad/s"}),
                                        std::move(imu)));
        project->putStream(rec + QStringLiteral("/q"),
                           outputStream(QStringLiteral("orientation"), QStringLiteral("ENU"),
                                        columnsOf({"qw", "qx", "qy", "qz"}, {"1", "1", "1", "1"}), std::move(q)));
    };
    store(synthetic(3, 0.1), QStringLiteral("a"));
    store(synthetic(1, 0.0, 1.0, 0.0, 3.0), QStringLiteral("b"));
    const VelocityResetProcessor processor;
    const QVariantMap params{{QStringLiteral("gyro_bridge"), QStringLiteral("false")}};
    auto ok = runProcessor(
        *project, processor,
        RunRequest{processor.id(), {QStringLiteral("a/q"), QStringLiteral("a/imu")}, QStringLiteral("a/v"), params});
    ASSERT_TRUE(ok.ok()) << qPrintable(ok.message());
    const Stream* v = project->stream(QStringLiteral("a/v"));
    ASSERT_NE(v, nullptr);
    EXPECT_EQ(v->info().kind, QStringLiteral("trajectory"));
    EXPECT_EQ(v->info().frame, QStringLiteral("ENU"));
    ASSERT_GE(v->info().columnIndex(QStringLiteral("vx")), 0);
    EXPECT_EQ(v->info().columns[std::size_t(v->info().columnIndex(QStringLiteral("vx")))].unit, QStringLiteral("m/s"));
    EXPECT_EQ(v->info().columns[std::size_t(v->info().columnIndex(QStringLiteral("x")))].unit, QStringLiteral("m"));
    const Table* phases = project->table(QStringLiteral("a/v-zero-velocity"));
    ASSERT_NE(phases, nullptr);
    EXPECT_EQ(phases->column(QStringLiteral("start"))->numbers.size(), 4u);
    EXPECT_EQ(phases->column(QStringLiteral("drift_x"))->unit, QStringLiteral("m/s"));

    auto refused = runProcessor(
        *project, processor,
        RunRequest{processor.id(), {QStringLiteral("b/q"), QStringLiteral("b/imu")}, QStringLiteral("b/v"), {}});
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains(QStringLiteral("zero-velocity phase"))) << qPrintable(refused.message());
    EXPECT_EQ(project->stream(QStringLiteral("b/v")), nullptr);
}
