// gait-parameters' algorithm (StrideSegmenter + StrideIntegrator, and with method = rts the
// ZuptKalmanSmoother) on the foot-motion simulator, whose stride lengths, heights, turns and swing
// heights are known: stride count exact, lengths within 1.5 %, turns within 0.03 rad, with noise and
// gyroscope/accelerometer biases; then a stance that is never still (heel-to-toe roll, the sensor
// off the pivot, pivots in turns) and scale errors, both methods side by side.
// Figures: docs/validation/gait-parameters.md.
#include "plugins/events/FootMotionSimulator.h"
#include "plugins/events/MediolateralAxis.h"
#include "plugins/events/StaticGyroBias.h"
#include "plugins/events/StrideIntegrator.h"
#include "plugins/events/ZuptKalmanSmoother.h"

#include <Eigen/Geometry>
#include <cmath>
#include <gtest/gtest.h>

using namespace athlos::events;

namespace {

struct Result {
    SimRecording rec;
    StrideSegmentation segmentation;
    FootTrajectory trajectory;  // method = instant
    FootTrajectory smoothed;    // method = rts
    StaticGyroBias bias;
};

// mount: the sensor frame the signals are expressed in, v_mounted = mount · v (identity: the simulator's
// "x forward, z up"); autoAxis: the medio-lateral axis from the data (ml_axis = auto) instead of params'.
Result run(const SimConfig& config, StrideSegmentationParams params = {},
           const Eigen::Matrix3d& mount = Eigen::Matrix3d::Identity(), bool autoAxis = false) {
    Result r;
    r.rec = simulateFoot(config);
    for (std::size_t k = 0; k < r.rec.t.size(); ++k)
        for (std::size_t c : {std::size_t(0), std::size_t(3)}) {
            Eigen::Map<Eigen::Vector3d> v(r.rec.values.data() + 6 * k + c);
            v = mount * Eigen::Vector3d(v);
        }
    const double* v = r.rec.values.data();
    const std::size_t n = r.rec.t.size();
    // As the processor does: the gyroscope bias from the standing phases removed first.
    r.bias = estimateStaticGyroBias(r.rec.t.data(), v + 3, n, 6, params.restWindow, params.staticThreshold, 1.0);
    std::vector<double> gyr(3 * n);
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t i = 0; i < 3; ++i) gyr[3 * k + i] = v[6 * k + 3 + i] - r.bias.bias[int(i)];
    if (autoAxis) params.mlAxis = mediolateralAxis(QStringLiteral("auto"), gyr.data(), n, 3)->axis;
    r.segmentation = segmentStrides(params, r.rec.t.data(), gyr.data(), n, 3);
    r.trajectory = integrateStrides({}, r.segmentation.strides, r.rec.t.data(), v, 6, gyr.data(), 3, n);
    r.smoothed = smoothStrides({}, r.segmentation.strides, r.rec.t.data(), v, 6, gyr.data(), 3, n);
    return r;
}

// Stride-length error against the sensor's true horizontal displacement between the middles of the
// stances around each swing (the footprint's stride length when the sensor sits on the pivot).
struct LengthError {
    double mean = 0.0, worst = 0.0;
};
LengthError lengthError(const Result& r, const FootTrajectory& trajectory) {
    LengthError e;
    const auto& truth = r.rec.truth;
    const double rate = 1.0 / (r.rec.t[1] - r.rec.t[0]);
    const auto at = [&](double t) { return r.rec.position[std::size_t(std::lround(t * rate))]; };
    for (std::size_t i = 0; i < truth.size() && i < trajectory.strides.size(); ++i) {
        const double length = (at(truth[i].end) - at(truth[i].start)).head<2>().norm();
        const double error = std::abs(trajectory.strides[i].length - length) / length;
        e.mean += error / double(truth.size());
        e.worst = std::max(e.worst, error);
    }
    return e;
}

void printFigures(const char* scenario, const Result& r) {
    const LengthError a = lengthError(r, r.trajectory), b = lengthError(r, r.smoothed);
    std::printf(
        "[ figures  ] %s: stride length error, instant mean %.2f %% worst %.2f %%; rts mean %.2f %% worst %.2f "
        "%%\n",
        scenario, 100.0 * a.mean, 100.0 * a.worst, 100.0 * b.mean, 100.0 * b.worst);
}

