#include "plugins/events/TurnSwitchDetector.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace athlos::events {

namespace {
std::vector<double> movingAverage(const std::vector<double>& x, std::size_t half) {
    const std::size_t n = x.size();
    std::vector<double> prefix(n + 1, 0.0), out(n);
    for (std::size_t i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + x[i];
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t lo = i - std::min(i, half), hi = std::min(n, i + half + 1);
        out[i] = (prefix[hi] - prefix[lo]) / double(hi - lo);
    }
    return out;
}
}  // namespace

Eigen::Vector3d longitudinalAxis(const std::vector<double>& acc) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i + 2 < acc.size(); i += 3) mean += Eigen::Vector3d(acc[i], acc[i + 1], acc[i + 2]);
    Eigen::Vector3d axis = Eigen::Vector3d::Zero();
    if (mean.norm() <= 0.0) return axis;
    Eigen::Index k = 0;
    mean.cwiseAbs().maxCoeff(&k);
    axis[k] = mean[k] > 0.0 ? 1.0 : -1.0;
    return axis;
}

std::vector<Turn> detectTurns(const std::vector<double>& t, const std::vector<double>& gyr,
                              const std::vector<double>& acc, const TurnSwitchParams& p, std::vector<double>* yawRate) {
    const std::size_t n = t.size();
    std::vector<Turn> turns;
    if (n < 3) return turns;
    const Eigen::Vector3d up = p.axis.norm() > 0.0 ? Eigen::Vector3d(p.axis.normalized()) : longitudinalAxis(acc);
    if (up.norm() <= 0.0) return turns;
    std::vector<double> w(n);
    for (std::size_t i = 0; i < n; ++i) w[i] = Eigen::Vector3d(gyr[3 * i], gyr[3 * i + 1], gyr[3 * i + 2]).dot(up);
    const double ts = (t.back() - t.front()) / double(n - 1);
    const auto half = std::size_t(0.5 * p.smoothing / ts);
    w = movingAverage(movingAverage(w, half), half);
    if (yawRate) *yawRate = w;

    // Switch instants (linear interpolation of the zero crossing) with the side of the turn after it.
    std::vector<double> switches;
    std::vector<bool> leftAfter;
    int side = 0;
    double lastCross = t.front();
    for (std::size_t i = 1; i < n; ++i) {
        if ((w[i - 1] < 0.0) != (w[i] < 0.0)) lastCross = t[i - 1] + (t[i] - t[i - 1]) * w[i - 1] / (w[i - 1] - w[i]);
        const int s = w[i] > p.threshold ? 1 : w[i] < -p.threshold ? -1 : 0;
        if (s == 0 || s == side) continue;
        if (side != 0) {
            switches.push_back(lastCross);
            leftAfter.push_back(s > 0);
        }
        side = s;
    }
    for (std::size_t k = 0; k + 1 < switches.size(); ++k) {
        const double d = switches[k + 1] - switches[k];
        if (d < p.minTurn || d > p.maxTurn) continue;
        Turn turn{switches[k], switches[k + 1], leftAfter[k], 0.0};
        for (std::size_t i = 0; i < n; ++i)
            if (t[i] >= turn.start && t[i] <= turn.end) turn.peakRate = std::max(turn.peakRate, std::abs(w[i]));
        turns.push_back(turn);
    }
    return turns;
}

}  // namespace athlos::events
