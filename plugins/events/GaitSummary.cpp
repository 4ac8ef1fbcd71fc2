#include "plugins/events/GaitSummary.h"

#include <algorithm>
#include <cmath>

namespace athlos::events {

namespace {
// Adjacent strides share their mid-stance: one's end is the next one's start (to 1 ms).
constexpr double kAdjacent = 1e-3;  // s

ParameterStats statsOf(const std::vector<double>& values, const std::vector<bool>& use) {
    // Eq. 2 over the used, finite values.
    ParameterStats s;
    double sum = 0.0;
    bool positive = true, negative = true;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (use[i] && std::isfinite(values[i])) {
            sum += values[i];
            positive = positive && values[i] > 0.0;
            negative = negative && values[i] < 0.0;
            ++s.n;
        }
    if (s.n == 0) return s;
    s.sign = positive ? 1 : negative ? -1 : 0;
    s.mean = sum / s.n;
    if (s.n < 2) return s;
    double ss = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (use[i] && std::isfinite(values[i])) ss += (values[i] - s.mean) * (values[i] - s.mean);
    s.sd = std::sqrt(ss / (s.n - 1));  // eq. 2
    if (s.sign != 0) s.cv = 100.0 * s.sd / std::abs(s.mean);
    return s;
}
}  // namespace

std::optional<Terrain> terrainOf(const QString& name) {
    if (name == QLatin1String("all")) return Terrain::All;
    if (name == QLatin1String("level")) return Terrain::Level;
    if (name == QLatin1String("up")) return Terrain::Up;
    if (name == QLatin1String("down")) return Terrain::Down;
    return std::nullopt;
}

namespace {
bool onTerrain(const GaitSummaryParams& params, const FootStrides& foot, std::size_t i) {
    if (params.terrain == Terrain::All) return true;
    const double h = i < foot.height.size() ? foot.height[i] : std::numeric_limits<double>::quiet_NaN();
    switch (params.terrain) {
        case Terrain::Level:
            return std::abs(h) <= params.levelHeight;
        case Terrain::Up:
            return h >= params.stairHeight;
        case Terrain::Down:
            return h <= -params.stairHeight;
        case Terrain::All:
            break;
    }
    return true;
}

// Eq. 1 without the run ends: straight and on the chosen terrain.
bool straightOnTerrain(const GaitSummaryParams& params, const FootStrides& foot, std::size_t i) {
    return std::abs(foot.turn[i]) <= params.maxTurn && onTerrain(params, foot, i);
}
}  // namespace

std::vector<bool> steadyStrides(const GaitSummaryParams& params, const FootStrides& foot) {
    const std::size_t n = foot.start.size();
    std::vector<bool> use(n);
    for (std::size_t i = 0; i < n; ++i) use[i] = straightOnTerrain(params, foot, i);
    // Eq. 1, run ends: the first and last edgeStrides of every run of adjacent straight strides.
    std::vector<bool> out = use;
    std::size_t i = 0;
    while (i < n) {
        if (!use[i]) {
            ++i;
            continue;
        }
        std::size_t j = i;  // the run is i … j
        while (j + 1 < n && use[j + 1] && std::abs(foot.start[j + 1] - foot.end[j]) <= kAdjacent) ++j;
        const std::size_t length = j - i + 1, edge = std::size_t(std::max(params.edgeStrides, 0));
        for (std::size_t k = 0; k < length; ++k)
            if (k < edge || k + edge >= length) out[i + k] = false;
        i = j + 1;
    }
    return out;
}

GaitSummary summariseGait(const GaitSummaryParams& params, const std::vector<FootStrides>& feet) {
    GaitSummary g;
    if (feet.empty()) return g;
    g.names = feet.front().names;
    g.units = feet.front().units;
    std::vector<std::vector<bool>> uses;
    for (const FootStrides& f : feet) {
        const std::vector<bool>& use = uses.emplace_back(steadyStrides(params, f));
        FootSummary s;
        s.foot = f.foot;
        s.strides = int(f.start.size());
        for (std::size_t i = 0; i < f.start.size(); ++i) {
            if (std::abs(f.turn[i]) > params.maxTurn)
                ++s.turns;
            else if (!onTerrain(params, f, i))
                ++s.terrain;
            else if (!use[i])
                ++s.edges;
            else
                ++s.used;
        }
        for (const QString& name : g.names) {
            const qsizetype p = f.names.indexOf(name);
            s.stats.push_back(p < 0 ? ParameterStats{} : statsOf(f.parameters[std::size_t(p)], use));
        }
        g.feet.push_back(std::move(s));
    }
    if (g.feet.size() == 2) {
        g.pooled.foot = QStringLiteral("both");
        for (const FootSummary& s : g.feet) {
            g.pooled.strides += s.strides;
            g.pooled.turns += s.turns;
            g.pooled.terrain += s.terrain;
            g.pooled.edges += s.edges;
            g.pooled.used += s.used;
        }
        for (const QString& name : g.names) {
            std::vector<double> values;
            std::vector<bool> used;
            for (int f = 0; f < 2; ++f) {
                const qsizetype p = feet[std::size_t(f)].names.indexOf(name);
                if (p < 0) continue;
                const std::vector<double>& v = feet[std::size_t(f)].parameters[std::size_t(p)];
                values.insert(values.end(), v.begin(), v.end());
                used.insert(used.end(), uses[std::size_t(f)].begin(), uses[std::size_t(f)].end());
            }
            g.pooled.stats.push_back(statsOf(values, used));
        }
        for (std::size_t p = 0; p < std::size_t(g.names.size()); ++p) {
            const ParameterStats &l = g.feet[0].stats[p], &r = g.feet[1].stats[p];
            g.symmetry.push_back(l.sign != 0 && l.sign == r.sign
                                     ? 100.0 * std::abs(l.mean - r.mean) / (0.5 * std::abs(l.mean + r.mean))  // eq. 3
                                     : std::numeric_limits<double>::quiet_NaN());
        }
    }
    return g;
}

}  // namespace athlos::events
