#pragma once
// GNSS-free gate positions from several runs on the same course (Fasel thesis ch. 10, step 4): each
// run's gate estimates (p + r_m of the ZUPT-only pass, in that run's own inertial frame) are aligned
// and scaled so that its first and last gates fall on the mean first and last gates of all runs
// (a similarity in the horizontal plane, a scale and shift in height), then averaged gate by gate.
// Drift that differs between runs partly cancels; drift common to all runs stays (the thesis found
// up to 1.5 m between subsequent gates with the runs of one day).
#include "core/util/Expected.h"
#include "plugins/positioning/GateRunSimulator.h"

#include <vector>

namespace athlos::positioning {

struct GateAveraging {
    // runs[r][m]: gate m as estimated in run r (all runs the same gates in the same order). Errors:
    // fewer than two gates, runs of different lengths, first and last gate at the same place.
    static Expected<std::vector<math::Vec3>> average(const std::vector<std::vector<math::Vec3>>& runs);
};

}  // namespace athlos::positioning
