#include "plugins/metrics/MotionFromPositions.h"

#include <QString>
#include <algorithm>
#include <cmath>

namespace athlos::metrics {

using positioning::PositionFilter;
using positioning::PositionSamples;

namespace {

// Marks grid samples that fall inside an outage longer than maxGap (between consecutive fixes).
void markOutages(const std::vector<double>& fixTimes, double maxGap, MotionSeries& s) {
    std::size_t i = 0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        while (i + 1 < fixTimes.size() && fixTimes[i + 1] <= s.t[k]) ++i;
        const bool inGap = i + 1 < fixTimes.size() && s.t[k] > fixTimes[i] && fixTimes[i + 1] - fixTimes[i] > maxGap;
        s.valid[k] = inGap ? 0 : 1;
    }
}

// Raw motion: the fixes themselves, an invalid sample in the middle of every outage longer than maxGap,
// speed and forward acceleration by central differences within each gap-free segment.
MotionSeries rawMotion(const PositionSamples& in, double maxGap) {
    MotionSeries s;
    for (std::size_t k = 0; k < in.t.size(); ++k) {
        if (k > 0 && in.t[k] - in.t[k - 1] > maxGap) {
            s.t.push_back(0.5 * (in.t[k] + in.t[k - 1]));
            s.x.push_back(std::nan(""));
            s.y.push_back(std::nan(""));
            s.valid.push_back(0);
        }
        s.t.push_back(in.t[k]);
        s.x.push_back(in.p[k].x());
        s.y.push_back(in.p[k].y());
        s.valid.push_back(1);
    }
    const std::size_t n = s.t.size();
    s.speed.assign(n, 0.0);
    s.accel.assign(n, 0.0);
    // Central difference of f within the gap-free segment (one-sided at its ends).
    auto derivative = [&](std::size_t k, auto&& difference) {
        const std::size_t lo = (k > 0 && s.valid[k - 1]) ? k - 1 : k;
        const std::size_t hi = (k + 1 < n && s.valid[k + 1]) ? k + 1 : k;
        return lo == hi ? 0.0 : difference(lo, hi) / (s.t[hi] - s.t[lo]);
    };
    for (std::size_t k = 0; k < n; ++k)
        if (s.valid[k])
            s.speed[k] = derivative(
                k, [&](std::size_t lo, std::size_t hi) { return std::hypot(s.x[hi] - s.x[lo], s.y[hi] - s.y[lo]); });
    for (std::size_t k = 0; k < n; ++k)
        if (s.valid[k])
            s.accel[k] = derivative(k, [&](std::size_t lo, std::size_t hi) { return s.speed[hi] - s.speed[lo]; });
    return s;
}

// Standing still (see the header): flags grid samples whose window of fixes is consistent with one
// point, then holds each run of flagged samples at the mean of its fixes with speed and acceleration 0.
double holdStationary(const PositionSamples& in, const std::vector<char>& outlier, double r, const MotionParams& params,
                      MotionSeries& s) {
    if (!(params.stationaryWindow > 0) || !(r > 0)) return 0.0;
    // Prefix sums of the accepted fixes about the first fix (less cancellation).
    const std::size_t n = in.t.size();
    const Eigen::Vector2d origin = in.p.front();
    std::vector<double> count(n + 1, 0.0), sx(n + 1, 0.0), sy(n + 1, 0.0), sq(n + 1, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const bool use = !outlier[i];
        const Eigen::Vector2d d = in.p[i] - origin;
        count[i + 1] = count[i] + use;
        sx[i + 1] = sx[i] + (use ? d.x() : 0.0);
        sy[i + 1] = sy[i] + (use ? d.y() : 0.0);
        sq[i + 1] = sq[i] + (use ? d.squaredNorm() : 0.0);
    }
    auto range = [&](double a, double b) {
        return std::pair<std::size_t, std::size_t>(std::lower_bound(in.t.begin(), in.t.end(), a) - in.t.begin(),
                                                   std::upper_bound(in.t.begin(), in.t.end(), b) - in.t.begin());
    };
    const double half = 0.5 * params.stationaryWindow;
    std::vector<char> still(s.size(), 0);
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (!s.valid[k]) continue;
        const auto [lo, hi] = range(s.t[k] - half, s.t[k] + half);
        const double m = count[hi] - count[lo];
        if (m < 3) continue;
        const double mx = (sx[hi] - sx[lo]) / m, my = (sy[hi] - sy[lo]) / m;
        const double scatter = (sq[hi] - sq[lo]) - m * (mx * mx + my * my);
        still[k] = scatter / r <= chiSquareQuantile(params.stationaryConfidence, 2.0 * (m - 1.0));
    }
    double time = 0.0;
    for (std::size_t a = 0; a < s.size();) {
        if (!still[a]) {
            ++a;
            continue;
        }
        std::size_t b = a;
        while (b + 1 < s.size() && still[b + 1]) ++b;
        const auto [lo, hi] = range(s.t[a], s.t[b]);
        const double m = count[hi] - count[lo];
        if (m > 0) {
            const double mx = origin.x() + (sx[hi] - sx[lo]) / m, my = origin.y() + (sy[hi] - sy[lo]) / m;
            for (std::size_t k = a; k <= b; ++k) {
                s.x[k] = mx;
                s.y[k] = my;
                s.speed[k] = 0.0;
                s.accel[k] = 0.0;
            }
            time += s.t[b] - s.t[a];
        }
        a = b + 1;
    }
    return time;
}

}  // namespace