// Every simulated stride found once: its estimate starts in the stance before its swing and ends
// in the stance after it.
void expectMatched(const Result& r) {
    const auto& truth = r.rec.truth;
    ASSERT_EQ(r.trajectory.strides.size(), truth.size());
    for (std::size_t i = 0; i < truth.size(); ++i) {
        const StrideEstimate& e = r.trajectory.strides[i];
        const double previousSwingEnd = i ? truth[i - 1].swingStart + truth[i - 1].swing : 0.0;
        EXPECT_GE(e.tStart, previousSwingEnd) << "stride " << i;
        EXPECT_LE(e.tStart, truth[i].swingStart) << "stride " << i;
        EXPECT_GE(e.tEnd, truth[i].swingStart + truth[i].swing) << "stride " << i;
        if (i + 1 < truth.size()) {
            EXPECT_LE(e.tEnd, truth[i + 1].swingStart) << "stride " << i;
        }
    }
}

double relativeError(double estimate, double truth) { return std::abs(estimate - truth) / truth; }

SimConfig levelWalk() {
    SimConfig c;
    for (int i = 0; i < 12; ++i) {
        SimStride s;
        s.length = 1.2 + 0.04 * i;  // 1.20 … 1.64 m
        s.stance = 0.6 + 0.01 * (i % 3);
        c.strides.push_back(s);
    }
    return c;
}

}  // namespace

TEST(GaitParametersSimulation, LevelWalkLengthsWithinOnePointFivePercent) {
    const Result r = run(levelWalk());
    expectMatched(r);
    // The bias from the 2 s of standing at each end (noise 0.01 rad/s over ~400 samples).
    EXPECT_GT(r.bias.staticTime, 3.0);
    EXPECT_LT((r.bias.bias - SimConfig{}.gyrBias).norm(), 0.002) << r.bias.bias.transpose();
    double worst = 0.0;
    for (std::size_t i = 0; i < r.rec.truth.size(); ++i) {
        const auto& truth = r.rec.truth[i];
        const auto& e = r.trajectory.strides[i];
        worst = std::max(worst, relativeError(e.length, truth.length));
        EXPECT_LT(relativeError(e.length, truth.length), 0.015) << "stride " << i << ": " << e.length;
        EXPECT_NEAR(e.height, 0.0, 0.03) << "stride " << i;
        EXPECT_NEAR(e.maxClearance, truth.lift, 0.015) << "stride " << i;
        EXPECT_NEAR(e.turningAngle, 0.0, 0.02) << "stride " << i;
    }
    std::printf("[ figures  ] level walk, 102.4 Hz: %zu strides, worst stride-length error %.2f %%\n",
                r.trajectory.strides.size(), 100.0 * worst);
    // The smoother, with the same strides: as accurate, and the same heights and clearances.
    printFigures("level walk, 102.4 Hz", r);
    EXPECT_LT(lengthError(r, r.smoothed).worst, 0.015);
    for (std::size_t i = 0; i < r.rec.truth.size(); ++i) {
        EXPECT_NEAR(r.smoothed.strides[i].height, 0.0, 0.03) << "stride " << i;
        EXPECT_NEAR(r.smoothed.strides[i].maxClearance, r.rec.truth[i].lift, 0.015) << "stride " << i;
        EXPECT_NEAR(r.smoothed.strides[i].turningAngle, 0.0, 0.02) << "stride " << i;
    }
}

TEST(GaitParametersSimulation, TurnsGiveTheirHeadingChange) {
    SimConfig c;
    const double turns[] = {0.0, 0.0, 0.5, 0.5, 0.5, -0.3, 0.0, 1.0, -0.8, 0.0};
    for (double turn : turns) {
        SimStride s;
        s.turn = turn;
        s.length = std::abs(turn) > 0.7 ? 0.8 : 1.3;  // tight turns take short strides
        c.strides.push_back(s);
    }
    const Result r = run(c);
    expectMatched(r);
    double worstTurn = 0.0, worstLength = 0.0;
    for (std::size_t i = 0; i < r.rec.truth.size(); ++i) {
        const auto& truth = r.rec.truth[i];
        const auto& e = r.trajectory.strides[i];
        EXPECT_NEAR(e.turningAngle, truth.turn, 0.03) << "stride " << i;
        EXPECT_LT(relativeError(e.length, truth.length), 0.02) << "stride " << i << ": " << e.length;
        worstTurn = std::max(worstTurn, std::abs(e.turningAngle - truth.turn));
        worstLength = std::max(worstLength, relativeError(e.length, truth.length));
    }
    // The trajectory's end point is the sum of the strides: the path closes where the truth does.
    std::printf("[ figures  ] turns: worst turning-angle error %.4f rad, worst length error %.2f %%\n", worstTurn,
                100.0 * worstLength);
    printFigures("turns, 102.4 Hz", r);
    EXPECT_LT(lengthError(r, r.smoothed).worst, 0.02);
    for (std::size_t i = 0; i < r.rec.truth.size(); ++i)
        EXPECT_NEAR(r.smoothed.strides[i].turningAngle, r.rec.truth[i].turn, 0.03) << "stride " << i;
}

