#pragma once
// PlayerLoad (Catapult Sports; Boyd, Ball & Aughey 2011, "The reliability of MinimaxX accelerometers for
// measuring physical activity in Australian football", IJSPP 6:311–321):
//
//   PlayerLoad = Σ_k √((a_x,k+1 − a_x,k)² + (a_y,k+1 − a_y,k)² + (a_z,k+1 − a_z,k)²) / 100
//
// the accumulated rate of change of acceleration, accelerations in g (here converted from m/s² with
// g = 9.80665), in arbitrary units (AU). The formula is defined for Catapult's 100 Hz accelerometers: a
// sensor at another rate accumulates a different number of differences, so values are comparable only
// between recordings at the same rate (the processor records the rate).
#include <vector>

namespace athlos::metrics {

struct AccelerationSeries {
    std::vector<double> t;           // s
    std::vector<double> ax, ay, az;  // m/s², sensor frame (the formula is rotation invariant)
};

// PlayerLoad over the samples with start ≤ t ≤ end (differences between consecutive samples both in
// range; a step with a non-finite component is skipped).
double playerLoad(const AccelerationSeries& acc, double start, double end);

}  // namespace athlos::metrics
