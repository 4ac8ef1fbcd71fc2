#include "plugins/events/PoleEventDetector.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace athlos::events {

std::vector<PoleEvents> detectPoleEvents(const std::vector<double>& t, const std::vector<double>& a,
                                         const PoleEventParams& p) {
    const std::size_t n = t.size();
    std::vector<PoleEvents> out;
    if (n < 3) return out;
    const double ts = (t.back() - t.front()) / double(n - 1);
    std::vector<double> vib(n, 0.0);
    for (std::size_t i = 2; i < n; ++i) vib[i] = std::abs(a[i] - 2.0 * a[i - 1] + a[i - 2]);
    const auto half = std::max<std::size_t>(1, std::size_t(0.5 * p.minCycle / ts));
    const auto onset = std::size_t(std::ceil(p.onsetWindow / ts));
    std::vector<std::size_t> plants;
    for (std::size_t i = 2; i < n; ++i) {
        if (vib[i] < p.plantThreshold) continue;
        const std::size_t lo = i - std::min(i, half), hi = std::min(n, i + half + 1);
        if (std::size_t(std::max_element(vib.begin() + std::ptrdiff_t(lo), vib.begin() + std::ptrdiff_t(hi)) -
                        vib.begin()) != i)
            continue;
        std::size_t k = i - std::min(i, onset);
        while (k < i && vib[k] < p.onsetThreshold) ++k;
        plants.push_back(k);
        i += half;
    }
    const auto skip = std::size_t(std::ceil(p.shockSkip / ts));
    const auto contact = std::size_t(std::ceil(p.maxContact / ts));
    for (std::size_t k = 0; k < plants.size(); ++k) {
        const std::size_t lo = plants[k] + skip;
        const std::size_t hi = std::min({n, k + 1 < plants.size() ? plants[k + 1] : n, plants[k] + contact});
        if (lo >= hi) continue;
        const auto m =
            std::size_t(std::max_element(a.begin() + std::ptrdiff_t(lo), a.begin() + std::ptrdiff_t(hi)) - a.begin());
        out.push_back({t[plants[k]], t[m]});
    }
    return out;
}

}  // namespace athlos::events
