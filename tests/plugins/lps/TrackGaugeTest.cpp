// Track gauge of the calibration (TrackGauge.h, LpsCalibration gauge=auto|guess|track): the rotation
// about the reference node's vertical axis from a walk along the track, the fallback to the guess
// when the walk does not follow the track, and the judged flow over several venues.
#include "LpsTestSupport.h"

#include "core/processing/ProcessorRunner.h"
#include "plugins/lps/FrameAlignment.h"
#include "plugins/lps/LpsCalibration.h"
#include "plugins/lps/LpsCalibrationProcessor.h"
#include "plugins/lps/LpsPositioningProcessor.h"
#include "plugins/lps/SimulateLpsProcessor.h"
#include "plugins/lps/TdoaSimulator.h"
#include "plugins/lps/TrackGauge.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace athlos;
using namespace athlos::lps;
using namespace athlos::lps::testsupport;

namespace {

// Points of a trajectory rotated by −θ about the pivot (so the fit must find +θ), with noise.
std::vector<Vector3> rotatedWalk(const std::vector<TrajectorySample>& samples, const Vector3& pivot, double theta,
                                 double noise, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n(0.0, noise);
    BeaconLayout layout;
    layout.reference = pivot;
    for (const auto& s : samples) layout.positions.push_back(s.position + Vector3(n(rng), n(rng), 0.0));
    rotateLayout(layout, -theta);
    return layout.positions;
}

// A random walk at 1.4 m/s, 1 Hz, heading changes of σ 0.6 rad, reflected inside the track's area.
std::vector<TrajectorySample> randomWalk(int steps, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n(0.0, 1.0);
    std::vector<TrajectorySample> walk;
    Vector3 p(-20.0, -10.0, 1.0);
    double heading = 0.3;
    for (int k = 0; k < steps; ++k) {
        walk.push_back({double(k), p, heading});
        heading += 0.6 * n(rng);
        p += 1.4 * Vector3(std::cos(heading), std::sin(heading), 0.0);
        if (std::abs(p.x()) > 70.0) {
            p.x() = std::copysign(70.0, p.x());
            heading = std::numbers::pi - heading;
        }
        if (std::abs(p.y()) > 30.0) {
            p.y() = std::copysign(30.0, p.y());
            heading = -heading;
        }
    }
    return walk;
}

}  // namespace

TEST(TrackGauge, RecoversTheRotationOfALaneThreeWalk) {
    const TrackGeometry track;
    const auto lane3 = TdoaSimulator::laps(track, track.laneOffset(3), 1.4, 1.0, 1.0, 1.0);
    for (const Vector3& pivot : {Vector3(0, 0, 0), Vector3(4.0, -2.5, 0.5)}) {
        for (const double theta : {0.008, -0.004, 0.02}) {
            const auto walk = rotatedWalk(lane3, pivot, theta, 0.1, 5);
            const TrackGaugeFit fit = fitTrackGauge(walk, pivot, track);
            ASSERT_TRUE(fit.valid);
            EXPECT_NEAR(fit.rotation, theta, 0.5e-3) << "pivot " << pivot.transpose();
            EXPECT_NEAR(fit.lateralOffset, track.laneOffset(3), 0.05);  // 2.74 m: the walker's lane, a nuisance
            EXPECT_LT(fit.rms, 0.15);
            EXPECT_GT(fit.inlierShare, 0.95);
            EXPECT_GT(fit.coverage, 0.95);
            EXPECT_TRUE(fit.bothBends);
            EXPECT_LT(fit.sigmaRotation, 0.5e-3);
        }
    }
}

TEST(TrackGauge, IsRobustToAFewStraysOffTheLine) {
    const TrackGeometry track;
    const auto lane1 = TdoaSimulator::laps(track, track.laneOffset(1), 1.4, 1.0, 1.0, 1.0);
    auto walk = rotatedWalk(lane1, Vector3::Zero(), 0.006, 0.1, 9);
    for (std::size_t k = 0; k < walk.size(); k += 25) walk[k] += Vector3(3.0, -4.0, 0.0);  // 4 % strays of 5 m
    const TrackGaugeFit fit = fitTrackGauge(walk, Vector3::Zero(), track);
    ASSERT_TRUE(fit.valid);
    EXPECT_NEAR(fit.rotation, 0.006, 0.5e-3);
    EXPECT_LT(fit.rms, 0.2);
    EXPECT_LT(fit.inlierShare, 0.97);
}

