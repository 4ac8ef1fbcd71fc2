// TrackGapBridge: outages bridged along the track, checked against runners whose truth is the track
// geometry itself (pointAt): constant speed in a lane (to cm), more than a lap unseen (whole laps
// chosen by speed), running the wrong way round, an acceleration through the gap (bounded error),
// and the cases it must leave alone (short gaps, ends off the track, the filter's own samples).
#include "core/math/Angles.h"
#include "plugins/positioning/TrackGapBridge.h"

#include <gtest/gtest.h>
#include <cmath>
#include <functional>
#include <numbers>

using namespace athlos;
using namespace athlos::positioning;

namespace {

std::shared_ptr<const TrackGeometry> rotatedOval() {
    auto t = std::make_shared<TrackGeometry>(TrackGeometry::iaaf400m());
    t->setPose({5.0, -3.0, 0.6});
    return t;
}

struct Scenario {
    PositionSamples in;
    PositionFilterResult result;  // truth outside the gap, a frozen (lost) filter inside it
    std::vector<Kinematics> truth;
};

// A runner at arc length s(t) (reference line) and offset d, sampled at 10 Hz over [0, duration];
// no fixes in (gapBegin, gapEnd).
Scenario scenario(const TrackGeometry& track, double duration, double gapBegin, double gapEnd, double d,
                  const std::function<double(double)>& s, double sign = 1.0) {
    Scenario sc;
    for (int k = 0; k <= int(std::lround(duration * 10)); ++k) {
        const double t = 0.1 * k, h = 1e-4;
        const TrackPoint p = track.pointAt(s(t), d);
        const double speed =
            (track.pointAt(s(t + h), d).position - track.pointAt(s(t - h), d).position).norm() / (2 * h);
        Kinematics truth{p.position.x(),
                         p.position.y(),
                         speed,
                         sign > 0 ? p.heading : math::wrapAngle(p.heading + std::numbers::pi),
                         sign * speed * p.curvature,
                         0.0};
        sc.truth.push_back(truth);
        sc.result.t.push_back(t);
        const bool inGap = t > gapBegin + 1e-9 && t < gapEnd - 1e-9;
        sc.result.states.push_back(inGap ? sc.result.states.back() : truth);
        if (!inGap) {
            sc.in.t.push_back(t);
            sc.in.p.push_back(p.position);
            sc.result.outlier.push_back(0);
        }
    }
    return sc;
}

double gapError(const Scenario& sc, double gapBegin, double gapEnd) {
    double worst = 0.0;
    for (std::size_t k = 0; k < sc.result.t.size(); ++k) {
        if (sc.result.t[k] <= gapBegin || sc.result.t[k] >= gapEnd) continue;
        worst =
            std::max(worst, std::hypot(sc.result.states[k].x - sc.truth[k].x, sc.result.states[k].y - sc.truth[k].y));
    }
    return worst;
}

TrackGapBridge bridgeFor(std::shared_ptr<const TrackGeometry> track, double minGap = 2.0) {
    TrackConstraintParams c;
    c.track = std::move(track);
    return TrackGapBridge(c, {minGap});
}

}  // namespace

TEST(TrackGapBridge, ConstantSpeedInALaneIsReproducedToCentimetres) {
    const auto track = rotatedOval();
    const double d = track->laneOffset(3);
    // 12 s unseen from the back straight into and through bend 2, 7 m/s on the lane-3 running line.
    const double s0 = 150.0, v = 7.0;
    auto sc = scenario(*track, 30.0, 8.0, 20.0, d, [&](double t) {
        // Constant path speed: ds/dt = v / stretch; integrate numerically on the running line.
        double s = s0;
        for (double u = 0.0; u < t; u += 1e-3) {
            const double h = 1e-4;
            const double g = (track->pointAt(s + h, d).position - track->pointAt(s - h, d).position).norm() / (2 * h);
            s += std::min(1e-3, t - u) * v / g;
        }
        return s;
    });
    EXPECT_GT(gapError(sc, 8.0, 20.0), 30.0);  // the frozen filter
    EXPECT_EQ(bridgeFor(track).apply(sc.in, sc.result), 1);
    // Not exactly cubic where the running line passes a straight/bend joint (stretch jumps): cm.
    EXPECT_LT(gapError(sc, 8.0, 20.0), 0.05);
    for (std::size_t k = 0; k < sc.result.t.size(); ++k) {
        if (sc.result.t[k] <= 8.0 || sc.result.t[k] >= 20.0) continue;
        EXPECT_NEAR(sc.result.states[k].speed, v, 0.05);
        EXPECT_LT(std::abs(math::wrapAngle(sc.result.states[k].heading - sc.truth[k].heading)), 2e-3);
        EXPECT_NEAR(sc.result.states[k].turnRate, sc.truth[k].turnRate, 0.01);
    }
}

