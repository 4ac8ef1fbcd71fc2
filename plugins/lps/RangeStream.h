#pragma once
// The two-way-ranging stream (kind "lps-range", stored wide: one "range_<id>" column per anchor, m,
// see core/io/TdoaLayout.h) as a time-ordered list of single ranges against a beacon table. Anchors
// report at their own instants, so a row usually holds one range; nothing is merged here.
#include "core/model/Stream.h"
#include "core/util/Expected.h"
#include "plugins/lps/Tdoa.h"

#include <vector>

namespace athlos::lps {

struct RangeReading {
    double t = 0.0;      // s
    int beacon = 0;      // index into the BeaconLayout
    double range = 0.0;  // m
};

struct RangeSet {
    std::vector<RangeReading> readings;  // non-decreasing t
    long long readingsSkipped = 0;       // non-finite or negative ranges
};

// Errors name the stream path: not an lps-range stream, or ids the beacon table does not have (all listed).
Expected<RangeSet> rangesFromStream(const Stream& stream, const StreamData& data, const BeaconLayout& layout,
                                    const QString& path);

}  // namespace athlos::lps

namespace athlos::lps {

// Per-instant solving needs every anchor's range at one instant, but anchors report at their own
// times: an epoch every `step` seconds holds each beacon's newest range not older than `maxAge`
// (readings are never extrapolated; a beacon without a fresh range is left out of the epoch).
// Epochs with fewer than `minBeacons` ranges are dropped. TdoaEpoch::readings[].dt holds the range (m).
std::vector<TdoaEpoch> mergeRangeEpochs(const std::vector<RangeReading>& readings, int beacons, double step,
                                        double maxAge, int minBeacons);

}  // namespace athlos::lps