TEST(GaitParametersSimulation, AnyMountingWithTheAutomaticAxis) {
    // The same turning walk expressed in three other sensor frames: gaitmap's raw lateral NilsPod
    // (x up, ML along z), an oblique mount and one upside down. With ml_axis = auto the axis is found
    // along the true medio-lateral direction, and strides, lengths and turns are those of the aligned
    // sensor for both methods (the mounting cancels in the levelling and in the heading change).
    SimConfig c = levelWalk();
    const double turns[] = {0.0, 0.4, -0.3, 0.0, 0.8, -0.6, 0.0, 0.2, 0.0, -0.4, 0.3, 0.0};
    for (std::size_t i = 0; i < c.strides.size(); ++i) c.strides[i].turn = turns[i];
    const Result a = run(c);
    expectMatched(a);
    const Eigen::Matrix3d mounts[] = {
        (Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()))
            .toRotationMatrix(),
        Eigen::AngleAxisd(2.0, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix(),
        Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix()};
    for (const Eigen::Matrix3d& mount : mounts) {
        const Result b = run(c, {}, mount, true);
        std::vector<double> gyr(3 * b.rec.t.size());
        for (std::size_t k = 0; k < b.rec.t.size(); ++k)
            for (std::size_t i = 0; i < 3; ++i) gyr[3 * k + i] = b.rec.values[6 * k + 3 + i];
        const MediolateralAxis axis = *mediolateralAxis(QStringLiteral("auto"), gyr.data(), b.rec.t.size(), 3);
        EXPECT_GT(std::abs(axis.axis.dot(mount * Eigen::Vector3d::UnitY())), 0.99) << axis.axis.transpose();
        std::printf(
            "[ figures  ] mount: true ML axis [%.3f %.3f %.3f], principal [%.3f %.3f %.3f], used [%.3f %.3f "
            "%.3f], dominance %.2f\n",
            (mount * Eigen::Vector3d::UnitY()).x(), (mount * Eigen::Vector3d::UnitY()).y(),
            (mount * Eigen::Vector3d::UnitY()).z(), axis.principal.x(), axis.principal.y(), axis.principal.z(),
            axis.axis.x(), axis.axis.y(), axis.axis.z(), axis.dominance);
        EXPECT_GT(axis.dominance, 0.6);
        expectMatched(b);
        ASSERT_EQ(b.smoothed.strides.size(), a.smoothed.strides.size());
        for (std::size_t i = 0; i < a.trajectory.strides.size(); ++i) {
            const auto &x = a.trajectory.strides[i], &y = b.trajectory.strides[i];
            EXPECT_DOUBLE_EQ(x.tStart, y.tStart) << "stride " << i;
            EXPECT_NEAR(x.length, y.length, 1e-6) << "stride " << i;
            EXPECT_NEAR(x.turningAngle, y.turningAngle, 1e-6) << "stride " << i;
            EXPECT_NEAR(y.turningAngle, b.rec.truth[i].turn, 0.03) << "stride " << i;
            EXPECT_LT(relativeError(y.length, b.rec.truth[i].length), 0.015) << "stride " << i;
            EXPECT_NEAR(a.smoothed.strides[i].length, b.smoothed.strides[i].length, 1e-6) << "stride " << i;
            EXPECT_NEAR(b.smoothed.strides[i].turningAngle, b.rec.truth[i].turn, 0.03) << "stride " << i;
        }
    }
}

