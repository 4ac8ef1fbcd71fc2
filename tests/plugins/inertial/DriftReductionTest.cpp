// Drift reduction (Fasel 2017 ch. 2, 5, 6): the Nelder–Mead minimiser and the Markley mean on worked
// examples, the sensor-to-joint vectors and the relative drift recovered on the body simulator with
// a known drift added, the static correction on a strapdown inclination drift, and the whole chain
// (orientation → calibration → drift reduction → joint angles) improving the simulated skiing run.
#include "core/math/Angles.h"
#include "plugins/inertial/BodySimulator.h"
#include "plugins/inertial/DriftReduction.h"
#include "plugins/inertial/DriftReductionProcessor.h"
#include "plugins/inertial/NelderMead.h"
#include "tools/eval/DriftEvaluation.h"

#include <gtest/gtest.h>

#include <array>
#include <numbers>
#include <random>

using namespace athlos;
using namespace athlos::inertial;
using math::kDeg;
using math::Quat;
using math::Vec3;

TEST(NelderMead, FindsTheRosenbrockMinimum) {
    const auto rosenbrock = [](const Eigen::VectorXd& x) {
        return 100.0 * std::pow(x[1] - x[0] * x[0], 2) + std::pow(1.0 - x[0], 2);
    };
    NelderMead::Params p;
    p.initialStep = 0.5;
    p.xTolerance = 1e-8;
    p.fTolerance = 1e-12;
    const NelderMead::Result r = NelderMead::minimize(rosenbrock, Eigen::Vector2d(-1.2, 1.0), p);
    EXPECT_TRUE(r.converged);
    EXPECT_NEAR(r.x[0], 1.0, 1e-5);
    EXPECT_NEAR(r.x[1], 1.0, 1e-5);
    // A non-smooth cost (sum of absolute values) as in Eq. 5.5: minimum at the median.
    const auto l1 = [](const Eigen::VectorXd& x) {
        return std::abs(x[0] - 1.0) + std::abs(x[0] - 2.0) + std::abs(x[0] - 7.0) + std::abs(x[1] + 3.0);
    };
    const NelderMead::Result m = NelderMead::minimize(l1, Eigen::Vector2d(0.0, 0.0), p);
    EXPECT_NEAR(m.x[0], 2.0, 1e-5);
    EXPECT_NEAR(m.x[1], -3.0, 1e-5);
}

TEST(DriftReduction, MarkleyMeanOfSymmetricSpreadAndSignFlips) {
    const Quat centre = math::quatFromRotationVector(Vec3(0.3, -0.2, 0.5));
    std::vector<Quat> q;
    for (int i = 0; i < 3; ++i)
        for (double s : {-1.0, 1.0}) {
            const Quat e = centre * math::quatFromRotationVector(s * 0.2 * Vec3::Unit(i));
            q.push_back(i == 1 ? Quat(-e.coeffs()) : e);  // the sign of a quaternion must not matter
        }
    EXPECT_LT(DriftReduction::markleyMean(q).angularDistance(centre), 1e-9);
    // Windowed mean: a linearly growing rotation is followed (the window mean of a linear ramp is the ramp).
    const std::size_t n = 1000;
    std::vector<Quat> ramp(n);
    std::vector<unsigned char> valid(n, 1);
    for (std::size_t k = 0; k < n; ++k) ramp[k] = math::quatFromAxisAngle(Vec3(1, 2, 2).normalized(), 1e-3 * k);
    for (std::size_t k = 300; k < 500; ++k) valid[k] = 0;  // a gap is bridged by SLERP
    std::vector<Quat> out;
    ASSERT_TRUE(DriftReduction::windowedMean(ramp, valid, 50, 5, out));
    for (std::size_t k = 60; k + 60 < n; k += 10) {
        // Next to the gap the window is one-sided (its mean lags by up to half a window).
        const bool nearGap = k > 250 && k < 550;
        EXPECT_LT(out[k].angularDistance(ramp[k]), nearGap ? 0.05 : 2e-3) << k;
    }
}

