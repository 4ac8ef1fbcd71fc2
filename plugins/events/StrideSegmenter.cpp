#include "plugins/events/StrideSegmenter.h"

#include "plugins/events/GaitEventDetector.h"

#include <algorithm>
#include <cmath>

namespace athlos::events {

std::vector<double> meanGyroNorm(const double* t, const double* gyr, std::size_t rows, std::size_t stride,
                                 double window) {
    std::vector<double> norm(rows), mean(rows);
    for (std::size_t k = 0; k < rows; ++k) {
        const double* g = gyr + k * stride;
        norm[k] = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    }
    // Prefix sums; the window [t − w/2, t + w/2] is found with two moving indices.
    std::vector<double> prefix(rows + 1, 0.0);
    for (std::size_t k = 0; k < rows; ++k) prefix[k + 1] = prefix[k] + norm[k];
    std::size_t lo = 0, hi = 0;
    for (std::size_t k = 0; k < rows; ++k) {
        while (t[lo] < t[k] - 0.5 * window) ++lo;
        if (hi < k) hi = k;
        while (hi + 1 < rows && t[hi + 1] <= t[k] + 0.5 * window) ++hi;
        mean[k] = (prefix[hi + 1] - prefix[lo]) / double(hi + 1 - lo);
    }
    return mean;
}

namespace {

// Index of the smallest value of v in [from, to] (inclusive); to < from: npos.
std::size_t argMin(const std::vector<double>& v, std::size_t from, std::size_t to) {
    if (to < from) return std::size_t(-1);
    std::size_t best = from;
    for (std::size_t k = from; k <= to; ++k)
        if (v[k] < v[best]) best = k;
    return best;
}

struct MidStance {
    std::size_t k = std::size_t(-1);
    bool valid = false;
};

}  // namespace

StrideSegmentation segmentStrides(const StrideSegmentationParams& p, const double* t, const double* gyr,
                                  std::size_t rows, std::size_t stride) {
    StrideSegmentation out;
    if (rows < 3) return out;
    out.swingSign =
        p.swingSign ? (p.swingSign < 0 ? -1 : 1) : GaitEventDetector::swingSign(t, gyr, rows, stride, p.mlAxis);
    std::vector<double> w(rows);
    for (std::size_t k = 0; k < rows; ++k)
        w[k] = out.swingSign * p.mlAxis.dot(Eigen::Map<const Eigen::Vector3d>(gyr + k * stride));
    const std::vector<double> rest = meanGyroNorm(t, gyr, rows, stride, p.restWindow);

    // Swing peaks: the largest ω_ml within ±minStrideTime/2, at least minStrideTime apart.
    const double half = 0.5 * p.minStrideTime;
    std::vector<std::size_t> peaks;
    double lastPeak = -1e300;
    for (std::size_t k = 0; k < rows; ++k) {
        if (w[k] < p.swingThreshold || t[k] - lastPeak < p.minStrideTime) continue;
        bool peak = true;
        for (std::size_t j = k; peak && j-- > 0 && t[j] >= t[k] - half;) peak = w[j] < w[k];
        for (std::size_t j = k + 1; peak && j < rows && t[j] <= t[k] + half; ++j) peak = w[j] <= w[k];
        if (!peak) continue;
        peaks.push_back(k);
        lastPeak = t[k];
    }
    out.swings = peaks.size();
    if (peaks.empty()) return out;

    // Between two swings the foot stood on the ground, so the quietest instant there is the
    // mid-stance however much the foot still rolls (running: 2–4 rad/s over restWindow). Before the
    // first swing and after the last one the data may start or end in motion: a minimum there must be
    // quiet (at most restThreshold), not one cut off by the edge.
    const auto accept = [&](std::size_t k) { return MidStance{k, k != std::size_t(-1) && k > 0 && k + 1 < rows}; };
    const auto acceptAtEdge = [&](std::size_t k) {
        MidStance m = accept(k);
        m.valid = m.valid && rest[k] <= p.restThreshold;
        return m;
    };
    const auto firstAtOrAfter = [&](double time) { return std::size_t(std::lower_bound(t, t + rows, time) - t); };
    const auto lastAtOrBefore = [&](double time) {
        const auto k = std::size_t(std::upper_bound(t, t + rows, time) - t);
        return k == 0 ? std::size_t(-1) : k - 1;
    };
    // before[i] / after[i]: the mid-stance that starts / ends the stride of swing i.
    std::vector<MidStance> before(peaks.size()), after(peaks.size());
    {
        const std::size_t p0 = peaks.front();
        const std::size_t from = firstAtOrAfter(t[p0] - p.stanceSearch);
        if (t[p0] - p.stanceSearch >= t[0]) before.front() = acceptAtEdge(argMin(rest, from, p0 - 1));
        const std::size_t pn = peaks.back();
        const std::size_t to = lastAtOrBefore(t[pn] + p.stanceSearch);
        if (t[pn] + p.stanceSearch <= t[rows - 1]) after.back() = acceptAtEdge(argMin(rest, pn + 1, to));
    }
    // Initial contact after / toe-off before a swing peak (the event definitions of GaitEventDetector).
    const auto icAfter = [&](std::size_t peak, std::size_t limit) {
        return argMin(w, peak + 1, std::min(limit, lastAtOrBefore(t[peak] + p.icWindow)));
    };
    const auto tcBefore = [&](std::size_t peak, std::size_t limit) {
        return argMin(w, std::max(limit, firstAtOrAfter(t[peak] - p.tcWindow)), peak - 1);
    };
    for (std::size_t i = 0; i + 1 < peaks.size(); ++i) {
        const std::size_t a = peaks[i], b = peaks[i + 1];
        // The longest standing stretch between the swings (mean norm below staticThreshold).
        std::size_t standFrom = 0, standTo = 0;
        for (std::size_t k = a + 1; k < b;) {
            if (rest[k] >= p.staticThreshold) {
                ++k;
                continue;
            }
            std::size_t e = k;
            while (e + 1 < b && rest[e + 1] < p.staticThreshold) ++e;
            if (t[e] - t[k] > t[standTo] - t[standFrom]) standFrom = k, standTo = e;
            k = e + 1;
        }
        if (standTo > standFrom && t[standTo] - t[standFrom] >= p.standDuration) {
            // A pause: the stride before ends where the foot comes to rest, the next starts where it
            // leaves, so that neither stride time contains the pause.
            const double edge = 0.5 * p.standDuration;
            after[i] = accept(argMin(rest, standFrom, lastAtOrBefore(t[standFrom] + edge)));
            before[i + 1] = accept(argMin(rest, firstAtOrAfter(t[standTo] - edge), standTo));
        } else if (t[b] - t[a] <= p.maxStrideTime) {
            after[i] = before[i + 1] = accept(argMin(rest, a + 1, b - 1));
        } else {  // long gap without a clear stand (shuffling, turning on the spot)
            after[i] = accept(argMin(rest, a + 1, std::min(lastAtOrBefore(t[a] + p.stanceSearch), b - 1)));
            before[i + 1] = accept(argMin(rest, std::max(firstAtOrAfter(t[b] - p.stanceSearch), a + 1), b - 1));
        }
    }
    for (std::size_t i = 0; i < peaks.size(); ++i) {
        if (!before[i].valid || !after[i].valid) continue;
        StrideSegment s;
        s.start = before[i].k;
        s.end = after[i].k;
        s.peak = peaks[i];
        s.restStart = rest[s.start];
        s.restEnd = rest[s.end];
        s.tc = tcBefore(s.peak, s.start);
        s.ic = icAfter(s.peak, s.end);
        if (s.tc == std::size_t(-1) || s.ic == std::size_t(-1)) continue;
        out.strides.push_back(s);
    }
    return out;
}

}  // namespace athlos::events