TEST(GaitParametersSimulation, StairsGiveHorizontalLengthAndStepPairHeight) {
    for (double rise : {0.34, -0.34}) {  // two 17 cm steps per stride, up and down
        SimConfig c;
        c.rate = 204.8;
        for (int i = 0; i < 8; ++i) {
            SimStride s;
            s.length = 0.58;
            s.rise = rise;
            s.lift = 0.08;
            s.pitch = 0.4;
            s.swing = 0.55;
            c.strides.push_back(s);
        }
        const Result r = run(c);
        expectMatched(r);
        double worstHeight = 0.0, worstLength = 0.0;
        for (std::size_t i = 0; i < r.rec.truth.size(); ++i) {
            const auto& e = r.trajectory.strides[i];
            EXPECT_NEAR(e.height, rise, 0.01) << "stride " << i;
            EXPECT_LT(relativeError(e.length, 0.58), 0.02) << "stride " << i << ": " << e.length;
            worstHeight = std::max(worstHeight, std::abs(e.height - rise));
            worstLength = std::max(worstLength, relativeError(e.length, 0.58));
        }
        std::printf(
            "[ figures  ] stairs %+.2f m per stride, 204.8 Hz: worst height error %.1f mm, worst length "
            "error %.2f %%\n",
            rise, 1000.0 * worstHeight, 100.0 * worstLength);
        printFigures(rise > 0.0 ? "stairs up, 204.8 Hz" : "stairs down, 204.8 Hz", r);
        EXPECT_LT(lengthError(r, r.smoothed).worst, 0.02);
        for (std::size_t i = 0; i < r.rec.truth.size(); ++i)
            EXPECT_NEAR(r.smoothed.strides[i].height, rise, 0.01) << "stride " << i;
    }
}

namespace {

// 14 running strides of 2.4–2.55 m at 204.8 Hz: swing 0.52 s, lift 0.25 m, pitch 1 rad.
SimConfig running(double stance) {
    SimConfig c;
    c.rate = 204.8;
    for (int i = 0; i < 14; ++i) {
        SimStride s;
        s.length = 2.4 + 0.05 * (i % 4);
        s.stance = stance;
        s.swing = 0.52;
        s.lift = 0.25;
        s.pitch = 1.0;
        c.strides.push_back(s);
    }
    return c;
}

}  // namespace

TEST(GaitParametersSimulation, RunningWithShortStance) {
    const Result r = run(running(0.18));
    expectMatched(r);
    double worst = 0.0;
    for (std::size_t i = 0; i < r.rec.truth.size(); ++i) {
        const double error = relativeError(r.trajectory.strides[i].length, r.rec.truth[i].length);
        EXPECT_LT(error, 0.015) << "stride " << i;
        worst = std::max(worst, error);
    }
    std::printf("[ figures  ] running (stance 0.18 s), 204.8 Hz: %zu strides, worst length error %.2f %%\n",
                r.trajectory.strides.size(), 100.0 * worst);
    printFigures("running, 204.8 Hz", r);
    EXPECT_LT(lengthError(r, r.smoothed).worst, 0.015);
}

TEST(GaitParametersSimulation, RunningFootThatRollsThroughStance) {
    // A running foot is never still: it lands and pushes off at 10 rad/s and rolls at 1 rad/s in
    // between, so the quietest 0.15 s of its 0.2 s stance averages more than rest_threshold (2 rad/s).
    // Between two swings that is still the mid-stance: every stride is found (none were while
    // rest_threshold held every mid-stance). The sensor sits 10 cm behind the pivot, so zero velocity
    // at the mid-stance is off by ω × d ≈ 0.1 m/s; the smoother's zero-velocity samples stop where the
    // roll speeds up (before: mean 6.1 %, worst 6.9 %). Bounds: the measured worst errors plus a margin.
    SimConfig c = running(0.2);
    c.stanceRate = 1.0;
    c.stanceEdgeRate = 10.0;
    c.leverArm = Eigen::Vector3d(-0.10, 0.0, 0.06);
    const Result r = run(c);
    expectMatched(r);
    double low = 1e9, high = 0.0;
    for (std::size_t i = 0; i + 1 < r.segmentation.strides.size(); ++i) {
        const double rest = r.segmentation.strides[i].restEnd;
        EXPECT_GT(rest, StrideSegmentationParams{}.restThreshold) << "stride " << i;
        low = std::min(low, rest);
        high = std::max(high, rest);
    }
    std::printf("[ figures  ] running with a rolling stance: mean gyroscope norm at the mid-stances %.2f–%.2f rad/s\n",
                low, high);
    const LengthError instant = lengthError(r, r.trajectory), rts = lengthError(r, r.smoothed);
    EXPECT_LT(instant.worst, 0.045);
    EXPECT_LT(rts.worst, 0.035);
    // The simulator's accelerometer noise is white, which the smoother's dynamic noise does not
    // assume: rts 2.3 % against instant 2.2 % here (1.65 % with version 4's white-noise model).
    EXPECT_LT(rts.mean, 0.03);
    printFigures("running, stance roll 1 rad/s (10 at contact and push-off), 204.8 Hz", r);
}