namespace {

BodySimulatorParams cleanSkiing(double motion) {
    BodySimulatorParams p;
    p.uprightDuration = 3.0;
    p.squats = 0;
    p.motionDuration = motion;
    p.gyrBias = p.gyrDrift = p.gSensitivity = p.gyrScale = p.accScale = 0.0;
    p.vibration = p.impactRate = 0.0;
    return p;
}

}  // namespace

TEST(DriftReduction, RecoversSensorToJointVectorsAndRelativeDrift) {
    const BodySimulation sim = simulateBody(cleanSkiing(40.0));
    const double ts = sim.t[1] - sim.t[0];
    const std::size_t n = sim.t.size();
    std::vector<DriftReduction::Segment> segments(kBodySegments);
    std::vector<DriftReduction::Link> links;
    std::mt19937_64 rng(7);
    std::normal_distribution<double> normal;
    std::vector<Vec3> driftAxis(kBodySegments);
    for (int s = 0; s < kBodySegments; ++s) {
        segments[s].acc = sim.sensors[s].acc;
        segments[s].gyr = sim.sensors[s].gyr;
        // A known drift: a rotation about a random axis growing at 0.3°/s, plus a constant heading offset.
        const Vec3 axis = Vec3(normal(rng), normal(rng), normal(rng)).normalized();
        const Quat heading = math::headingRotation(0.4 * s);
        segments[s].q.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            segments[s].q[k] =
                heading * math::quatFromAxisAngle(axis, 0.3 * kDeg * sim.t[k]) * sim.sensors[s].sensor[k];
    }
    for (int j = 0; j < kBodyJoints; ++j) {
        const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
        links.push_back({static_cast<int>(info.proximal), static_cast<int>(info.distal)});
    }
    DriftReduction::Params p = DriftReduction::onSnow();
    p.staticCorrection = false;
    const DriftReduction::Result r = DriftReduction(p).run(segments, links, ts);
    ASSERT_EQ(r.q.size(), std::size_t(kBodySegments));
    for (int j = 0; j < kBodyJoints; ++j) {
        const DriftReduction::LinkResult& lr = r.links[j];
        const BodyJointTruth& truth = sim.joints[j];
        const QString name = bodyJointName(static_cast<BodyJoint>(j));
        // The trunk turns almost rigidly with the pelvis, so the lumbar joint centre is weakly defined
        // by the accelerations (any point moves alike on both); its drift must still come out right.
        if (j != static_cast<int>(BodyJoint::Lumbar)) {
            EXPECT_LT((lr.proximalToJoint - truth.proximalToJoint).norm(), 0.04) << qUtf8Printable(name);
            EXPECT_LT((lr.distalToJoint - truth.distalToJoint).norm(), 0.04) << qUtf8Printable(name);
        }
        EXPECT_GT(lr.validShare, 0.3) << qUtf8Printable(name);
        // Relative orientation of the two sensors over the motion: before ≈ 0.3°/s × t, after small.
        const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
        const auto ip = static_cast<std::size_t>(info.proximal), id = static_cast<std::size_t>(info.distal);
        double before = 0.0, after = 0.0;
        int count = 0;
        for (std::size_t k = 0; k < n; ++k) {
            if (sim.t[k] < sim.motionBegin + 5.0 || sim.t[k] > sim.motionEnd - 5.0) continue;
            const Quat truthRel = sim.sensors[ip].sensor[k].conjugate() * sim.sensors[id].sensor[k];
            before += (segments[ip].q[k].conjugate() * segments[id].q[k]).angularDistance(truthRel);
            after += (r.q[ip][k].conjugate() * r.q[id][k]).angularDistance(truthRel);
            ++count;
        }
        EXPECT_GT(before / count, 5.0 * kDeg) << qUtf8Printable(name);
        EXPECT_LT(after / count, 1.5 * kDeg) << qUtf8Printable(name);
    }
}

