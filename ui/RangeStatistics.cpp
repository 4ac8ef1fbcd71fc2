#include "ui/RangeStatistics.h"

#include "core/model/StreamData.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::ui {

RangeStatistics RangeStatistics::compute(const StreamData& data, int column, double t0, double t1) {
    RangeStatistics s;
    if (column < 0 || column >= data.columns) return s;
    const auto first = std::lower_bound(data.t.begin(), data.t.end(), t0);
    const auto last = std::upper_bound(first, data.t.end(), t1);
    // Welford: one pass, stable for long ranges with a large mean (e.g. 9.81 m/s² offsets).
    double mean = 0, m2 = 0;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (auto it = first; it != last; ++it) {
        const double v = data.at(std::size_t(it - data.t.begin()), column);
        if (!std::isfinite(v)) continue;
        ++s.count;
        const double delta = v - mean;
        mean += delta / double(s.count);
        m2 += delta * (v - mean);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (s.count == 0) return s;
    s.mean = mean;
    s.sd = s.count > 1 ? std::sqrt(m2 / double(s.count - 1)) : 0.0;
    s.min = lo;
    s.max = hi;
    return s;
}

double RangeStatistics::valueAt(const StreamData& data, int column, double t) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (column < 0 || column >= data.columns || data.rows() == 0) return nan;
    if (t < data.t.front() || t > data.t.back()) return nan;
    const auto upper = std::lower_bound(data.t.begin(), data.t.end(), t);
    const std::size_t i = std::size_t(upper - data.t.begin());
    if (*upper == t || i == 0) return data.at(i, column);
    const double ta = data.t[i - 1], tb = data.t[i];
    const double a = data.at(i - 1, column), b = data.at(i, column);
    return a + (b - a) * (t - ta) / (tb - ta);
}

}  // namespace athlos::ui
