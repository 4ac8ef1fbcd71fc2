// wrist-cadence: a worked example (a synthetic norm with known stride frequency and only even
// harmonics, where the tracker must keep the stride), the thesis criterion on simulated walkers
// (median cadence error ≤ 1 %), walking detection, and the processor through the runner.
#include "plugins/events/WristCadence.h"
#include "plugins/events/WristCadenceProcessor.h"
#include "plugins/events/SimulateWristWalkProcessor.h"
#include "tools/eval/WristEvaluation.h"

#include "core/processing/ProcessorRunner.h"

#include <QTemporaryDir>
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <numbers>
#include <random>

using namespace athlos;
using namespace athlos::events;

namespace {

// A 3-axis "acceleration" whose norm is g plus five harmonics of the stride frequency f (Hz).
// A little white noise (as every sensor has) gives the spectrum a floor.
std::vector<double> syntheticAcc(const std::vector<double>& t, double f, double fundamental, double second) {
    std::vector<double> acc(3 * t.size());
    std::mt19937 rng(3);
    std::normal_distribution<double> noise(0.0, 0.05);
    for (std::size_t k = 0; k < t.size(); ++k) {
        const double w = 2.0 * std::numbers::pi * f * t[k];
        acc[3 * k + 2] = 9.81 + fundamental * std::sin(w) + second * std::sin(2.0 * w + 0.3) + 0.5 * std::sin(3.0 * w) +
                         0.6 * std::sin(4.0 * w + 1.0) + 0.3 * std::sin(5.0 * w) + noise(rng);
    }
    return acc;
}

}  // namespace

TEST(WristCadence, CombFindsTheStrideFrequencyOfAHarmonicSignal) {
    std::vector<double> t(100 * 60);
    for (std::size_t k = 0; k < t.size(); ++k) t[k] = 0.01 * double(k);
    for (double f : {0.75, 0.9, 1.05}) {  // 90, 108, 126 steps/min
        const auto acc = syntheticAcc(t, f, 0.8, 2.0);
        const auto windows = WristCadence().estimate(t.data(), acc.data(), t.size(), 3);
        ASSERT_GT(windows.size(), 40u);
        std::vector<double> cadences;
        for (const auto& w : windows) {
            ASSERT_TRUE(w.walking) << f;
            // One window resolves the stride to ~0.02 Hz (6 s, Hann): within 3 %, the thesis's IQR.
            EXPECT_NEAR(w.cadence, 120.0 * f, 0.03 * 120.0 * f) << "stride " << f << " Hz at " << w.tStart;
            cadences.push_back(w.cadence);
        }
        std::nth_element(cadences.begin(), cadences.begin() + long(cadences.size() / 2), cadences.end());
        EXPECT_NEAR(cadences[cadences.size() / 2], 120.0 * f, 0.01 * 120.0 * f) << f;
    }
    // The comb's half harmonics reject twice the stride frequency: CL at f beats CL at 2f.
    std::vector<double> window(120);
    for (std::size_t i = 0; i < window.size(); ++i) {
        const double w = 2.0 * std::numbers::pi * 0.8 * double(i) / 20.0;
        window[i] =
            9.81 + 0.8 * std::sin(w) + 2.0 * std::sin(2.0 * w) + 0.3 * std::sin(3.0 * w) + 0.05 * std::sin(7.7 * w * w);
    }
    const auto cl = WristCadence().likelihood(window.data(), window.size());
    EXPECT_GT(cl[40], cl[120]);  // f = 0.80 Hz vs 1.60 Hz
}

TEST(WristCadence, MedianErrorWithinOnePercentOnSimulatedWalkers) {
    CadenceScore score;
    for (unsigned seed : {31u, 32u, 33u, 34u}) {
        WristWalkParams base;
        base.duration = 400.0;
        scoreCadence(simulateWristTrial({seed, 1.6 + 0.08 * (seed - 30)}, base), score);
    }
    const ErrorSummary s = summarize(score.errors);
    ASSERT_GT(s.n, 600u);
    EXPECT_LE(std::abs(s.median), 1.0) << s.median;  // judged: thesis −0.13 %
    EXPECT_LE(s.medianAbs, 1.5) << s.medianAbs;
    EXPECT_LT(s.q75 - s.q25, 3.0);  // thesis IQR 3.8 %
    // Walking detected in most walking windows; pauses mostly rejected.
    EXPECT_GT(score.walkingDetected, 8 * score.walkingMissed);
    EXPECT_GT(score.pauseRejected, 3 * score.pauseAsWalking);
}

