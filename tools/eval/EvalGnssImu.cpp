// athlos-eval-gnss-imu [sessions=6] [attitude=orientation|kalman|ekf] [acc_noise m/s²] [position-only: 0|1]
// Simulated football sessions (ImuGnssSimulator: 100 Hz IMU with bias, noise, scale errors and
// saturation; 10 Hz GNSS with 2.5 m noise and a slowly correlated error), fused with GnssImuEkf.
// Prints the shape of seed 004's Tables 1–2 (distance and speed error per 2 m zone of the 10 m
// sprints: mean ± SD [5 %, 95 %]) for the fused track and for GNSS alone, and overall RMSEs.
#include "tools/eval/FusionEvaluation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace athlos::inertial;

namespace {
void printZones(const char* title, const std::array<std::vector<double>, FusionMetrics::kZones>& zones) {
    std::printf("%-28s", title);
    for (const auto& values : zones) {
        std::vector<double> v = values;
        if (v.empty()) {
            std::printf(" %24s", "-");
            continue;
        }
        std::sort(v.begin(), v.end());
        double mean = 0, var = 0;
        for (double x : v) mean += x;
        mean /= static_cast<double>(v.size());
        for (double x : v) var += (x - mean) * (x - mean);
        const double sd = std::sqrt(var / static_cast<double>(v.size()));
        const auto q = [&](double p) {
            return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))];
        };
        std::printf("  %.2f±%.2f [%.2f,%.2f]", mean, sd, q(0.05), q(0.95));
    }
    std::printf("\n");
}
}  // namespace

int main(int argc, char** argv) {
    const int sessions = argc > 1 ? std::max(1, std::atoi(argv[1])) : 6;
    GnssImuEkf::Params params;
    if (argc > 2) {
        if (!std::strcmp(argv[2], "kalman"))
            params.attitude = AttitudeSource::Kalman;
        else if (!std::strcmp(argv[2], "ekf"))
            params.attitude = AttitudeSource::Ekf;
        else if (std::strcmp(argv[2], "orientation")) {
            std::fprintf(stderr, "attitude: use orientation, kalman or ekf\n");
            return 2;
        }
    }
    if (argc > 3) params.accNoise = std::atof(argv[3]);
    const bool positionOnly = argc > 4 && std::atoi(argv[4]) != 0;
    FusionMetrics all;
    std::printf("%-8s %14s %14s %14s %14s\n", "session", "fused pos m", "GNSS pos m", "fused spd m/s", "GNSS spd m/s");
    for (int s = 1; s <= sessions; ++s) {
        SimulatorParams sp;
        sp.seed = static_cast<std::uint64_t>(s);
        const FusionMetrics m = evaluateFusion(simulateImuGnss(sp), params, !positionOnly);
        std::printf("%-8d %14.3f %14.3f %14.3f %14.3f\n", s, m.fusedPositionRmse, m.gnssPositionRmse, m.fusedSpeedRmse,
                    m.gnssSpeedRmse);
        mergeFusionMetrics(all, m, s);
    }
    std::printf("%-8s %14.3f %14.3f %14.3f %14.3f   (position RMSE %.0f %% below GNSS)\n\n", "MEAN",
                all.fusedPositionRmse, all.gnssPositionRmse, all.fusedSpeedRmse, all.gnssSpeedRmse,
                100.0 * (1.0 - all.fusedPositionRmse / all.gnssPositionRmse));
    std::printf("%-28s  %-22s  %-22s  %-22s  %-22s  %-22s\n", "per 2 m zone of 10 m sprints", "[0,2) m", "[2,4) m",
                "[4,6) m", "[6,8) m", "[8,10) m");
    printZones("distance error fused (m)", all.fusedZoneDistance);
    printZones("distance error GNSS (m)", all.gnssZoneDistance);
    printZones("speed error fused (m/s)", all.fusedZoneSpeed);
    printZones("speed error GNSS (m/s)", all.gnssZoneSpeed);
    return 0;
}
