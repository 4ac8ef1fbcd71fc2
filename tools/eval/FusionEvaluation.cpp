#include "tools/eval/FusionEvaluation.h"

#include "plugins/inertial/GnssImuFusion.h"

#include <cmath>

namespace athlos::inertial {

FusionMetrics evaluateFusion(const SimulatedData& d, const GnssImuEkf::Params& params, bool useVelocity) {
    const std::size_t n = d.imuT.size();
    std::vector<double> rows(n * 9);
    for (std::size_t k = 0; k < n; ++k) {
        for (int i = 0; i < 3; ++i) {
            rows[k * 9 + i] = d.acc[k][i];
            rows[k * 9 + 3 + i] = d.gyr[k][i];
            rows[k * 9 + 6 + i] = d.mag[k][i];
        }
    }
    const ImuBatch imu{rows.data() + 3, rows.data(), rows.data() + 6, n, 9};
    const GnssSeries gnss{d.gnssT, d.gnssPosition, useVelocity ? d.gnssVelocity : std::vector<Vec3>()};
    const double ts = d.imuT[1] - d.imuT[0];
    const FusedTrack fused = fuseGnssImu(params, ts, d.imuT, imu, gnss);

    FusionMetrics m;
    double sp = 0, ss = 0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < n; ++k) {
        if (!fused.position[k].allFinite()) continue;
        sp += (fused.position[k] - d.position[k]).head<2>().squaredNorm();
        ss += std::pow(fused.speed[k] - d.velocity[k].head<2>().norm(), 2);
        ++count;
    }
    m.fusedPositionRmse = std::sqrt(sp / static_cast<double>(count));
    m.fusedSpeedRmse = std::sqrt(ss / static_cast<double>(count));
    // Raw GNSS at its epochs (the truth at the same instants).
    const double step = d.gnssT.size() > 1 ? d.gnssT[1] - d.gnssT[0] : 0.1;
    sp = ss = 0;
    for (std::size_t g = 0; g < d.gnssT.size(); ++g) {
        const auto k = static_cast<std::size_t>(std::llround(d.gnssT[g] / ts));
        sp += (d.gnssPosition[g] - d.position[k]).head<2>().squaredNorm();
        ss += std::pow(d.gnssVelocity[g].head<2>().norm() - d.velocity[k].head<2>().norm(), 2);
    }
    m.gnssPositionRmse = std::sqrt(sp / static_cast<double>(d.gnssT.size()));
    m.gnssSpeedRmse = std::sqrt(ss / static_cast<double>(d.gnssT.size()));
    // Per-zone errors inside the 10 m sprints; GNSS interpolated linearly to the IMU times.
    for (std::size_t k = 0; k < n; ++k) {
        if (d.sprint[k] < 0 || !fused.position[k].allFinite()) continue;
        const int zone = std::min(FusionMetrics::kZones - 1, static_cast<int>(d.sprintDistance[k] / 2.0));
        const double trueSpeed = d.velocity[k].head<2>().norm();
        m.fusedZoneDistance[zone].push_back((fused.position[k] - d.position[k]).head<2>().norm());
        m.fusedZoneSpeed[zone].push_back(std::abs(fused.speed[k] - trueSpeed));
        const double f = d.imuT[k] / step;
        const auto g0 = std::min(static_cast<std::size_t>(f), d.gnssT.size() - 2);
        const double a = f - static_cast<double>(g0);
        const Vec3 gp = (1 - a) * d.gnssPosition[g0] + a * d.gnssPosition[g0 + 1];
        const Vec3 gv = (1 - a) * d.gnssVelocity[g0] + a * d.gnssVelocity[g0 + 1];
        m.gnssZoneDistance[zone].push_back((gp - d.position[k]).head<2>().norm());
        m.gnssZoneSpeed[zone].push_back(std::abs(gv.head<2>().norm() - trueSpeed));
    }
    return m;
}

void mergeFusionMetrics(FusionMetrics& all, const FusionMetrics& more, int count) {
    const double w = 1.0 / count;
    all.fusedPositionRmse += w * (more.fusedPositionRmse - all.fusedPositionRmse);
    all.gnssPositionRmse += w * (more.gnssPositionRmse - all.gnssPositionRmse);
    all.fusedSpeedRmse += w * (more.fusedSpeedRmse - all.fusedSpeedRmse);
    all.gnssSpeedRmse += w * (more.gnssSpeedRmse - all.gnssSpeedRmse);
    for (int z = 0; z < FusionMetrics::kZones; ++z) {
        all.fusedZoneDistance[z].insert(all.fusedZoneDistance[z].end(), more.fusedZoneDistance[z].begin(),
                                        more.fusedZoneDistance[z].end());
        all.fusedZoneSpeed[z].insert(all.fusedZoneSpeed[z].end(), more.fusedZoneSpeed[z].begin(),
                                     more.fusedZoneSpeed[z].end());
        all.gnssZoneDistance[z].insert(all.gnssZoneDistance[z].end(), more.gnssZoneDistance[z].begin(),
                                       more.gnssZoneDistance[z].end());
        all.gnssZoneSpeed[z].insert(all.gnssZoneSpeed[z].end(), more.gnssZoneSpeed[z].begin(),
                                    more.gnssZoneSpeed[z].end());
    }
}

}  // namespace athlos::inertial
