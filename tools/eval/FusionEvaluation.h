#pragma once
// Scores GNSS/IMU fusion on simulated data against the truth: horizontal position and speed errors of
// the fused track (IMU rate) and of the raw GNSS (at its epochs, and interpolated for the per-zone
// tables), and per 2 m zone of each 10 m sprint as in Tables 1–2 of seed 004.
#include "plugins/inertial/GnssImuEkf.h"
#include "plugins/inertial/ImuGnssSimulator.h"

#include <array>
#include <vector>

namespace athlos::inertial {

struct FusionMetrics {
    double fusedPositionRmse = 0, gnssPositionRmse = 0;  // m, horizontal
    double fusedSpeedRmse = 0, gnssSpeedRmse = 0;        // m/s, horizontal speed
    static constexpr int kZones = 5;                     // [0,2), [2,4), ... [8,10) m
    std::array<std::vector<double>, kZones> fusedZoneDistance, fusedZoneSpeed, gnssZoneDistance, gnssZoneSpeed;
};

// useVelocity = false fuses GNSS positions only.
FusionMetrics evaluateFusion(const SimulatedData& data, const GnssImuEkf::Params& params, bool useVelocity = true);

// Appends the errors of `more` to `all` (zone samples) and averages the RMS figures (call with
// count = number of sessions merged so far, including `more`).
void mergeFusionMetrics(FusionMetrics& all, const FusionMetrics& more, int count);

}  // namespace athlos::inertial