TEST(TrackGapBridge, MoreThanALapUnseenAndRunningTheWrongWay) {
    const auto track = rotatedOval();
    const double d = track->laneOffset(1);
    // 65 s unseen at 7.5 m/s of reference arc: 487 m, more than a lap; the laps come from the speed.
    auto laps = scenario(*track, 80.0, 5.0, 70.0, d, [](double t) { return 30.0 + 7.5 * t; });
    EXPECT_EQ(bridgeFor(track).apply(laps.in, laps.result), 1);
    EXPECT_LT(gapError(laps, 5.0, 70.0), 0.5);
    // Clockwise (heading against the track): s decreases.
    auto reverse = scenario(
        *track, 30.0, 6.0, 18.0, d, [](double t) { return 300.0 - 6.5 * t; }, -1.0);
    EXPECT_EQ(bridgeFor(track).apply(reverse.in, reverse.result), 1);
    EXPECT_LT(gapError(reverse, 6.0, 18.0), 0.5);
    for (std::size_t k = 0; k < reverse.result.t.size(); ++k)
        if (reverse.result.t[k] > 6.0 && reverse.result.t[k] < 18.0) {
            EXPECT_LT(std::abs(math::wrapAngle(reverse.result.states[k].heading - reverse.truth[k].heading)), 1e-2);
        }
}

TEST(TrackGapBridge, AccelerationThroughTheGapStaysOnTheRunningLine) {
    const auto track = rotatedOval();
    const double d = track->laneOffset(2);
    // Start acceleration (τ = 1.3 s to 7 m/s) unseen from 1 s to 13 s: the case that motivated the bridge.
    auto sc = scenario(*track, 25.0, 1.0, 13.0, d, [](double t) {
        constexpr double tau = 1.3, top = 7.0;
        return 20.0 + top * (t - tau * (1.0 - std::exp(-t / tau)));
    });
    EXPECT_EQ(bridgeFor(track).apply(sc.in, sc.result), 1);
    EXPECT_LT(gapError(sc, 1.0, 13.0), 5.0);  // a cubic cannot follow the knee; the frozen filter is 70 m off
    for (std::size_t k = 0; k < sc.result.t.size(); ++k) {
        const auto& K = sc.result.states[k];
        EXPECT_NEAR(track->query({K.x, K.y}).d, d, 1e-6);  // on the lane-2 running line throughout
        EXPECT_GE(K.speed, 0.0);                           // monotone: never backwards
    }
}

TEST(TrackGapBridge, LeavesShortGapsAndOffTrackEndsAlone) {
    const auto track = rotatedOval();
    auto shortGap = scenario(*track, 10.0, 3.0, 4.5, track->laneOffset(1), [](double t) { return 7.0 * t; });
    const auto before = shortGap.result.states;
    EXPECT_EQ(bridgeFor(track).apply(shortGap.in, shortGap.result), 0);
    for (std::size_t k = 0; k < before.size(); ++k) EXPECT_EQ(shortGap.result.states[k].x, before[k].x);
    // A warm-up in the infield (25 m inside the kerb): not on the track, nothing to bridge.
    auto infield = scenario(*track, 20.0, 5.0, 15.0, -25.0, [](double t) { return 100.0 + 2.0 * t; });
    EXPECT_EQ(bridgeFor(track).apply(infield.in, infield.result), 0);
    // Samples the filter flagged as outliers inside the window count as unseen.
    auto flagged = scenario(*track, 20.0, 5.0, 5.05, track->laneOffset(1), [](double t) { return 7.0 * t; });
    for (std::size_t i = 0; i < flagged.in.t.size(); ++i)
        if (flagged.in.t[i] > 5.0 && flagged.in.t[i] < 12.0) {
            flagged.result.outlier[i] = 1;
            flagged.result.states[i] = flagged.result.states[i - 1];
        }
    EXPECT_EQ(bridgeFor(track).apply(flagged.in, flagged.result), 1);
    EXPECT_LT(gapError(flagged, 5.0, 12.0), 0.05);
}
