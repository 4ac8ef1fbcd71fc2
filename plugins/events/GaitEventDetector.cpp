#include "plugins/events/GaitEventDetector.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::events {

const char* gaitEventName(GaitEventType type) {
    switch (type) {
        case GaitEventType::TerminalContact:
            return "tc";
        case GaitEventType::InitialContact:
            return "ic";
        case GaitEventType::MinimumVelocity:
            return "min_vel";
    }
    return "";
}

GaitEventDetector::GaitEventDetector(Params params, int swingSign) : params_(params), sign_(swingSign < 0 ? -1 : 1) {}

void GaitEventDetector::reset() { state_ = State{}; }

// A sample is judged once the later half of its peak window and the IC window after it are known.
double GaitEventDetector::delay() const { return std::max(0.5 * params_.minStrideTime, params_.icWindow); }

void GaitEventDetector::update(double t, double gyrMl, double gyrNorm) {
    State& s = state_;
    // Moving average of the norm over restWindow: mid-stance is a stretch of rest, not one quiet sample.
    s.normWindow.push_back({t, gyrNorm});
    s.normSum += gyrNorm;
    while (s.normWindow.size() > 1 && s.normWindow.front().first <= t - params_.restWindow) {
        s.normSum -= s.normWindow.front().second;
        s.normWindow.pop_front();
    }
    s.buffer.push_back({t, sign_ * gyrMl, s.normSum / double(s.normWindow.size())});
    evaluate(false);
    // Keep what the searches back from a peak can reach: the previous IC (≤ one stride) and TC.
    const double horizon = params_.maxStrideTime + params_.tcWindow + 2.0 * delay();
    while (!s.buffer.empty() && s.buffer.front().t < t - horizon) s.buffer.pop_front();
}

void GaitEventDetector::updateBatch(const double* t, const double* gyr, std::size_t rows, std::size_t stride,
                                    const Eigen::Vector3d& mlAxis) {
    for (std::size_t k = 0; k < rows; ++k) {
        const Eigen::Map<const Eigen::Vector3d> g(gyr + k * stride);
        update(t[k], mlAxis.dot(g), g.norm());
    }
    finish();
}

void GaitEventDetector::finish() { evaluate(true); }

void GaitEventDetector::evaluate(bool flushing) {
    State& s = state_;
    if (s.buffer.empty()) return;
    const double tNow = s.buffer.back().t;
    const double half = 0.5 * params_.minStrideTime;
    for (std::size_t c = 0; c < s.buffer.size(); ++c) {
        const auto& sc = s.buffer[c];
        if (sc.t <= s.checkedUntil) continue;
        if (!flushing && sc.t > tNow - delay()) break;
        s.checkedUntil = sc.t;
        if (sc.w < params_.swingThreshold || sc.t - s.lastPeakT < params_.minStrideTime) continue;
        bool peak = true;
        for (std::size_t j = c; j-- > 0 && s.buffer[j].t >= sc.t - half;)
            if (s.buffer[j].w >= sc.w) {
                peak = false;
                break;
            }
        for (std::size_t j = c + 1; peak && j < s.buffer.size() && s.buffer[j].t <= sc.t + half; ++j)
            if (s.buffer[j].w > sc.w) peak = false;
        if (peak) confirmPeak(c);
    }
}

void GaitEventDetector::confirmPeak(std::size_t c) {
    State& s = state_;
    const auto& b = s.buffer;
    const double tc0 = b[c].t;
    s.lastPeakT = tc0;

    // TC: most negative ω_ml in the window before the swing peak (after the previous IC).
    const double tcFrom = std::max(tc0 - params_.tcWindow, s.havePreviousIc ? s.previousIcT : -1e300);
    std::size_t tc = c;
    for (std::size_t j = c; j-- > 0 && b[j].t >= tcFrom;)
        if (b[j].w < b[tc].w) tc = j;
    // IC: most negative ω_ml in the window after the swing peak.
    std::size_t ic = c;
    for (std::size_t j = c + 1; j < b.size() && b[j].t <= tc0 + params_.icWindow; ++j)
        if (b[j].w < b[ic].w) ic = j;
    // A minimum on the edge of the data is a cut-off slope, not a peak.
    const bool tcValid = tc != c && tc != 0;
    const bool icValid = ic != c && ic + 1 < b.size();

    double restNorm = std::numeric_limits<double>::quiet_NaN();
    double tMinVel = 0.0;
    if (s.havePreviousIc && tcValid) {
        for (std::size_t j = 0; j < tc; ++j) {
            if (b[j].t <= s.previousIcT) continue;
            if (!(b[j].norm >= restNorm)) {
                restNorm = b[j].norm;
                tMinVel = b[j].t;
            }
        }
        if (std::isfinite(restNorm)) s.events.push_back({tMinVel, GaitEventType::MinimumVelocity});
    }
    if (tcValid) s.events.push_back({b[tc].t, GaitEventType::TerminalContact});
    if (!icValid) {
        s.havePreviousIc = false;
        s.previousStrideTime = 0.0;
        return;
    }
    const double tIc = b[ic].t;
    s.events.push_back({tIc, GaitEventType::InitialContact});

    const double duration = tIc - s.previousIcT;
    if (s.havePreviousIc && tcValid && std::isfinite(restNorm) && duration >= params_.minStrideTime &&
        duration <= params_.maxStrideTime) {
        GaitStride stride;
        stride.tStart = s.previousIcT;
        stride.tEnd = tIc;
        stride.tMinVel = tMinVel;
        stride.tTc = b[tc].t;
        stride.swingPeak = b[c].w;
        stride.restGyr = restNorm;
        // Quality in [0, 1]: a clear swing peak, a foot at rest in mid-stance, and a stride time
        // like the previous one; the geometric mean keeps any single weak cue visible.
        const double th = params_.swingThreshold;
        const double peakQ = 1.0 - std::exp(-(stride.swingPeak - th) / th);
        const double restQ = std::exp(-restNorm / params_.restScale);
        double regularQ = 1.0;
        if (s.previousStrideTime > 0.0) {
            const double z = (duration - s.previousStrideTime) / (params_.regularityTolerance * s.previousStrideTime);
            regularQ = std::exp(-0.5 * z * z);
        }
        stride.confidence = std::clamp(std::cbrt(std::max(0.0, peakQ) * restQ * regularQ), 0.0, 1.0);
        s.strides.push_back(stride);
        s.previousStrideTime = duration;
    } else {
        s.previousStrideTime = 0.0;
    }
    s.havePreviousIc = true;
    s.previousIcT = tIc;
}

int GaitEventDetector::swingSign(const double* t, const double* gyr, std::size_t rows, std::size_t stride,
                                 const Eigen::Vector3d& mlAxis) {
    const auto ml = [&](std::size_t k) { return mlAxis.dot(Eigen::Map<const Eigen::Vector3d>(gyr + k * stride)); };
    double lo = 0.0, hi = 0.0, sum = 0.0;
    std::size_t first = 0;
    for (std::size_t k = 0; k < rows; ++k) {
        sum += ml(k);
        while (t[k] - t[first] > 0.25) sum -= ml(first++);
        const double mean = sum / double(k - first + 1);
        lo = std::min(lo, mean);
        hi = std::max(hi, mean);
    }
    return hi >= -lo ? 1 : -1;
}

}  // namespace athlos::events