TEST(WristCadence, ProcessorRunsOnTheSimulatorAndRefusesBadInput) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    SimulateWristWalkProcessor sim;
    auto simulated = runProcessor(*project, sim,
                                  RunRequest{sim.id(),
                                             {},
                                             QStringLiteral("walk/wrist"),
                                             {{QStringLiteral("duration"), 120.0}, {QStringLiteral("seed"), 5}}});
    ASSERT_TRUE(simulated.ok()) << qPrintable(simulated.message());
    ASSERT_NE(project->stream(QStringLiteral("walk/wrist-barometer")), nullptr);
    EXPECT_EQ(project->stream(QStringLiteral("walk/wrist-barometer"))->kind(), QStringLiteral("barometer"));
    const Stream* truth = project->stream(QStringLiteral("walk/wrist-truth"));
    ASSERT_NE(truth, nullptr);

    WristCadenceProcessor cadence;
    auto run =
        runProcessor(*project, cadence,
                     RunRequest{cadence.id(), {QStringLiteral("walk/wrist")}, QStringLiteral("walk/cadence"), {}});
    ASSERT_TRUE(run.ok()) << qPrintable(run.message());
    const Stream* out = project->stream(QStringLiteral("walk/cadence"));
    ASSERT_NE(out, nullptr);
    EXPECT_EQ(out->kind(), QStringLiteral("wrist-cadence"));
    const StreamData& d = **out->data();
    const StreamData& tr = **truth->data();
    // Walking windows agree with the truth at their centre within 3 % (9 in 10: a window at gait
    // termination may still take the step frequency for the stride frequency).
    int checked = 0, close = 0;
    for (std::size_t k = 0; k < d.rows(); ++k) {
        if (d.at(k, 1) < 0.5) continue;
        const auto i = std::size_t(std::lround(d.t[k] * 10.0));
        if (i >= tr.rows() || tr.at(i, 4) < 0.5) continue;
        close += std::abs(d.at(k, 0) - tr.at(i, 0)) <= 0.03 * tr.at(i, 0) ? 1 : 0;
        ++checked;
    }
    EXPECT_GT(checked, 40);
    EXPECT_GE(close, 0.9 * checked) << close << " of " << checked;

    // Standing still: refused with the reason, nothing stored.
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.columns = {{"acc_x", "m/s^2"}, {"acc_y", "m/s^2"}, {"acc_z", "m/s^2"}};
    StreamData still(2000, 3);
    for (std::size_t k = 0; k < still.rows(); ++k) {
        still.t[k] = 0.01 * double(k);
        still.at(k, 2) = 9.81;
    }
    project->putStream(QStringLiteral("walk/still"), Stream(info, still));
    auto none = runProcessor(*project, cadence,
                             RunRequest{cadence.id(), {QStringLiteral("walk/still")}, QStringLiteral("walk/c2"), {}});
    ASSERT_FALSE(none.ok());
    EXPECT_TRUE(none.message().contains(QStringLiteral("no walking"))) << qPrintable(none.message());
    EXPECT_EQ(project->stream(QStringLiteral("walk/c2")), nullptr);
    // Accelerations in g are refused, naming the column.
    info.columns = {{"acc_x", "g"}, {"acc_y", "g"}, {"acc_z", "g"}};
    project->putStream(QStringLiteral("walk/ing"), Stream(info, still));
    auto units = runProcessor(*project, cadence,
                              RunRequest{cadence.id(), {QStringLiteral("walk/ing")}, QStringLiteral("walk/c3"), {}});
    ASSERT_FALSE(units.ok());
    EXPECT_TRUE(units.message().contains(QStringLiteral("acc_x"))) << qPrintable(units.message());
}