TEST(GaitParametersSimulation, StandingStillBetweenBoutsAddsNoStride) {
    SimConfig c = levelWalk();
    c.strides[6].stance = 4.0;  // the walker stops for 4 s, then walks on
    const Result r = run(c);
    expectMatched(r);
    EXPECT_EQ(r.segmentation.swings, c.strides.size());
    // The strides next to the stop keep their lengths: the standing time is not integrated.
    EXPECT_LT(relativeError(r.trajectory.strides[5].length, c.strides[5].length), 0.015);
    EXPECT_LT(relativeError(r.trajectory.strides[6].length, c.strides[6].length), 0.015);
    printFigures("4 s stop", r);
    EXPECT_LT(lengthError(r, r.smoothed).worst, 0.015);
}

TEST(GaitParametersSimulation, ShortPauseIsInNoStride) {
    // A 1.5 s pause keeps the swings closer than max_stride (2.5 s): the strides around it must
    // still end where the foot comes to rest and start where it leaves, not in the middle of the
    // pause (which would move the stride midpoints out of the contact-to-contact strides).
    SimConfig c = levelWalk();
    c.strides[6].stance = 1.5;
    const Result r = run(c);
    expectMatched(r);
    const auto& truth = r.rec.truth;
    const double pauseFrom = truth[5].swingStart + truth[5].swing, pauseTo = truth[6].swingStart;
    EXPECT_LT(r.trajectory.strides[5].tEnd, pauseFrom + 0.5);  // the middle is 0.75 s in
    EXPECT_GT(r.trajectory.strides[6].tStart, pauseTo - 0.5);
    EXPECT_LT(relativeError(r.trajectory.strides[5].length, c.strides[5].length), 0.015);
    EXPECT_LT(relativeError(r.trajectory.strides[6].length, c.strides[6].length), 0.015);
    printFigures("1.5 s pause", r);
    EXPECT_LT(lengthError(r, r.smoothed).worst, 0.015);
}

TEST(GaitParametersSimulation, DataStartingMidSwingDropsThatStride) {
    SimConfig c = levelWalk();
    c.standStart = 0.0;
    c.strides[0].stance = 0.0;  // the recording starts with the first swing
    const Result r = run(c);
    ASSERT_EQ(r.trajectory.strides.size(), c.strides.size() - 1);
    EXPECT_GE(r.trajectory.strides.front().tStart, c.strides[0].swing);
}

TEST(GaitParametersSimulation, TrajectoryIsContinuousAndEndsAtTheSumOfStrides) {
    SimConfig c = levelWalk();
    for (auto& s : c.strides) s.turn = 0.15;
    const Result r = run(c);
    expectMatched(r);
    // Truth: footholds along a polygon with headings 0, 0.15, 0.30, ... (each stride's mean).
    Eigen::Vector2d end = Eigen::Vector2d::Zero();
    double heading = 0.0;
    for (const auto& s : c.strides) {
        end += s.length * Eigen::Vector2d(std::cos(heading + 0.5 * s.turn), std::sin(heading + 0.5 * s.turn));
        heading += s.turn;
    }
    const auto& pos = r.trajectory.position;
    ASSERT_FALSE(pos.empty());
    const Eigen::Vector2d estimate = pos.back().head<2>();
    double path = 0.0;
    for (const auto& s : c.strides) path += s.length;
    EXPECT_LT((estimate - end).norm(), 0.02 * path) << estimate.transpose() << " vs " << end.transpose();
    for (std::size_t k = 1; k < pos.size(); ++k) ASSERT_LT((pos[k] - pos[k - 1]).norm(), 0.1) << k;
    // The smoother's trajectory: one row per sample as well, and the same end point.
    const auto& smoothed = r.smoothed.position;
    ASSERT_EQ(smoothed.size(), pos.size());
    EXPECT_LT((smoothed.back().head<2>() - end).norm(), 0.02 * path) << smoothed.back().transpose();
    for (std::size_t k = 1; k < smoothed.size(); ++k) ASSERT_LT((smoothed[k] - smoothed[k - 1]).norm(), 0.1) << k;
    printFigures("12 strides turning 0.15 rad", r);
}

