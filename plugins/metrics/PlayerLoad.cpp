#include "plugins/metrics/PlayerLoad.h"

#include <algorithm>
#include <cmath>

namespace athlos::metrics {

double playerLoad(const AccelerationSeries& acc, double start, double end) {
    constexpr double g = 9.80665;
    const auto first = std::lower_bound(acc.t.begin(), acc.t.end(), start) - acc.t.begin();
    double load = 0.0;
    for (auto k = first; k + 1 < static_cast<long>(acc.t.size()) && acc.t[k + 1] <= end; ++k) {
        const double dx = (acc.ax[k + 1] - acc.ax[k]) / g, dy = (acc.ay[k + 1] - acc.ay[k]) / g,
                     dz = (acc.az[k + 1] - acc.az[k]) / g;
        const double step = std::sqrt(dx * dx + dy * dy + dz * dz);
        if (std::isfinite(step)) load += step;
    }
    return load / 100.0;
}

}  // namespace athlos::metrics
