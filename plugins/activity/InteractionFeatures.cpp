#include "plugins/activity/InteractionFeatures.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::activity {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double interpolate(const std::vector<double>& t, const std::vector<double>& v, double x) {
    if (t.size() < 2 || x < t.front() || x > t.back()) return kNaN;
    const std::size_t j = std::min(std::size_t(std::upper_bound(t.begin(), t.end(), x) - t.begin()), t.size() - 1);
    if (j == 0) return v.front();
    const double w = (x - t[j - 1]) / (t[j] - t[j - 1]);
    return (1.0 - w) * v[j - 1] + w * v[j];
}

double speedOf(const InteractionFeatures::Athlete& a, double t, double span) {
    const double dx = interpolate(a.tPos, a.x, t) - interpolate(a.tPos, a.x, t - span);
    const double dy = interpolate(a.tPos, a.y, t) - interpolate(a.tPos, a.y, t - span);
    return std::hypot(dx, dy) / span;
}

double meanPitch(const InteractionFeatures::Athlete& a, double from, double to) {
    const auto begin = std::lower_bound(a.tPitch.begin(), a.tPitch.end(), from);
    const auto end = std::upper_bound(a.tPitch.begin(), a.tPitch.end(), to);
    if (begin >= end) return kNaN;
    double sum = 0.0;
    for (auto it = begin; it != end; ++it) sum += a.pitch[std::size_t(it - a.tPitch.begin())];
    return sum / double(end - begin);
}
}  // namespace

QStringList InteractionFeatures::names(const Params& params) {
    QStringList out{QStringLiteral("own_pitch"), QStringLiteral("own_speed")};
    for (int k = 1; k <= params.neighbours; ++k)
        for (const char* f : {"distance", "speed", "pitch"})
            out << QStringLiteral("opp%1_%2").arg(k).arg(QLatin1String(f));
    return out;
}

std::vector<double> InteractionFeatures::compute(const std::vector<Athlete>& athletes, int player, double t,
                                                 const Params& params) {
    const Athlete& me = athletes[std::size_t(player)];
    const double from = t - 0.5 * params.window, to = t + 0.5 * params.window;
    std::vector<double> out{meanPitch(me, from, to), speedOf(me, t, params.speedSpan)};
    const double x = interpolate(me.tPos, me.x, t), y = interpolate(me.tPos, me.y, t);
    std::vector<std::pair<double, int>> opponents;
    for (std::size_t j = 0; j < athletes.size(); ++j) {
        if (athletes[j].team == me.team) continue;
        const double d = std::hypot(interpolate(athletes[j].tPos, athletes[j].x, t) - x,
                                    interpolate(athletes[j].tPos, athletes[j].y, t) - y);
        if (std::isfinite(d)) opponents.emplace_back(d, int(j));
    }
    std::sort(opponents.begin(), opponents.end());
    for (int k = 0; k < params.neighbours; ++k) {
        if (k >= int(opponents.size())) {
            out.insert(out.end(), {kNaN, kNaN, kNaN});
            continue;
        }
        const Athlete& o = athletes[std::size_t(opponents[std::size_t(k)].second)];
        out.push_back(opponents[std::size_t(k)].first);
        out.push_back(speedOf(o, t, params.speedSpan));
        out.push_back(meanPitch(o, from, to));
    }
    return out;
}

}  // namespace athlos::activity
