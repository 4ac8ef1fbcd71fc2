#include "plugins/metrics/TrackSplits.h"

#include <cmath>
#include <limits>

namespace athlos::metrics {

std::vector<double> TrackSplits::progress(const MotionSeries& s, const TrackGeometry& track) {
    const double length = track.referenceLength(), scale = track.laneLength(1) / length;
    std::vector<double> out(s.size(), std::numeric_limits<double>::quiet_NaN());
    double previous = std::nan(""), unwrapped = 0.0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (!s.valid[k]) continue;
        const double arc = track.query({s.x[k], s.y[k]}).s;
        if (std::isfinite(previous)) {
            double step = arc - previous;  // unwrap across the start of the reference line
            step -= length * std::round(step / length);
            unwrapped += step;
        }
        previous = arc;
        out[k] = unwrapped * scale;
    }
    // Running clockwise: progress counts the other way.
    double last = 0.0;
    for (double v : out)
        if (std::isfinite(v)) last = v;
    if (last < 0)
        for (double& v : out) v = -v;
    return out;
}

std::vector<TrackInterval> TrackSplits::compute(const MotionSeries& s, const TrackGeometry& track, const Params& p) {
    const std::vector<double> progressed = progress(s, track);
    const double lap = track.laneLength(1);
    // Instants at which the progress first reaches each multiple of `step` (k = 1, 2, …).
    auto passes = [&](double step) {
        std::vector<double> times;
        double tPrev = std::nan(""), vPrev = 0.0;
        for (std::size_t k = 0; k < s.size(); ++k) {
            if (!std::isfinite(progressed[k])) {
                tPrev = std::nan("");
                continue;
            }
            const double v = progressed[k];
            while (v >= step * double(times.size() + 1)) {
                const double level = step * double(times.size() + 1);
                times.push_back(std::isfinite(tPrev) && v > vPrev
                                    ? tPrev + (s.t[k] - tPrev) * (level - vPrev) / (v - vPrev)
                                    : s.t[k]);
            }
            tPrev = s.t[k];
            vPrev = v;
        }
        return times;
    };
    double start = std::nan("");
    for (std::size_t k = 0; k < s.size() && std::isnan(start); ++k)
        if (std::isfinite(progressed[k])) start = s.t[k];
    std::vector<TrackInterval> out;
    if (std::isnan(start)) return out;
    const auto laps = passes(lap);
    for (std::size_t i = 0; i < laps.size(); ++i)
        out.push_back({QStringLiteral("lap %1").arg(i + 1), i == 0 ? start : laps[i - 1], laps[i]});
    if (p.splitDistance > 0) {
        const auto splits = passes(p.splitDistance);
        for (std::size_t i = 0; i < splits.size(); ++i)
            out.push_back({QStringLiteral("%1 m #%2").arg(p.splitDistance).arg(i + 1), i == 0 ? start : splits[i - 1],
                           splits[i]});
    }
    return out;
}

}  // namespace athlos::metrics
