#pragma once
// Alpine turn switches from a trunk or sacrum IMU (Fasel 2017 ch. 2 and 11; spec §8): the angular
// velocity about the trunk's longitudinal axis changes sign at each turn switch; positive (counter-
// clockwise seen from above) is a left turn. The axis is the sensor axis closest to the mean
// accelerometer direction (up over a run at roughly constant speed) unless given. Projecting on the
// true vertical instead would mix in the lean rate about the forward axis, which on a 26° slope has
// a vertical component and moves the zero crossings by ~0.4 s (seen on the simulator). The rate is smoothed over `smoothing` (centred moving
// average, twice) and a turn counts once it exceeds `threshold`, so noise around zero between turns
// does not add switches; the switch is the last zero crossing before that.
#include <Eigen/Core>
#include <vector>

namespace athlos::events {

struct Turn {
    double start = 0, end = 0;  // s, turn switch to turn switch
    bool left = false;
    double peakRate = 0;  // rad/s, largest |yaw rate| in the turn
};

struct TurnSwitchParams {
    double smoothing = 0.3;                          // s
    double threshold = 0.3;                          // rad/s
    double minTurn = 0.4;                            // s
    double maxTurn = 6.0;                            // s: longer intervals are not turns (straight running, stops)
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();  // sensor frame, up; zero: automatic
};

// The sensor axis (±x, ±y, ±z) nearest the mean of acc; zero when acc averages to zero.
Eigen::Vector3d longitudinalAxis(const std::vector<double>& acc);

// gyr and acc row-major x, y, z per sample.
std::vector<Turn> detectTurns(const std::vector<double>& t, const std::vector<double>& gyr,
                              const std::vector<double>& acc, const TurnSwitchParams& params,
                              std::vector<double>* yawRate = nullptr);

}  // namespace athlos::events