TEST(DriftReduction, StaticCorrectionRemovesInclinationDriftAtRest) {
    BodySimulatorParams sp = cleanSkiing(20.0);
    sp.scenario = BodyScenario::Walking;
    sp.accBias = 0.0;  // a bias tilts the measured vertical at rest by atan(b/g)
    const BodySimulation sim = simulateBody(sp);
    const double ts = sim.t[1] - sim.t[0];
    const std::size_t n = sim.t.size();
    // Inclination drift growing linearly (about a horizontal axis), as strapdown with a gyro bias gives.
    std::vector<DriftReduction::Segment> segments(1);
    segments[0].acc = sim.sensors[2].acc;
    segments[0].gyr = sim.sensors[2].gyr;
    segments[0].q.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        segments[0].q[k] = math::quatFromAxisAngle(Vec3::UnitX(), 0.2 * kDeg * sim.t[k]) * sim.sensors[2].sensor[k];
    DriftReduction::Params p;
    p.jointCorrection = false;
    const DriftReduction::Result r = DriftReduction(p).run(segments, {}, ts);
    ASSERT_GE(r.restIntervals[0], 2);
    const auto inclinationError = [&](const Quat& q, std::size_t k) {
        const Vec3 up = q.conjugate() * Vec3::UnitZ(), trueUp = sim.sensors[2].sensor[k].conjugate() * Vec3::UnitZ();
        return std::acos(std::clamp(up.dot(trueUp), -1.0, 1.0));
    };
    double before = 0.0, after = 0.0;
    // Between the first and the last rest instant (before and after them the correction is held).
    for (std::size_t k = 0; k < n; ++k) {
        if (sim.t[k] < sim.motionBegin || sim.t[k] > sim.motionEnd) continue;
        before = std::max(before, inclinationError(segments[0].q[k], k));
        after = std::max(after, inclinationError(r.q[0][k], k));
    }
    EXPECT_GT(before, 4.0 * kDeg);
    EXPECT_LT(after, 0.3 * kDeg);  // linear drift is exactly what SLERP between rest instants removes
}

// Params::estimationRate: the window solution from every 5th sample, mapped back to every sample. With
// `to` = R(t) `from` and R turning steadily (0.5°/s), it must match the solution from every sample at
// every output sample, and the truth: a wrong index mapping (estimate j not at sample 5j) would shift it
// in time.
TEST(DriftReduction, WindowedWahbaFromEveryFifthSampleMatchesEverySample) {
    const double ts = 0.002;  // 500 Hz
    const std::size_t n = 10001, stride = 5;
    const Vec3 axis = Vec3(1.0, 2.0, 3.0).normalized();
    const auto truth = [&](std::size_t k) { return math::quatFromAxisAngle(axis, 0.5 * kDeg * double(k) * ts); };
    // Smooth vectors sweeping a cone (2 Hz about z, 0.7 Hz nod): the window sums are alike for every
    // sample and for every 5th one (random directions would make them differ by chance).
    std::vector<Vec3> from(n), to(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double t = double(k) * ts;
        from[k] = 10.0 * Vec3(std::cos(4.0 * std::numbers::pi * t), std::sin(4.0 * std::numbers::pi * t),
                              0.8 * std::cos(1.4 * std::numbers::pi * t))
                             .normalized();
        to[k] = truth(k) * from[k];
    }
    const std::vector<unsigned char> valid(n, 1);
    std::vector<Quat> every;
    // No pull to the identity (prior 0): it biases both towards it by an amount that depends on the
    // sample set, which is not what is compared here.
    ASSERT_TRUE(DriftReduction::windowedWahba(from, to, valid, 625, 25, 125, false, every, 0.0));
    const std::size_t ne = (n - 1) / stride + 1;
    std::vector<Vec3> fromE(ne), toE(ne);
    for (std::size_t j = 0; j < ne; ++j) {
        fromE[j] = from[j * stride];
        toE[j] = to[j * stride];
    }
    std::vector<Quat> thinned;
    ASSERT_TRUE(DriftReduction::windowedWahba(fromE, toE, std::vector<unsigned char>(ne, 1), 125, 5, 25, false, thinned,
                                              0.0, stride, n));
    ASSERT_EQ(thinned.size(), n);
    double worst = 0.0, worstTruth = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        worst = std::max(worst, thinned[k].angularDistance(every[k]));
        // Away from the ends (where the window is one-sided and the estimate is held).
        if (k > 700 && k + 700 < n) worstTruth = std::max(worstTruth, thinned[k].angularDistance(truth(k)));
    }
    EXPECT_LT(worst, 0.005 * kDeg);  // one estimate step (25 samples) off would be 0.025°
    EXPECT_LT(worstTruth, 0.1 * kDeg);
}

