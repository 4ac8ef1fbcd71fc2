#include "plugins/positioning/TrackRunSimulator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::positioning {

namespace {

// Smooth 0 → 1 transition (lane changes take a couple of seconds, without lateral jerk jumps).
double smoothStep(double u) {
    u = std::clamp(u, 0.0, 1.0);
    return 0.5 - 0.5 * std::cos(std::numbers::pi * u);
}

struct LaneChange {
    double startDistance = 0.0;  // m along the running line
    double duration = 0.0;       // s
    double delta = 0.0;          // m of lateral offset change
    double startTime = -1.0;     // filled when it begins
};

}  // namespace

TrackRunSimulator::Result TrackRunSimulator::simulate(const Params& P) {
    std::mt19937_64 rng(P.seed);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    const TrackGeometry& track = P.track;
    const double laneWidth =
        track.kind() == TrackGeometry::Kind::Oval ? track.ovalParams().laneWidth : track.polylineParams().laneWidth;

    // Lane plan: 800 m (and longer) break to lane 1 after the first bend; overtakes one lane out.
    std::vector<LaneChange> changes;
    const double startOffset = track.laneOffset(P.lane);
    if (P.laneChanges) {
        if (P.distance > 400.0 && P.lane > 1)
            changes.push_back(
                {100.0 + 20.0 * uniform(rng), 3.0 + 2.0 * uniform(rng), track.laneOffset(1) - startOffset});
        const int overtakes = std::poisson_distribution<int>(P.distance / 400.0)(rng);
        for (int i = 0; i < overtakes; ++i) {
            const double at = 140.0 + (P.distance - 200.0) * uniform(rng);
            const double hold = 20.0 + 40.0 * uniform(rng);
            changes.push_back({at, 1.5 + uniform(rng), laneWidth});
            changes.push_back({at + hold, 1.5 + uniform(rng), -laneWidth});
        }
        std::sort(changes.begin(), changes.end(),
                  [](const LaneChange& a, const LaneChange& b) { return a.startDistance < b.startDistance; });
    }

    // Integrate the motion at 1 ms.
    const double dt = 1e-3;
    const double tau = 3.0;  // s, OU correlation time of the speed fluctuation
    double t = 0.0, run = 0.0, sRef = 0.0, fluctuation = 0.0, v = 0.0, finishTime = -1.0;
    std::vector<double> ts, xs, ys;
    const double endGuess = P.preStart + P.distance / std::max(P.topSpeed * 0.6, 1.0) + P.postFinish + 10.0;
    ts.reserve(static_cast<std::size_t>(endGuess / dt));
    xs.reserve(ts.capacity());
    ys.reserve(ts.capacity());
    while (true) {
        double offset = startOffset;
        for (auto& c : changes) {
            if (run < c.startDistance) break;
            if (c.startTime < 0) c.startTime = t;
            offset += c.delta * smoothStep((t - c.startTime) / c.duration);
        }
        const TrackPoint pt = track.pointAt(sRef, offset);
        ts.push_back(t);
        xs.push_back(pt.position.x());
        ys.push_back(pt.position.y());
        if (finishTime >= 0 && t >= finishTime + P.postFinish) break;

        // Speed: start acceleration, fatigue, fluctuation; deceleration after the finish.
        fluctuation += -fluctuation / tau * dt + P.speedSd * std::sqrt(2.0 / tau * dt) * gauss(rng);
        if (t < P.preStart) {
            v = 0.0;
        } else if (finishTime < 0) {
            const double rise = 1.0 - std::exp(-(t - P.preStart) / P.accelTime);
            v = rise * (P.topSpeed * (1.0 - P.fatigue * run / P.distance) + fluctuation);
        } else {
            v = std::max(2.0, v - 1.5 * dt);
        }
        const double ds = v * dt;
        run += ds;
        // Along a line at offset d right of the reference: ds_ref = ds / (1 + κ_ref d).
        const double kappaRef = track.pointAt(sRef, 0.0).curvature;
        sRef += ds / (1.0 + kappaRef * offset);
        if (finishTime < 0 && run >= P.distance) finishTime = t;
        t += dt;
    }

    Result result;
    // Truth on multiples of 1/truthRate; speed and heading from central differences at 1 ms.
    const std::size_t n = ts.size();
    const auto stride = static_cast<std::size_t>(std::lround(1.0 / (P.truthRate * dt)));
    for (std::size_t k = 0; k < n; k += stride) {
        const std::size_t a = k > 0 ? k - 1 : k, b = std::min(k + 1, n - 1);
        const double vx = (xs[b] - xs[a]) / (ts[b] - ts[a]), vy = (ys[b] - ys[a]) / (ts[b] - ts[a]);
        result.truth.t.push_back(std::round(ts[k] * P.truthRate) / P.truthRate);
        result.truth.x.push_back(xs[k]);
        result.truth.y.push_back(ys[k]);
        result.truth.speed.push_back(std::hypot(vx, vy));
        result.truth.heading.push_back(result.truth.speed.back() > 1e-6 ? std::atan2(vy, vx)
                                                                        : track.headingAt({xs[k], ys[k]}));
    }
    const double tEnd = ts.back();

    // Outages: a Poisson number of intervals after the gun, durations uniform in [min, max].
    std::vector<std::pair<double, double>> outages;
    const int outageCount = std::poisson_distribution<int>(P.outagesPer400m * P.distance / 400.0)(rng);
    for (int i = 0; i < outageCount; ++i) {
        const double length = P.outageMin + (P.outageMax - P.outageMin) * uniform(rng);
        const double begin = P.preStart + uniform(rng) * std::max(0.0, tEnd - P.preStart - length - 1.0);
        outages.emplace_back(begin, begin + length);
    }

    // Sampling: intervals 10 ms + 1.5 τ ms (τ ~ Poisson(20)); bursts of outliers as a two-state chain
    // with the requested fraction and mean burst length.
    std::poisson_distribution<int> poisson(P.intervalPoisson);
    const double pEnd = 1.0 / std::max(P.outlierBurst, 1.0);
    const double f = std::clamp(P.outlierFraction, 0.0, 0.99);
    const double pStart = f * pEnd / std::max(1.0 - f, 1e-9);
    bool inBurst = false;
    const double sx = std::sqrt(P.noiseVarX), sy = std::sqrt(P.noiseVarY);
    for (double tm = P.intervalBase * uniform(rng); tm <= tEnd; tm += P.intervalBase + P.intervalScale * poisson(rng)) {
        inBurst = inBurst ? uniform(rng) >= pEnd : uniform(rng) < pStart;
        const bool out =
            std::any_of(outages.begin(), outages.end(), [&](const auto& o) { return tm >= o.first && tm < o.second; });
        const double ex = gauss(rng), ey = gauss(rng), ox = gauss(rng), oy = gauss(rng);
        if (out) continue;
        const auto k = std::min(static_cast<std::size_t>(tm / dt), n - 2);
        const double u = (tm - ts[k]) / dt;
        Eigen::Vector2d p((1 - u) * xs[k] + u * xs[k + 1], (1 - u) * ys[k] + u * ys[k + 1]);
        p += inBurst ? Eigen::Vector2d(P.outlierSd * ox, P.outlierSd * oy) : Eigen::Vector2d(sx * ex, sy * ey);
        result.measured.t.push_back(std::round(tm * 1e6) / 1e6);
        result.measured.p.push_back(p);
        result.outlier.push_back(inBurst ? 1 : 0);
    }
    for (const auto& o : outages) result.outageSeconds += o.second - o.first;
    return result;
}

Eigen::Vector2d TrackRunSimulator::truthAt(const Truth& truth, double t) {
    const auto it = std::lower_bound(truth.t.begin(), truth.t.end(), t);
    if (it == truth.t.begin()) return {truth.x.front(), truth.y.front()};
    if (it == truth.t.end()) return {truth.x.back(), truth.y.back()};
    const std::size_t k = static_cast<std::size_t>(it - truth.t.begin());
    const double u = (t - truth.t[k - 1]) / (truth.t[k] - truth.t[k - 1]);
    return {(1 - u) * truth.x[k - 1] + u * truth.x[k], (1 - u) * truth.y[k - 1] + u * truth.y[k]};
}

double TrackRunSimulator::rmse(const Truth& truth, const std::vector<double>& t,
                               const std::vector<Eigen::Vector2d>& p) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        if (t[k] < truth.t.front() || t[k] > truth.t.back()) continue;
        sum += (p[k] - truthAt(truth, t[k])).squaredNorm();
        ++count;
    }
    return count ? std::sqrt(sum / double(count)) : 0.0;
}

}  // namespace athlos::positioning
