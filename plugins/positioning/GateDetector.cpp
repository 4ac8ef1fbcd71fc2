#include "plugins/positioning/GateDetector.h"

#include <algorithm>
#include <cmath>

namespace athlos::positioning {

double GateDetector::distanceFromField(double excess) {
    const double r = excess < 1.62 ? -0.4 * excess + 1.0 : -0.062 * excess + 0.452;  // eq. 9.1
    return std::clamp(r, 0.02, 1.0);
}

std::vector<GateCrossing> GateDetector::detect(const std::vector<double>& t, const std::vector<double>& e,
                                               const std::vector<double>& yawRate) const {
    std::vector<GateCrossing> out;
    const std::size_t n = std::min({t.size(), e.size(), yawRate.size()});
    if (n < 3) return out;
    std::size_t k = 1;
    while (k + 1 < n) {
        if (!(e[k] > params_.threshold)) {
            ++k;
            continue;
        }
        // The excursion above the threshold: its maximum is the crossing.
        std::size_t end = k, best = k;
        while (end + 1 < n && e[end + 1] > params_.threshold) {
            ++end;
            if (e[end] > e[best]) best = end;
        }
        double tc = t[best], peak = e[best];
        if (best > 0 && best + 1 < n) {
            const double a = e[best - 1], b = e[best], c = e[best + 1];
            const double den = a - 2.0 * b + c;
            if (den < 0.0) {
                const double off = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
                const double step = off >= 0.0 ? t[best + 1] - t[best] : t[best] - t[best - 1];
                tc = t[best] + off * step;
                peak = b - 0.25 * (a - c) * off;
            }
        }
        GateCrossing crossing{tc, peak, distanceFromField(peak), yawRate[best] >= 0.0 ? 1 : -1};
        if (!out.empty() && tc - out.back().t < params_.minInterval) {
            if (peak > out.back().excess) out.back() = crossing;  // the stronger of two close peaks
        } else {
            out.push_back(crossing);
        }
        k = end + 1;
    }
    return out;
}

}  // namespace athlos::positioning