// The same on the whole chain at 500 Hz: the on-snow preset's 100 Hz estimation (every 5th sample) gives
// the joint angles of every sample (docs/validation/drift-reduction.md: ≤ 0.01° over 10 seeds).
TEST(DriftReduction, EstimationRateKeepsTheSkiingAnglesAt500Hz) {
    eval::DriftEvaluationOptions o;
    o.simulation.motionDuration = 40.0;
    o.simulation.rate = 500.0;
    o.simulation.seed = 3;
    ASSERT_EQ(o.reduction.estimationRate, 100.0);
    const eval::DriftEvaluation thinned = eval::evaluateDriftReduction(o);
    o.reduction.estimationRate = 0.0;
    const eval::DriftEvaluation every = eval::evaluateDriftReduction(o);
    for (int j = 0; j < kBodyJoints; ++j)
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(thinned.joints[j].rmse[i], every.joints[j].rmse[i], 0.05 * kDeg)
                << qUtf8Printable(bodyJointName(static_cast<BodyJoint>(j))) << " axis " << i;
}

// The judged figure in small (docs/validation/drift-reduction.md has the 2-minute run): a skiing run
// with 0.15°/s gyroscope drift and every sensor error, 6D orientation, functional calibration, joint
// angles. Drift reduction must make the angles better, and good.
TEST(DriftReduction, ImprovesJointAnglesOnTheSimulatedSkiingRun) {
    eval::DriftEvaluationOptions o;
    o.simulation.motionDuration = 60.0;
    o.simulation.seed = 3;
    o.driftReduction = false;
    const eval::DriftEvaluation without = eval::evaluateDriftReduction(o);
    o.driftReduction = true;
    const eval::DriftEvaluation with = eval::evaluateDriftReduction(o);
    double sumWithout = 0.0, sumWith = 0.0;
    for (BodyJoint j : {BodyJoint::RightKnee, BodyJoint::LeftKnee, BodyJoint::RightHip, BodyJoint::LeftHip}) {
        const auto& a = without.joints[static_cast<int>(j)].rmse;
        const auto& b = with.joints[static_cast<int>(j)].rmse;
        for (int i = 0; i < 3; ++i) {
            sumWithout += a[i];
            sumWith += b[i];
        }
        const bool knee = j == BodyJoint::RightKnee || j == BodyJoint::LeftKnee;
        EXPECT_LT(b[0], (knee ? 3.0 : 4.0) * kDeg) << qUtf8Printable(bodyJointName(j));
        EXPECT_LT(b[1], 5.0 * kDeg) << qUtf8Printable(bodyJointName(j));
        EXPECT_LT(b[2], 5.0 * kDeg) << qUtf8Printable(bodyJointName(j));
    }
    EXPECT_LT(sumWith, 0.7 * sumWithout);
}

