#pragma once
// Bridging long outages along the track (augmented model with RTS smoothing).
//
// Why: a forward filter that coasts through a long outage during the start acceleration (speed
// unknown, 10 s or more unseen) ends the gap tens of metres behind along the bend; the RTS pass
// corrects it only linearly in x/y around that wrong trajectory, which cannot move an estimate
// 50 m along an arc (seen on held-out runs: 47 m RMS inside such a gap, 0.03 m outside). Between
// two smoothed states that ARE observed (the last accepted fix before the gap and the first after
// it) the runner follows the track, so the gap is interpolated in track coordinates instead:
//   s(t): cubic Hermite in arc length matching both end speeds (ds/dt = v / stretch, where stretch
//         = path length per unit of s on the running line at offset d, (r + d)/r on oval bends),
//         made monotone (Fritsch–Carlson) so the runner never goes backwards; whole laps are added
//         to the along-track distance so that the mean speed matches the end speeds best;
//   d(t): linear between the end offsets (a lane change inside the gap).
// Speed, acceleration, heading and turn rate of the bridged samples follow from s(t) and the track.
#include "plugins/positioning/PositionFilter.h"
#include "plugins/positioning/TrackModels.h"

namespace athlos::positioning {

class TrackGapBridge {
public:
    struct Params {
        double minGap = 2.0;  // s between accepted fixes from which a gap is bridged
    };

    TrackGapBridge(TrackConstraintParams constraint, Params params);

    // Replaces the output samples strictly inside every gap of at least minGap between accepted
    // (non-outlier) input samples whose both ends lie on the track. Returns the number of gaps bridged.
    int apply(const PositionSamples& in, PositionFilterResult& result) const;

private:
    bool bridge(PositionFilterResult& result, std::size_t a, std::size_t b) const;
    double stretch(double s, double d) const;  // path length per unit of s at offset d

    TrackConstraintField field_;
    Params params_;
};

}  // namespace athlos::positioning
