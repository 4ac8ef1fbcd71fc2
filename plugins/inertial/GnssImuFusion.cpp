#include "plugins/inertial/GnssImuFusion.h"

#include <limits>

namespace athlos::inertial {

FusedTrack fuseGnssImu(const GnssImuEkf::Params& params, double ts, const std::vector<double>& imuT,
                       const ImuBatch& imu, const GnssSeries& gnss, const std::function<bool(double)>& keepGoing) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::size_t n = imu.rows;
    FusedTrack out;
    out.position.assign(n, Vec3::Constant(nan));
    out.velocity.assign(n, Vec3::Constant(nan));
    out.orientation.assign(n, Quat(nan, nan, nan, nan));
    out.speed.assign(n, nan);
    out.distance.assign(n, nan);
    GnssImuEkf ekf(ts, params);
    std::size_t g = 0;
    double distance = 0.0;
    const bool hasVel = gnss.velocity.size() == gnss.t.size() && !gnss.t.empty();
    for (std::size_t k = 0; k < n; ++k) {
        if (keepGoing && (k & 0xFFFF) == 0 && !keepGoing(static_cast<double>(k) / static_cast<double>(n))) {
            out.cancelled = true;
            return out;
        }
        const std::size_t o = k * imu.stride;
        ekf.predict(Vec3(imu.acc[o], imu.acc[o + 1], imu.acc[o + 2]), Vec3(imu.gyr[o], imu.gyr[o + 1], imu.gyr[o + 2]));
        while (g < gnss.t.size() && gnss.t[g] <= imuT[k] + 1e-9) {
            const Vec3& p = gnss.position[g];
            const bool velOk = hasVel && gnss.velocity[g].allFinite();
            if (p.allFinite()) ekf.updateGnss(p, velOk ? &gnss.velocity[g] : nullptr);
            ++g;
        }
        if (!ekf.isInitialised()) continue;
        out.position[k] = ekf.position();
        out.velocity[k] = ekf.velocity();
        out.orientation[k] = ekf.quaternion();
        out.speed[k] = ekf.velocity().head<2>().norm();
        if (k > 0 && std::isfinite(out.speed[k - 1]))
            distance += 0.5 * (out.speed[k] + out.speed[k - 1]) * (imuT[k] - imuT[k - 1]);
        out.distance[k] = distance;
    }
    return out;
}

}  // namespace athlos::inertial