// static_correction=auto (docs/validation/drift-reduction.md, known problems): the static correction
// spreads the error found at each rest back over the motion, the model of a gyroscope integration. For
// strap-down input it is what brings the inclination back; for VQF, whose error at the rest after the
// stop is a transient, it made the inclination worse. The rule picks it for the first only, and on
// the simulated skiing run each choice beats the other on its input.
TEST(DriftReduction, StaticCorrectionOnlyForGyroscopeIntegration) {
    EXPECT_TRUE(staticCorrectionSuits(QStringLiteral("strapdown")));
    for (const char* other : {"vqf", "madgwick", "mahony", "kalman", ""})
        EXPECT_FALSE(staticCorrectionSuits(QString::fromLatin1(other))) << other;
    const auto meanInclination = [](const eval::DriftEvaluation& e) {
        double sum = 0.0;
        for (double x : e.orientationError) sum += x / kBodySegments;
        return sum;
    };
    eval::DriftEvaluationOptions o;
    o.simulation.motionDuration = 60.0;
    o.simulation.seed = 3;
    for (const OrientationAlgorithm algorithm : {OrientationAlgorithm::Vqf, OrientationAlgorithm::Strapdown}) {
        o.orientation.algorithm = algorithm;
        o.staticCorrectionAuto = true;
        const double automatic = meanInclination(eval::evaluateDriftReduction(o));
        o.staticCorrectionAuto = false;
        o.reduction.staticCorrection = algorithm != OrientationAlgorithm::Strapdown;  // the other choice
        const double other = meanInclination(eval::evaluateDriftReduction(o));
        o.reduction.staticCorrection = true;
        EXPECT_LT(automatic, other - 1.0 * kDeg) << qUtf8Printable(orientationAlgorithmName(algorithm)) << ": auto "
                                                 << automatic / kDeg << "°, other " << other / kDeg << "°";
    }
}

// Walking (issue #17 item 3(b), docs/validation/drift-reduction.md): the pelvis hardly turns, the hip
// joint centre's horizontal acceleration stays below the azimuth threshold (0.6 m/s²) on almost every
// sample, and the sacrum's sensor-to-joint fit has a second minimum. The joint heading fitted on all
// samples then came out 110–170° wrong and hip rotation went from 7–9° to 70–123°. Drift reduction must
// not make any joint angle clearly worse than the start-aligned angles without it (mean of two 2-minute
// walks, each axis within 1°), and the hips must be good.
TEST(DriftReduction, DoesNotSpoilJointAnglesInWalking) {
    std::array<std::array<double, 3>, kBodyJoints> without{}, with{};
    constexpr int kSeeds = 2;
    for (int seed = 1; seed <= kSeeds; ++seed) {
        eval::DriftEvaluationOptions o;
        o.simulation.scenario = BodyScenario::Walking;
        o.simulation.seed = static_cast<std::uint64_t>(seed);  // the 2-minute walk of the validation page
        o.reduction = DriftReduction::indoor();
        for (const bool on : {false, true}) {
            o.driftReduction = on;
            const eval::DriftEvaluation e = eval::evaluateDriftReduction(o);
            for (int j = 0; j < kBodyJoints; ++j)
                for (int i = 0; i < 3; ++i) (on ? with : without)[j][i] += e.joints[j].rmse[i] / kSeeds;
        }
    }
    const char* axes[] = {"flexion", "abduction", "rotation"};
    for (int j = 0; j < kBodyJoints; ++j) {
        const QString name = bodyJointName(static_cast<BodyJoint>(j));
        for (int i = 0; i < 3; ++i)
            EXPECT_LT(with[j][i], without[j][i] + 1.0 * kDeg)
                << qUtf8Printable(name) << ' ' << axes[i] << ": without " << without[j][i] / kDeg << "°, with "
                << with[j][i] / kDeg << "°";
    }
    for (BodyJoint j : {BodyJoint::RightHip, BodyJoint::LeftHip})
        for (int i = 0; i < 3; ++i)
            EXPECT_LT(with[static_cast<int>(j)][i], 5.0 * kDeg) << qUtf8Printable(bodyJointName(j)) << ' ' << axes[i];
}