TEST(TrackGauge, RandomWalkAndHalfLapAreNotTrackWalks) {
    const TrackGeometry track;
    std::vector<Vector3> points;
    for (const auto& s : randomWalk(300, 3)) points.push_back(s.position);
    const TrackGaugeFit random = fitTrackGauge(points, Vector3::Zero(), track);
    EXPECT_TRUE(!random.valid || random.rms > 0.5 || random.inlierShare < 0.8);

    const auto half = TdoaSimulator::laps(track, track.laneOffset(1), 1.4, 1.0, 0.45, 1.0);
    const TrackGaugeFit fit = fitTrackGauge(rotatedWalk(half, Vector3::Zero(), 0.0, 0.1, 2), Vector3::Zero(), track);
    ASSERT_TRUE(fit.valid);
    EXPECT_FALSE(fit.bothBends);
    EXPECT_LT(fit.coverage, 0.5);
}

TEST(LpsCalibrationGauge, TrackGaugeRemovesARotatedGuess) {
    // The guess is the survey rotated by 10 mrad about the reference node (plus σ 1 m errors): the
    // guess gauge keeps ≈ 10 mrad (0.7 m at 70 m), the track gauge removes it.
    const TrackGeometry track;
    TdoaSimulator sim(TdoaSimulator::Params(), 21);
    const BeaconLayout surveyed = sim.venue(VenueParams(), track);
    BeaconLayout guess = sim.perturb(surveyed, {1.0, 0.5});
    rotateLayout(guess, 0.010);
    const auto walk = sim.measure(TdoaSimulator::laps(track, track.laneOffset(3), 1.4, 1.0, 1.0, 1.0), surveyed);

    LpsCalibration::Params params;
    params.trackConstraint = false;  // the gauge alone: the track-constrained start is another solution
    params.gauge = LpsCalibration::Gauge::Guess;
    auto byGuess = LpsCalibration(params).run(walk.epochs, guess);
    params.gauge = LpsCalibration::Gauge::Auto;
    auto byTrack = LpsCalibration(params).run(walk.epochs, guess);
    ASSERT_TRUE(byGuess.ok() && byTrack.ok());
    EXPECT_EQ(byGuess->report.gauge.used, LpsCalibration::Gauge::Guess);
    ASSERT_EQ(byTrack->report.gauge.used, LpsCalibration::Gauge::Track) << byTrack->report.gauge.reason.toStdString();
    const double yawGuess = fitYawAboutPivot(byGuess->beacons.positions, surveyed.positions, surveyed.reference);
    const double yawTrack = fitYawAboutPivot(byTrack->beacons.positions, surveyed.positions, surveyed.reference);
    EXPECT_GT(std::abs(yawGuess), 0.005);
    EXPECT_LT(std::abs(yawTrack), 1e-3);
    EXPECT_NEAR(byTrack->report.gauge.fit.lateralOffset, track.laneOffset(3), 0.2);
    EXPECT_NEAR(byTrack->report.gauge.rotation, yawGuess,
                1e-3);  // the rotation that maps the guess gauge onto the truth
    EXPECT_NEAR(byTrack->report.nrmsrCalibrated, byGuess->report.nrmsrCalibrated, 1e-6);  // a pure gauge change
}

TEST(LpsCalibrationGauge, RandomWalkFallsBackToTheGuess) {
    const TrackGeometry track;
    TdoaSimulator sim(TdoaSimulator::Params(), 8);
    const BeaconLayout surveyed = sim.venue(VenueParams(), track);
    const BeaconLayout guess = sim.perturb(surveyed, {1.0, 0.5});
    const auto walk = sim.measure(randomWalk(400, 11), surveyed);
    auto result = LpsCalibration().run(walk.epochs, guess);
    ASSERT_TRUE(result.ok()) << result.message().toStdString();
    const auto& g = result->report.gauge;
    EXPECT_EQ(g.requested, LpsCalibration::Gauge::Auto);
    EXPECT_EQ(g.used, LpsCalibration::Gauge::Guess);
    EXPECT_EQ(g.rotation, 0.0);
    EXPECT_TRUE(g.reason.startsWith("auto: kept the guess-based rotation")) << g.reason.toStdString();

    // gauge=track forces the (meaningless) track rotation but says so.
    LpsCalibration::Params forced;
    forced.gauge = LpsCalibration::Gauge::Track;
    auto track2 = LpsCalibration(forced).run(walk.epochs, guess);
    ASSERT_TRUE(track2.ok());
    EXPECT_EQ(track2->report.gauge.used, LpsCalibration::Gauge::Track);
    EXPECT_TRUE(track2->report.gauge.reason.contains("forced")) << track2->report.gauge.reason.toStdString();
}