namespace {

// What real feet do and the simulator's default foot does not: the stance is never still (a
// heel-to-toe roll at `rate` about the ball of the foot, the sensor 10 cm behind and 6 cm above it
// on the instep), and the sensor has per-axis scale errors.
SimConfig rolling(double rate, double stanceRate) {
    SimConfig c = levelWalk();
    c.rate = rate;
    c.stanceRate = stanceRate;
    c.leverArm = Eigen::Vector3d(-0.10, 0.0, 0.06);
    c.accScale = Eigen::Vector3d(1.01, 0.99, 1.015);
    c.gyrScale = Eigen::Vector3d(1.02, 0.985, 1.01);
    return c;
}

}  // namespace

TEST(GaitParametersSimulation, StanceThatIsNeverStill) {
    // Zero velocity is assumed where the sensor still moves (ω × lever arm ≈ 0.12 m/s at 1 rad/s),
    // so both methods lose about that speed times the stride time: a bias that grows with the
    // roll rate, not a failure. The bounds are the measured worst errors plus a margin; the
    // smoother's mean must not be worse than the instant method's.
    for (double rate : {102.4, 204.8})
        for (const auto& [stanceRate, bound] : {std::pair{0.5, 0.04}, std::pair{1.0, 0.06}, std::pair{1.5, 0.085}}) {
            const Result r = run(rolling(rate, stanceRate));
            expectMatched(r);
            const LengthError instant = lengthError(r, r.trajectory), rts = lengthError(r, r.smoothed);
            EXPECT_LT(instant.worst, bound) << rate << " Hz, " << stanceRate << " rad/s";
            EXPECT_LT(rts.worst, bound) << rate << " Hz, " << stanceRate << " rad/s";
            EXPECT_LE(rts.mean, instant.mean + 0.002) << rate << " Hz, " << stanceRate << " rad/s";
            char scenario[96];
            std::snprintf(scenario, sizeof scenario, "stance roll %.1f rad/s, scale errors, %.1f Hz", stanceRate, rate);
            printFigures(scenario, r);
        }
}

TEST(GaitParametersSimulation, FootPivotsInStanceWhileTurning) {
    // Part of each turn happens in the stance, the foot pivoting on its ball, on top of the roll.
    const double pivots[] = {0, 0, 0.3, 0.2, 0, -0.25, 0, 0.4, 0, 0, -0.3, 0};
    const double turns[] = {0, 0, 0.4, 0.3, 0, -0.4, 0, 0.8, 0, 0, -0.5, 0};
    for (double rate : {102.4, 204.8}) {
        SimConfig c = rolling(rate, 1.0);
        for (std::size_t i = 0; i < c.strides.size(); ++i) {
            c.strides[i].stancePivot = pivots[i];
            c.strides[i].turn = turns[i];
            if (std::abs(turns[i]) > 0.7) c.strides[i].length = 0.9;
        }
        const Result r = run(c);
        expectMatched(r);
        const LengthError instant = lengthError(r, r.trajectory), rts = lengthError(r, r.smoothed);
        EXPECT_LT(instant.worst, 0.075) << rate;
        EXPECT_LT(rts.worst, 0.075) << rate;
        EXPECT_LE(rts.mean, instant.mean + 0.002) << rate;
        printFigures(
            rate > 150.0 ? "pivots in stance while turning, 204.8 Hz" : "pivots in stance while turning, 102.4 Hz", r);
    }
}

TEST(GaitParametersSimulation, ScaleErrorsOnAStillFoot) {
    // 1–1.5 % scale errors: the horizontal accelerations are scaled, so are the lengths.
    SimConfig c = levelWalk();
    c.rate = 204.8;
    c.accScale = Eigen::Vector3d(1.01, 0.99, 1.015);
    c.gyrScale = Eigen::Vector3d(1.02, 0.985, 1.01);
    const Result r = run(c);
    expectMatched(r);
    EXPECT_LT(lengthError(r, r.trajectory).worst, 0.015);
    EXPECT_LT(lengthError(r, r.smoothed).worst, 0.015);
    printFigures("still stance, scale errors, 204.8 Hz", r);
}
