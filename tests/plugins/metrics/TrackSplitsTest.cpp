// Lap and 100 m split times on the IAAF track from the progress along it: uniform progress (a lap in
// 50 s) gives laps of exactly 50 s and splits of 12.5 s, clockwise too, and outages are crossed.
#include "plugins/metrics/TrackSplits.h"

#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::metrics;

namespace {
MotionSeries onTrack(const TrackGeometry& track, double duration, double direction) {
    MotionSeries s;
    const std::size_t n = static_cast<std::size_t>(duration * 10) + 1;
    s.resize(n);
    const double length = track.referenceLength();
    for (std::size_t k = 0; k < n; ++k) {
        const double t = 0.1 * double(k);
        double arc = std::fmod(direction * length * t / 50.0 + 10.0 * length, length);  // a lap in 50 s
        const TrackPoint p = track.pointAt(arc, track.laneOffset(1));
        s.t[k] = t;
        s.x[k] = p.position.x();
        s.y[k] = p.position.y();
        s.speed[k] = 8.0;
    }
    return s;
}
}  // namespace

TEST(TrackSplits, LapsAndSplitsOfUniformProgress) {
    TrackGeometry track = TrackGeometry::iaaf400m();
    track.setPose({12.0, -5.0, 0.4});
    for (double direction : {1.0, -1.0}) {
        MotionSeries s = onTrack(track, 110.0, direction);
        const auto intervals = TrackSplits::compute(s, track, {});
        ASSERT_EQ(intervals.size(), 2u + 8u) << direction;
        EXPECT_EQ(intervals[0].name, QStringLiteral("lap 1"));
        EXPECT_NEAR(intervals[0].start, 0.0, 1e-9);
        EXPECT_NEAR(intervals[0].end, 50.0, 0.02);
        EXPECT_NEAR(intervals[1].end, 100.0, 0.02);
        EXPECT_EQ(intervals[2].name, QStringLiteral("100 m #1"));
        for (int i = 0; i < 8; ++i) EXPECT_NEAR(intervals[2 + i].end, 12.5 * (i + 1), 0.02) << i;
        // An outage of 3 s inside lap 2 is crossed: the lap still ends at 100 s.
        for (std::size_t k = 700; k < 730; ++k) s.valid[k] = 0;
        const auto gap = TrackSplits::compute(s, track, {});
        ASSERT_GE(gap.size(), 2u);
        EXPECT_NEAR(gap[1].end, 100.0, 0.02);
    }
}