TEST(LpsCalibrationGauge, WrongTrackPoseFallsBack) {
    // The track placed 15° off in the LPS frame: the fit disagrees with the guess (or fits badly).
    TrackGeometry track;
    TdoaSimulator sim(TdoaSimulator::Params(), 4);
    const BeaconLayout surveyed = sim.venue(VenueParams(), track);
    const BeaconLayout guess = sim.perturb(surveyed, {1.0, 0.5});
    const auto walk = sim.measure(TdoaSimulator::laps(track, track.laneOffset(1), 1.4, 1.0, 1.0, 1.0), surveyed);
    LpsCalibration::Params params;
    params.track.setPose({0.0, 0.0, 0.26});
    auto result = LpsCalibration(params).run(walk.epochs, guess);
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(result->report.gauge.used, LpsCalibration::Gauge::Guess) << result->report.gauge.reason.toStdString();
}

// The judged flow through the processors (simulate-lps, lps-calibration, lps-positioning at
// tag_height 1.2) on several venues: calibrated RMSE ≤ surveyed RMSE + 0.10 m with the default
// gauge=auto. With gauge=guess at least one of these venues fails (venue 3: +0.2 m).
TEST(LpsCalibrationGauge, JudgedFlowPassesOnSeveralVenues) {
    const SimulateLpsProcessor simulate;
    const LpsCalibrationProcessor calibrate;
    const LpsPositioningProcessor positioning;
    int guessFailures = 0;
    for (const int venue : {1, 2, 3, 4, 5}) {
        QTemporaryDir dir;
        auto project = Project::create(dir.filePath("p.athlos"));
        ASSERT_TRUE(
            run(*project, simulate, {}, "walk/tdoa", {{"scenario", "walk"}, {"venue_seed", venue}, {"seed", 1}}));
        ASSERT_TRUE(run(*project, simulate, {}, "test/tdoa",
                        {{"scenario", "run"}, {"venue_seed", venue}, {"seed", 2}, {"lane", 3}}));
        ASSERT_TRUE(
            run(*project, positioning, {"test/tdoa", "test/tdoa-beacons"}, "test/ref", {{"tag_height", "1.2"}}));
        const double surveyed = rmse(*project->stream("test/ref"), *project->stream("test/tdoa-truth"));
        double calibrated[2] = {NAN, NAN};
        const char* gauges[2] = {"auto", "guess"};
        for (int k = 0; k < 2; ++k) {
            const QString out = QStringLiteral("walk/beacons-%1").arg(gauges[k]);
            Status s = run(*project, calibrate, {"walk/tdoa", "walk/tdoa-guess"}, out, {{"gauge", gauges[k]}});
            ASSERT_TRUE(s) << s.message().toStdString();
            const Table* report = project->table(out + "-report");
            ASSERT_NE(report, nullptr);
            EXPECT_EQ(report->attributes.value("gauge").toString(), k == 0 ? "track" : "guess")
                << "venue " << venue << ": " << report->attributes.value("gauge_reason").toString().toStdString();
            const QString fixes = QStringLiteral("test/cal-%1").arg(gauges[k]);
            ASSERT_TRUE(run(*project, positioning, {"test/tdoa", out}, fixes, {{"tag_height", "1.2"}}));
            calibrated[k] = rmse(*project->stream(fixes), *project->stream("test/tdoa-truth"));
        }
        std::printf("venue %d: surveyed %.3f m, gauge=auto %.3f m, gauge=guess %.3f m\n", venue, surveyed,
                    calibrated[0], calibrated[1]);
        EXPECT_LE(calibrated[0], surveyed + 0.10) << "venue " << venue;
        guessFailures += calibrated[1] > surveyed + 0.10;
    }
    EXPECT_GE(guessFailures, 1);  // the test is sensitive: the guess gauge alone fails here
}
