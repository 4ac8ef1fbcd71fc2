#pragma once
// The coach's session metrics of one period (distance, speed zones, high-speed running, sprints,
// accelerations, peak distances, metabolic power) from a trajectory sampled on a time grid. The
// definitions follow the electronic performance and tracking systems' conventions (Catapult,
// STATSports, Kinexon) and the open libraries (floodlight, kloppy), with every threshold a parameter:
//
//  - distance: Σ |p_k+1 − p_k| over consecutive valid samples; a step touching an invalid sample (an
//    outage longer than the gap limit) adds nothing;
//  - zone distances: each step counts in the zone of its mean speed (v_k + v_k+1) / 2, so the zones sum
//    to the distance; zone i is [edge_i, edge_i+1), the last is open;
//  - efforts (sprints, accelerations, decelerations): maximal runs of valid samples with the quantity at
//    or beyond its threshold, lasting at least the minimum duration. A run starts and ends at the
//    threshold crossings, interpolated linearly between the samples on either side, so its duration
//    does not depend on the sampling rate; at a period edge or an outage it starts or ends at the sample;
//  - maximum speed: the highest speed held for at least maxSpeedDuration (the largest v such that the
//    speed stays ≥ v over a window of that length), so that one noisy sample cannot set it;
//  - peak distance over w: the largest distance covered in any window of length w inside the period
//    (windows start at samples, the cumulative distance is interpolated at their ends);
//  - metabolic energy ∫ P dt (trapezoid) and mean power over the valid time (MetabolicPower.h).
#include "plugins/metrics/MetabolicPower.h"

#include <vector>

namespace athlos::metrics {

// A trajectory on a time grid (uniform or not). speed ≥ 0; accel is the forward acceleration d|v|/dt.
struct MotionSeries {
    std::vector<double> t;      // s, strictly increasing
    std::vector<double> x, y;   // m
    std::vector<double> speed;  // m/s
    std::vector<double> accel;  // m/s²
    std::vector<char> valid;    // 1 = observed (or inside a short outage), 0 = inside a long outage

    std::size_t size() const { return t.size(); }
    void resize(std::size_t n);
};

struct MetricsParams {
    // Lower edges of the speed zones (m/s): 0, 7, 14.4, 19.8, 25.2 km/h (the usual five bands of
    // Bradley et al. 2009 and the vendors' defaults).
    std::vector<double> zoneEdges{0.0, 7.0 / 3.6, 14.4 / 3.6, 19.8 / 3.6, 25.2 / 3.6};
    double hsrSpeed = 5.5;           // m/s, high-speed running (19.8 km/h; Bradley et al. 2009)
    double sprintSpeed = 7.0;        // m/s, sprint entry speed (25.2 km/h; Bradley et al. 2009)
    double sprintMinDuration = 1.0;  // s (Di Salvo et al. 2010: sprints of at least 1 s)
    double maxSpeedDuration = 0.5;   // s, max_speed is the highest speed held this long (0 = instantaneous)
    double accelThreshold = 3.0;     // m/s², acceleration / deceleration efforts (Akenhead et al. 2013)
    double accelMinDuration = 0.5;   // s (Varley et al. 2012, the vendors' default dwell time)
    std::vector<double> peakWindows{60.0, 180.0, 300.0};  // s
    double highPowerThreshold = 20.0;                     // W/kg, high metabolic power (Osgnach et al. 2010)
    MetabolicParams metabolic;
};

struct PeriodMetrics {
    double start = 0.0, end = 0.0, duration = 0.0;  // s
    double validDuration = 0.0;                     // s covered by valid steps
    double distance = 0.0;                          // m
    double maxSpeed = 0.0;                          // m/s
    std::vector<double> zoneDistance;               // m, one per zone
    double hsrDistance = 0.0;                       // m
    int sprintCount = 0, accelerationCount = 0, decelerationCount = 0;
    std::vector<double> peakDistance;  // m per MetricsParams::peakWindows; NaN if the period is shorter
    double metabolicEnergy = 0.0;      // J/kg
    double metabolicPowerMean = 0.0;   // W/kg over the valid time
    double highPowerDistance = 0.0;    // m covered above the high-power threshold
};

// The metrics of the samples with start ≤ t ≤ end.
PeriodMetrics computePeriod(const MotionSeries& series, double start, double end, const MetricsParams& params);

// Number of efforts: runs where sign·value ≥ sign·threshold (sign = +1 or −1) lasting at least
// minDuration, among the samples [first, last] (indices into series.t; valid flags respected).
int countEfforts(const MotionSeries& series, const std::vector<double>& value, std::size_t first, std::size_t last,
                 double threshold, double sign, double minDuration);

}  // namespace athlos::metrics
