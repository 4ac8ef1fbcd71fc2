#include "plugins/lps/TdoaScreening.h"

#include "plugins/lps/RobustStatistics.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace athlos::lps {

// flags[k][j] = 1: reading j of epoch k is dropped.
std::vector<std::vector<char>> TdoaScreening::grubbsFlags(const std::vector<TdoaEpoch>& epochs, int beacons) const {
    std::vector<std::vector<char>> flags(epochs.size());
    for (std::size_t k = 0; k < epochs.size(); ++k) flags[k].assign(epochs[k].readings.size(), 0);
    struct Rate {
        std::size_t epoch, reading;
        bool startsSeries;  // the previous reading of this beacon had no rate (gap or first)
    };
    for (int b = 0; b < beacons; ++b) {
        std::vector<double> rate;
        std::vector<Rate> at;
        double lastT = 0.0, lastDt = 0.0;
        bool have = false, continuing = false;
        for (std::size_t k = 0; k < epochs.size(); ++k)
            for (std::size_t j = 0; j < epochs[k].readings.size(); ++j) {
                const TdoaReading& r = epochs[k].readings[j];
                if (r.beacon != b || !std::isfinite(r.dt)) continue;
                const double dtSeconds = epochs[k].t - lastT;
                if (have && dtSeconds > 0.0 && dtSeconds <= p_.maxGap) {
                    rate.push_back(kSpeedOfLight * (r.dt - lastDt) / dtSeconds);  // m/s
                    at.push_back({k, j, !continuing});
                    continuing = true;
                } else {
                    continuing = false;
                }
                lastT = epochs[k].t;
                lastDt = r.dt;
                have = true;
            }
        if (int(rate.size()) < p_.minSamples) continue;
        const std::vector<bool> outlier = grubbsOutliers(rate, p_.alpha, int(rate.size()) - p_.minSamples);
        // A single late reading makes two outlying rates: a jump into it and the opposite jump back.
        // Drop the reading of the first; the second (opposite sign, right after a dropped reading)
        // leads back to a clean reading, which is kept.
        bool previousDropped = false;
        for (std::size_t i = 0; i < outlier.size(); ++i) {
            const bool back =
                i > 0 && previousDropped && outlier[i - 1] && (rate[i] > 0) != (rate[i - 1] > 0) && !at[i].startsSeries;
            const bool drop = outlier[i] && !back;
            if (drop) flags[at[i].epoch][at[i].reading] = 1;
            previousDropped = drop;
        }
    }
    return flags;
}

std::vector<std::vector<char>> TdoaScreening::kalmanFlags(const std::vector<TdoaEpoch>& epochs, int beacons) const {
    std::vector<std::vector<char>> flags(epochs.size());
    for (std::size_t k = 0; k < epochs.size(); ++k) flags[k].assign(epochs[k].readings.size(), 0);
    struct Track {
        Eigen::Vector2d x = Eigen::Vector2d::Zero();  // c·Δt (m), its rate (m/s)
        Eigen::Matrix2d P = Eigen::Matrix2d::Identity();
        double t = 0.0, rejectedSince = NAN;
        bool live = false;
    };
    std::vector<Track> tracks(static_cast<std::size_t>(std::max(beacons, 0)));
    const double r = p_.measurementVariance;
    for (std::size_t k = 0; k < epochs.size(); ++k) {
        const double t = epochs[k].t;
        for (std::size_t j = 0; j < epochs[k].readings.size(); ++j) {
            const TdoaReading& reading = epochs[k].readings[j];
            if (reading.beacon < 0 || reading.beacon >= beacons || !std::isfinite(reading.dt)) continue;
            Track& f = tracks[std::size_t(reading.beacon)];
            const double y = kSpeedOfLight * reading.dt;
            const double h = t - f.t;
            const bool restart = !f.live || h > p_.maxGap || h < 0.0 ||
                                 (std::isfinite(f.rejectedSince) && t - f.rejectedSince > p_.maxRejected);
            if (restart) {
                f.x << y, 0.0;
                f.P << r, 0.0, 0.0, 100.0;  // rate unknown: (10 m/s)²
                f.t = t;
                f.live = true;
                f.rejectedSince = NAN;
                continue;
            }
            // Constant velocity with white-noise acceleration (density q): Φ, Q of the discretised model.
            Eigen::Matrix2d Phi;
            Phi << 1.0, h, 0.0, 1.0;
            Eigen::Matrix2d Q;
            Q << h * h * h / 3.0, h * h / 2.0, h * h / 2.0, h;
            const Eigen::Vector2d xp = Phi * f.x;
            const Eigen::Matrix2d Pp = Phi * f.P * Phi.transpose() + p_.accelDensity * Q;
            const double innovation = y - xp(0), s = Pp(0, 0) + r;
            f.t = t;
            if (innovation * innovation / s > p_.gate) {
                flags[k][j] = 1;
                f.x = xp;
                f.P = Pp;
                if (!std::isfinite(f.rejectedSince)) f.rejectedSince = t;
                continue;
            }
            const Eigen::Vector2d gain = Pp.col(0) / s;
            f.x = xp + gain * innovation;
            f.P = Pp - gain * Pp.row(0);
            f.rejectedSince = NAN;
        }
    }
    return flags;
}

std::vector<TdoaEpoch> TdoaScreening::screen(const std::vector<TdoaEpoch>& epochs, int beacons, int* dropped) const {
    if (dropped) *dropped = 0;
    if (p_.method == Method::None) return epochs;
    const auto flags = p_.method == Method::GrubbsRate ? grubbsFlags(epochs, beacons) : kalmanFlags(epochs, beacons);
    std::vector<TdoaEpoch> out(epochs.size());
    for (std::size_t k = 0; k < epochs.size(); ++k) {
        out[k].t = epochs[k].t;
        for (std::size_t j = 0; j < epochs[k].readings.size(); ++j) {
            if (flags[k][j]) {
                if (dropped) ++*dropped;
                continue;
            }
            out[k].readings.push_back(epochs[k].readings[j]);
        }
    }
    return out;
}

}  // namespace athlos::lps
