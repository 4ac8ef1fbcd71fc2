#pragma once
// Lap and split times on a track (athletics, speed skating): the athlete's progress along the track's
// reference line (TrackGeometry::query, arc length s unwrapped over laps, either running direction),
// scaled so that a lap counts as the running line of lane 1 (400 m on the IAAF track), and the instants
// it passes each lap and each `splitDistance` mark after the first valid sample, interpolated linearly
// between samples. Only complete laps and splits are returned.
#include "core/geometry/TrackGeometry.h"
#include "plugins/metrics/SessionMetrics.h"

#include <QString>
#include <vector>

namespace athlos::metrics {

struct TrackInterval {
    QString name;  // "lap 1", "100 m #3"
    double start = 0.0, end = 0.0;
};

class TrackSplits {
public:
    struct Params {
        double splitDistance = 100.0;  // m of lane-1 running line
    };
    // Laps first, then splits.
    static std::vector<TrackInterval> compute(const MotionSeries& series, const TrackGeometry& track,
                                              const Params& params);
    // Progress (m of lane-1 running line) at every sample from the first valid one; NaN where invalid.
    static std::vector<double> progress(const MotionSeries& series, const TrackGeometry& track);
};

}  // namespace athlos::metrics
