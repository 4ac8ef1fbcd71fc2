#include "plugins/metrics/SessionMetrics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::metrics {

void MotionSeries::resize(std::size_t n) {
    t.resize(n);
    x.resize(n);
    y.resize(n);
    speed.resize(n);
    accel.resize(n);
    valid.resize(n, 1);
}

namespace {

// Time at which the linear interpolation between (t0, v0) and (t1, v1) reaches `level`.
double crossing(double t0, double v0, double t1, double v1, double level) {
    if (v1 == v0) return t0;
    return t0 + (t1 - t0) * std::clamp((level - v0) / (v1 - v0), 0.0, 1.0);
}

int zoneOf(const std::vector<double>& edges, double speed) {
    const auto it = std::upper_bound(edges.begin(), edges.end(), speed);
    return std::max(0, static_cast<int>(it - edges.begin()) - 1);
}

// The largest v such that the speed stays ≥ v over a window of `duration` seconds of valid samples:
// the maximum over windows of the window's minimum (a monotone deque keeps the minimum, O(n)).
double sustainedMaximum(const MotionSeries& s, std::size_t first, std::size_t last, double duration) {
    double best = 0.0;
    std::vector<std::size_t> deque;  // indices of increasing speed within the current window
    std::size_t head = 0, start = first;
    for (std::size_t k = first; k <= last; ++k) {
        if (!s.valid[k]) {  // an outage ends every window
            deque.clear();
            head = 0;
            start = k + 1;
            continue;
        }
        while (deque.size() > head && s.speed[deque.back()] >= s.speed[k]) deque.pop_back();
        deque.push_back(k);
        // Shrink the window from the left while it still spans the duration without sample `start`.
        while (start < k && s.t[k] - s.t[start + 1] >= duration - 1e-9) ++start;
        while (deque[head] < start) ++head;
        if (s.t[k] - s.t[start] >= duration - 1e-9) best = std::max(best, s.speed[deque[head]]);
    }
    return best;
}

}  // namespace

int countEfforts(const MotionSeries& s, const std::vector<double>& value, std::size_t first, std::size_t last,
                 double threshold, double sign, double minDuration) {
    int count = 0;
    bool inside = false;
    double runStart = 0.0;
    const auto above = [&](std::size_t k) { return s.valid[k] && sign * value[k] >= sign * threshold; };
    for (std::size_t k = first; k <= last && k < s.size(); ++k) {
        const bool now = above(k);
        if (now && !inside) {
            // Entry: interpolate from the previous sample when it is a valid sample of this period.
            const bool fromBelow = k > first && s.valid[k - 1];
            runStart = fromBelow ? crossing(s.t[k - 1], value[k - 1], s.t[k], value[k], threshold) : s.t[k];
            inside = true;
        } else if (!now && inside) {
            const double runEnd =
                s.valid[k] ? crossing(s.t[k - 1], value[k - 1], s.t[k], value[k], threshold) : s.t[k - 1];
            if (runEnd - runStart >= minDuration - 1e-9) ++count;
            inside = false;
        }
    }
    if (inside) {
        const std::size_t end = std::min(last, s.size() - 1);
        if (s.t[end] - runStart >= minDuration - 1e-9) ++count;
    }
    return count;
}

PeriodMetrics computePeriod(const MotionSeries& s, double start, double end, const MetricsParams& p) {
    PeriodMetrics m;
    m.start = start;
    m.end = end;
    m.duration = end - start;
    const std::size_t zones = p.zoneEdges.size();
    m.zoneDistance.assign(zones, 0.0);
    m.peakDistance.assign(p.peakWindows.size(), std::numeric_limits<double>::quiet_NaN());
    const std::size_t first = std::lower_bound(s.t.begin(), s.t.end(), start) - s.t.begin();
    const std::size_t stop = std::upper_bound(s.t.begin(), s.t.end(), end) - s.t.begin();  // one past the last
    if (stop <= first) return m;
    const std::size_t last = stop - 1;

    std::vector<double> power(stop - first);
    for (std::size_t k = first; k < stop; ++k) {
        power[k - first] = metabolicPower(s.speed[k], s.accel[k], p.metabolic);
    }
    m.maxSpeed = sustainedMaximum(s, first, last, p.maxSpeedDuration);
    // Cumulative distance at every sample, for the peak windows.
    std::vector<double> cumulative(stop - first, 0.0);
    for (std::size_t k = first; k + 1 < stop; ++k) {
        double d = 0.0;
        if (s.valid[k] && s.valid[k + 1]) {
            d = std::hypot(s.x[k + 1] - s.x[k], s.y[k + 1] - s.y[k]);
            const double dt = s.t[k + 1] - s.t[k];
            const double meanSpeed = 0.5 * (s.speed[k] + s.speed[k + 1]);
            m.distance += d;
            m.validDuration += dt;
            m.zoneDistance[zoneOf(p.zoneEdges, meanSpeed)] += d;
            if (meanSpeed > p.hsrSpeed) m.hsrDistance += d;
            const double meanPower = 0.5 * (power[k - first] + power[k + 1 - first]);
            m.metabolicEnergy += meanPower * dt;
            if (meanPower > p.highPowerThreshold) m.highPowerDistance += d;
        }
        cumulative[k + 1 - first] = cumulative[k - first] + d;
    }
    m.metabolicPowerMean = m.validDuration > 0 ? m.metabolicEnergy / m.validDuration : 0.0;
    m.sprintCount = countEfforts(s, s.speed, first, last, p.sprintSpeed, +1.0, p.sprintMinDuration);
    m.accelerationCount = countEfforts(s, s.accel, first, last, p.accelThreshold, +1.0, p.accelMinDuration);
    m.decelerationCount = countEfforts(s, s.accel, first, last, -p.accelThreshold, -1.0, p.accelMinDuration);

    // Peak distance: windows [t_i, t_i + w] inside the period, the cumulative distance interpolated at
    // the window's end (two pointers: the end index only moves forward).
    const double tLast = s.t[last];
    for (std::size_t w = 0; w < p.peakWindows.size(); ++w) {
        const double window = p.peakWindows[w];
        if (!(window > 0) || tLast - s.t[first] < window - 1e-9) continue;
        double best = 0.0;
        std::size_t j = first;
        for (std::size_t i = first; i <= last && s.t[i] + window <= tLast + 1e-9; ++i) {
            const double tEnd = s.t[i] + window;
            while (j + 1 <= last && s.t[j + 1] <= tEnd) ++j;
            double atEnd = cumulative[j - first];
            if (j < last && s.t[j] < tEnd)
                atEnd += (cumulative[j + 1 - first] - cumulative[j - first]) * (tEnd - s.t[j]) / (s.t[j + 1] - s.t[j]);
            best = std::max(best, atEnd - cumulative[i - first]);
        }
        m.peakDistance[w] = best;
    }
    return m;
}

}  // namespace athlos::metrics
