#include "plugins/events/ImuGaps.h"

#include <QString>
#include <cmath>

namespace athlos::events {

Expected<GapFill> fillShortGaps(std::vector<double>& values, std::size_t columns, const std::vector<double>& t,
                                double maxGap) {
    const std::size_t n = t.size();
    const auto complete = [&](std::size_t k) {
        for (std::size_t c = 0; c < columns; ++c)
            if (!std::isfinite(values[k * columns + c])) return false;
        return true;
    };
    GapFill fill;
    std::vector<double> out = values;
    std::size_t k = 0;
    while (k < n) {
        if (complete(k)) {
            ++k;
            continue;
        }
        std::size_t end = k;  // the run is k … end − 1
        while (end < n && !complete(end)) ++end;
        const bool before = k > 0, after = end < n;
        // The interval without a complete sample: between the neighbours, or to the recording's start/end.
        const double t0 = before ? t[k - 1] : t[k], t1 = after ? t[end] : t[end - 1];
        if (!before && !after) return makeError(QStringLiteral("no sample has finite values in every IMU column"));
        if (t1 - t0 > maxGap)
            return makeError(QStringLiteral("no complete IMU sample from t = %1 s to %2 s (%3 s, %4 of the data): "
                                            "longer than max_gap = %5 s, too long to bridge for integration")
                                 .arg(t0, 0, 'f', 3)
                                 .arg(t1, 0, 'f', 3)
                                 .arg(t1 - t0, 0, 'g', 3)
                                 .arg(end == k + 1 ? QStringLiteral("row %1").arg(end)
                                                   : QStringLiteral("rows %1 to %2").arg(k + 1).arg(end))
                                 .arg(maxGap));
        for (std::size_t j = k; j < end; ++j)
            for (std::size_t c = 0; c < columns; ++c) {
                double& v = out[j * columns + c];
                if (std::isfinite(v)) continue;
                if (before && after) {
                    const double w = (t[j] - t[k - 1]) / (t[end] - t[k - 1]);
                    v = (1.0 - w) * values[(k - 1) * columns + c] + w * values[end * columns + c];
                } else {
                    v = before ? values[(k - 1) * columns + c] : values[end * columns + c];
                }
            }
        ++fill.runs;
        fill.samples += end - k;
        fill.longest = std::max(fill.longest, t1 - t0);
        k = end;
    }
    values.swap(out);
    return fill;
}

}  // namespace athlos::events
