// Calibration (§3.1): nRMSR definition (Eqn. 3.3), spread selection, Grubbs test, and recovery of
// beacons from σ = 1 m initial errors on simulated data (Kabsch-aligned beacon RMSE).
#include "plugins/lps/FrameAlignment.h"
#include "plugins/lps/LpsCalibration.h"
#include "plugins/lps/RobustStatistics.h"
#include "plugins/lps/TdoaPositioning.h"
#include "plugins/lps/TdoaSimulator.h"

#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::lps;

TEST(RobustStatistics, MedianMadAndQuantiles) {
    EXPECT_DOUBLE_EQ(math::median({3, 1, 2}), 2.0);
    EXPECT_DOUBLE_EQ(math::median({4, 1, 3, 2}), 2.5);
    EXPECT_DOUBLE_EQ(medianAbsoluteDeviation({1, 2, 3, 4, 100}), 1.0);
    EXPECT_NEAR(normalQuantile(0.975), 1.959964, 1e-5);
    EXPECT_NEAR(studentTQuantile(0.025, 20), 2.085963, 2e-3);
    EXPECT_NEAR(studentTQuantile(0.005, 100), 2.625891, 1e-3);
}

TEST(RobustStatistics, GrubbsFindsPlantedOutliersOnly) {
    std::vector<double> x;
    for (int i = 0; i < 200; ++i) x.push_back(0.1 * std::sin(i * 1.7));  // bounded, |x| ≤ 0.1
    x[17] = 3.0;
    x[120] = -2.5;
    const auto flags = grubbsOutliers(x, 0.05, 20);
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_EQ(flags[i], i == 17 || i == 120) << i;
}

TEST(LpsCalibration, NrmsrIsTheRootMeanOfPerFixMeanSquares) {
    // Two fixes with 4 beacons, noise-free except one reading: a perfect fix contributes 0, so
    // nRMSR = sqrt(rms_2² / 2) where rms_2 is the RMS residual of the disturbed fix on its own.
    TdoaSimulator::Params p;
    p.noiseSd = 0;
    p.outlierRate = 0;
    TdoaSimulator sim(p, 3);
    const TrackGeometry track;
    const BeaconLayout beacons = sim.venue(VenueParams(), track);
    auto rec = sim.measure({{0.0, Vector3(0, -36, 1.2), 0.0}, {1.0, Vector3(20, 36, 1.2), 0.0}}, beacons);
    EXPECT_NEAR(LpsCalibration::nrmsr(rec.epochs, beacons, 1.2), 0.0, 1e-6);
    rec.epochs[1].readings[2].dt += 1.0 / kSpeedOfLight;
    const double second = LpsCalibration::nrmsr({rec.epochs[1]}, beacons, 1.2);
    EXPECT_GT(second, 0.05);
    EXPECT_NEAR(LpsCalibration::nrmsr(rec.epochs, beacons, 1.2), std::sqrt(second * second / 2.0), 1e-9);
}

TEST(LpsCalibration, SpreadSelectionCoversTheArea) {
    std::vector<Vector3> points;
    for (int i = 0; i < 100; ++i) points.emplace_back(i < 90 ? 0.01 * i : 50.0 + i, 0, 0);  // a cluster and a tail
    const auto chosen = LpsCalibration::spreadSelection(points, 10);
    ASSERT_EQ(chosen.size(), 10u);
    int inTail = 0;
    for (int i : chosen) inTail += i >= 90;
    EXPECT_GE(inTail, 8);  // farthest-point sampling prefers the sparse tail over the dense cluster
    EXPECT_TRUE(std::is_sorted(chosen.begin(), chosen.end()));
    EXPECT_EQ(LpsCalibration::spreadSelection(points, 0).size(), 100u);
}

TEST(LpsCalibration, RecoversBeaconsFromOneMetreGuessErrors) {
    const TrackGeometry track;
    TdoaSimulator sim(TdoaSimulator::Params(), 42);  // thesis noise and 1 % outliers
    const BeaconLayout surveyed = sim.venue(VenueParams(), track);
    const BeaconLayout guess = sim.perturb(surveyed, {1.0, 0.5});
    const auto walk = sim.measure(TdoaSimulator::laps(track, 0.3, 1.4, 1.0, 1.0, 1.0), surveyed);

    LpsCalibration::Params params;
    params.walkHeight = 1.0;  // known here: isolates the beacon recovery from the weak z observability
    auto result = LpsCalibration(params).run(walk.epochs, guess, {}, &surveyed);
    ASSERT_TRUE(result.ok()) << result.message().toStdString();
    const auto& report = result->report;
    EXPECT_GT(report.nrmsrInitial, 3.0 * report.nrmsrCalibrated);
    EXPECT_LT(report.etaCalibrated(), 1.02);
    EXPECT_GT(report.readingsRemoved, 0);  // the 1 % outliers were found

    // Horizontal positions after Kabsch alignment: within centimetres (z is weakly observable from a
    // planar walk and is checked loosely).
    auto transform = fitRigid(result->beacons.positions, surveyed.positions, AlignMode::Full);
    ASSERT_TRUE(transform.ok());
    double sumXy = 0.0, sumZ = 0.0;
    for (int i = 0; i < surveyed.size(); ++i) {
        const Vector3 d = transform->apply(result->beacons.positions[size_t(i)]) - surveyed.positions[size_t(i)];
        sumXy += d.head<2>().squaredNorm();
        sumZ += d.z() * d.z();
    }
    EXPECT_LT(std::sqrt(sumXy / surveyed.size()), 0.10);
    EXPECT_LT(std::sqrt(sumZ / surveyed.size()), 1.0);
    const double guessRmse = alignedRmse(guess.positions, surveyed.positions);
    EXPECT_LT(alignedRmse(result->beacons.positions, surveyed.positions), guessRmse);
}

