#include "plugins/activity/ScrumDetector.h"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace athlos::activity {

namespace {
// Linear interpolation of (t, v) at time x (t ascending); NaN outside.
double interpolate(const std::vector<double>& t, const std::vector<double>& v, double x) {
    if (t.empty() || x < t.front() || x > t.back()) return std::numeric_limits<double>::quiet_NaN();
    const auto it = std::upper_bound(t.begin(), t.end(), x);
    if (it == t.end()) return v.back();
    const std::size_t j = std::size_t(it - t.begin());
    if (j == 0) return v.front();
    const double w = (x - t[j - 1]) / (t[j] - t[j - 1]);
    return (1.0 - w) * v[j - 1] + w * v[j];
}
}  // namespace

Expected<ScrumDetector::Result> ScrumDetector::detect(const std::vector<Player>& players, const Params& params) {
    const int k = params.players;
    if (k < 1) return makeError(QStringLiteral("players: must be at least 1 (thesis: 6)"));
    if (int(players.size()) < k)
        return makeError(QStringLiteral("players: the session has %1 players with an IMU, fewer than the %2 whose "
                                        "torso pitch is averaged")
                             .arg(players.size())
                             .arg(k));
    if (!(params.gridRate > 0)) return makeError(QStringLiteral("grid_rate: must be positive"));
    double begin = std::numeric_limits<double>::infinity(), end = -begin;
    for (const Player& p : players) {
        if (p.t.size() != p.pitch.size() || p.t.empty())
            return makeError(QStringLiteral("a player's torso pitch is empty or does not match its times"));
        begin = std::min(begin, p.t.front());
        end = std::max(end, p.t.back());
    }
    Result out;
    const std::size_t n = std::size_t(std::floor((end - begin) * params.gridRate)) + 1;
    out.t.resize(n);
    out.top.assign(n, std::numeric_limits<double>::quiet_NaN());
    std::vector<char> active(n, 0);
    std::vector<std::pair<double, int>> pitch;
    for (std::size_t g = 0; g < n; ++g) {
        const double t = begin + double(g) / params.gridRate;
        out.t[g] = t;
        pitch.clear();
        for (std::size_t i = 0; i < players.size(); ++i) {
            const double a = interpolate(players[i].t, players[i].pitch, t);
            if (std::isfinite(a)) pitch.emplace_back(a, int(i));
        }
        if (int(pitch.size()) < k) continue;  // fewer players recorded here than averaged
        std::partial_sort(pitch.begin(), pitch.begin() + k, pitch.end(), std::greater<>());
        double mean = 0.0;
        for (int j = 0; j < k; ++j) mean += pitch[std::size_t(j)].first;
        mean /= double(k);
        out.top[g] = mean;
        if (mean < params.threshold) continue;
        bool compact = true;
        if (params.maxSpread > 0.0) {
            std::vector<Eigen::Vector2d> at;
            for (int j = 0; j < k; ++j) {
                const Player& p = players[std::size_t(pitch[std::size_t(j)].second)];
                const double x = interpolate(p.tPos, p.x, t), y = interpolate(p.tPos, p.y, t);
                if (std::isfinite(x) && std::isfinite(y)) at.emplace_back(x, y);
            }
            if (!at.empty()) {
                Eigen::Vector2d c = Eigen::Vector2d::Zero();
                for (const auto& p : at) c += p;
                c /= double(at.size());
                for (const auto& p : at) compact = compact && (p - c).norm() <= params.maxSpread;
            }
        }
        active[g] = compact ? 1 : 0;
    }
    // Runs of active grid points, merged across short gaps, kept when long enough.
    const double step = 1.0 / params.gridRate;
    std::vector<std::pair<std::size_t, std::size_t>> runs;
    for (std::size_t g = 0; g < n;) {
        if (!active[g]) {
            ++g;
            continue;
        }
        std::size_t e = g;
        while (e + 1 < n && active[e + 1]) ++e;
        if (!runs.empty() && out.t[g] - out.t[runs.back().second] <= params.mergeGap + step)
            runs.back().second = e;
        else
            runs.emplace_back(g, e);
        g = e + 1;
    }
    for (const auto& [a, b] : runs) {
        if (out.t[b] - out.t[a] + step < params.minDuration) continue;
        double peak = 0.0;
        for (std::size_t g = a; g <= b; ++g)
            if (std::isfinite(out.top[g])) peak = std::max(peak, out.top[g]);
        Annotation an;
        an.label = QStringLiteral("scrum");
        an.tStart = out.t[a];
        an.tEnd = out.t[b];
        // Confidence: how far the peak is above the threshold, relative to the threshold.
        an.confidence = std::clamp(0.5 + (peak - params.threshold) / std::max(params.threshold, 1e-9), 0.5, 1.0);
        out.scrums.push_back(an);
    }
    return out;
}

}  // namespace athlos::activity