double chiSquareQuantile(double p, double k) {
    // z_p of the standard normal by Acklam's rational approximation is overkill here: the test uses
    // fixed confidences, so invert the normal CDF by bisection on std::erfc.
    double lo = -10.0, hi = 10.0;
    for (int i = 0; i < 100; ++i) {
        const double mid = 0.5 * (lo + hi);
        (0.5 * std::erfc(-mid / std::sqrt(2.0)) < p ? lo : hi) = mid;
    }
    const double z = 0.5 * (lo + hi), c = 2.0 / (9.0 * k);
    const double w = 1.0 - c + z * std::sqrt(c);
    return k * w * w * w;
}

Expected<MotionResult> motionFromPositions(const PositionSamples& in, const MotionParams& params,
                                           const MotionProgress& progress) {
    if (in.t.size() < 10)
        return makeError(QStringLiteral("%1 valid position fixes; session metrics need at least 10").arg(in.t.size()));
    bool anyStep = false;
    for (std::size_t k = 1; k < in.t.size() && !anyStep; ++k) anyStep = in.t[k] - in.t[k - 1] <= params.maxGap;
    if (!anyStep)
        return makeError(
            QStringLiteral("no two position fixes are within max_gap = %1 s of each other").arg(params.maxGap));
    MotionResult result;
    if (!params.filter) {
        result.series = rawMotion(in, params.maxGap);
        return result;
    }

    PositionFilter::Params fp;
    fp.filter = positioning::FilterKind::Ekf;
    fp.model = params.model;
    fp.smoothing = estimation::Smoothing::Rts;
    fp.noise = params.noise;
    if (params.estimateNoise) {
        const auto chunks = PositionFilter::noiseChunks(in, params.noiseChunk, params.noiseChunks);
        const auto estimate = PositionFilter::estimateNoise(fp, chunks, estimation::NoiseEstimator::Params{},
                                                            [&](double f) { return !progress || progress(0.7 * f); });
        if (estimate.cancelled) {
            result.cancelled = true;
            return result;
        }
        fp.noise = estimate.noise;
        result.estimatedNoise = estimate.values;
    }
    const std::vector<double> grid = PositionFilter::outputGrid(in.t.front(), in.t.back(), params.rate);
    const PositionFilter filter(fp);
    const auto r = filter.run(in, grid, [&](double f) { return !progress || progress(0.7 + 0.3 * f); });
    if (r.cancelled) {
        result.cancelled = true;
        return result;
    }
    MotionSeries& s = result.series;
    s.resize(r.t.size());
    for (std::size_t k = 0; k < r.t.size(); ++k) {
        const auto& st = r.states[k];
        s.t[k] = r.t[k];
        s.x[k] = st.x;
        s.y[k] = st.y;
        // A negative speed state is the same motion with heading + π: d|v|/dt = sign(v)·a.
        s.speed[k] = std::abs(st.speed);
        s.accel[k] = st.speed < 0 ? -st.accel : st.accel;
    }
    if (params.model == positioning::ModelKind::ConstantVelocity) {
        // The constant-velocity state has no acceleration: differentiate the smoothed speed.
        const std::size_t n = s.size();
        for (std::size_t k = 0; k < n; ++k) {
            const std::size_t lo = k > 0 ? k - 1 : k, hi = k + 1 < n ? k + 1 : k;
            s.accel[k] = hi > lo ? (s.speed[hi] - s.speed[lo]) / (s.t[hi] - s.t[lo]) : 0.0;
        }
    }
    markOutages(in.t, params.maxGap, s);
    result.stationaryTime = holdStationary(in, r.outlier, 0.5 * (fp.noise.ctra.rX + fp.noise.ctra.rY), params, s);
    for (char o : r.outlier) result.outliers += o;
    return result;
}

}  // namespace athlos::metrics