TEST(LpsCalibration, IsDeterministic) {
    const TrackGeometry track;
    TdoaSimulator sim(TdoaSimulator::Params(), 7);
    const BeaconLayout surveyed = sim.venue(VenueParams(), track);
    const BeaconLayout guess = sim.perturb(surveyed, {1.0, 0.5});
    const auto walk = sim.measure(TdoaSimulator::laps(track, 0.3, 1.4, 1.0, 1.0, 1.0), surveyed);
    auto a = LpsCalibration().run(walk.epochs, guess);
    auto b = LpsCalibration().run(walk.epochs, guess);
    ASSERT_TRUE(a.ok() && b.ok());
    for (int i = 0; i < guess.size(); ++i) EXPECT_EQ(a->beacons.positions[size_t(i)], b->beacons.positions[size_t(i)]);
}

TEST(LpsCalibration, RefusesAWalkThatIsTooShort) {
    const TrackGeometry track;
    TdoaSimulator sim(TdoaSimulator::Params(), 1);
    const BeaconLayout surveyed = sim.venue(VenueParams(), track);
    const auto walk = sim.measure(TdoaSimulator::laps(track, 0.3, 1.4, 1.0, 0.02, 1.0), surveyed);
    auto result = LpsCalibration().run(walk.epochs, surveyed);
    ASSERT_FALSE(result.ok());
    EXPECT_TRUE(result.message().contains("at least 20"));
}

// Rough guesses (issue #16 item 5, docs/validation/lps.md): from σ 10/10/5 m and 20/20/10 m guesses
// the calibrated beacons position a test lap within +0.10 m of the surveyed beacons' RMSE, with the
// default parameters (the guess quality is not stated: the prior is widened by adaptPrior, the
// heights kept above the walk, the track-constrained start chosen by its fit to the track). Before
// these remedies 0 of these 6 runs passed at 20/10 (+0.3 m typical). Seeds disjoint from the eval's.
TEST(LpsCalibration, CalibratesFromRoughGuesses) {
    const TrackGeometry track = TrackGeometry::iaaf400m();
    auto rmse = [](const std::vector<TagFix>& fixes, const std::vector<TrajectorySample>& truth) {
        double sum = 0.0;
        int n = 0;
        for (std::size_t k = 0; k < fixes.size(); ++k)
            if (fixes[k].valid) {
                sum += (fixes[k].position - truth[k].position).head<2>().squaredNorm();
                ++n;
            }
        return n ? std::sqrt(sum / n) : 1e9;
    };
    auto position = [](const std::vector<TdoaEpoch>& epochs, const BeaconLayout& beacons) {
        TdoaPositioning::Params p;
        p.solver.tagHeight = 1.2;
        return *TdoaPositioning(p, beacons).run(epochs);
    };
    for (const Perturbation level : {Perturbation{10.0, 5.0}, Perturbation{20.0, 10.0}}) {
        for (const std::uint64_t seed : {424201u, 424202u, 424203u}) {
            TdoaSimulator sim(TdoaSimulator::Params(), seed);
            const BeaconLayout surveyed = sim.venue(VenueParams(), track);
            const BeaconLayout guess = sim.perturb(surveyed, level);
            const auto walk = sim.measure(TdoaSimulator::laps(track, 0.3, 1.4, 1.0, 1.0, 1.0), surveyed);
            const auto test =
                sim.measure(TdoaSimulator::laps(track, track.laneOffset(3), 6.0, 10.0, 1.0, 1.2, 1e3), surveyed);
            auto result = LpsCalibration().run(walk.epochs, guess);
            ASSERT_TRUE(result.ok()) << result.message().toStdString();
            const double reference = rmse(position(test.epochs, surveyed), test.truth);
            const double calibrated = rmse(position(test.epochs, result->beacons), test.truth);
            std::printf("σ %g/%g seed %llu: surveyed %.3f m, calibrated %.3f m, prior %.1f m, track %d, gauge %s\n",
                        level.sigmaXy, level.sigmaZ, static_cast<unsigned long long>(seed), reference, calibrated,
                        result->report.priorSigmaXy, int(result->report.trackConstrained),
                        LpsCalibration::gaugeName(result->report.gauge.used));
            EXPECT_LE(calibrated, reference + 0.10) << "σ " << level.sigmaXy << " seed " << seed;
            EXPECT_TRUE(result->report.poorGuess);
        }
    }
}
