#pragma once
// Runs GnssImuEkf over whole recordings: IMU samples drive the prediction, GNSS epochs are applied
// as soon as their time stamp is reached (same clock assumed). Output at the IMU rate, with
// horizontal speed and the distance covered.
#include "plugins/inertial/GnssImuEkf.h"

#include <functional>
#include <vector>

namespace athlos::inertial {

struct GnssSeries {
    std::vector<double> t;
    std::vector<Vec3> position;  // local ENU (m)
    std::vector<Vec3> velocity;  // ENU (m/s); empty = position only
};

struct FusedTrack {
    std::vector<Vec3> position, velocity;  // NaN before the first GNSS fix
    std::vector<Quat> orientation;
    std::vector<double> speed, distance;  // horizontal speed (m/s), path length (m)
    bool cancelled = false;
};

FusedTrack fuseGnssImu(const GnssImuEkf::Params& params, double ts, const std::vector<double>& imuT,
                       const ImuBatch& imu, const GnssSeries& gnss, const std::function<bool(double)>& keepGoing = {});

}  // namespace athlos::inertial
