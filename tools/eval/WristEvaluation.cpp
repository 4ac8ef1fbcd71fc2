#include "tools/eval/WristEvaluation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::events {

WristTrial simulateWristTrial(const WristSubject& subject, const WristWalkParams& base,
                              const WristCadenceParams& cadence) {
    WristTrial trial;
    trial.subject = subject;
    WristWalkParams p = base;
    p.seed = subject.seed;
    p.height = subject.height;
    trial.recording = simulateWristWalk(p);
    const WristWalkRecording& r = trial.recording;
    trial.windows = WristCadence(cadence).estimate(r.t.data(), r.imu.data(), r.t.size(), 6);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const CadenceWindow& w : trial.windows) {
        double c = 0.0, v = 0.0, walking = 0.0;
        int n = 0;
        for (auto it = std::lower_bound(r.tTruth.begin(), r.tTruth.end(), w.tStart);
             it != r.tTruth.end() && *it < w.tEnd; ++it) {
            const auto k = std::size_t(it - r.tTruth.begin());
            c += r.cadence[k];
            v += r.speed[k];
            walking += r.walking[k];
            ++n;
        }
        const bool all = n > 0 && walking == double(n);
        trial.trueCadence.push_back(all ? c / n : nan);
        trial.trueSpeed.push_back(all ? v / n : nan);
        trial.trueNonWalking.push_back(n > 0 && walking == 0.0 ? 1 : 0);
    }
    return trial;
}

ErrorSummary summarize(std::vector<double> e) {
    ErrorSummary s;
    s.n = e.size();
    if (e.empty()) return s;
    auto quantile = [](std::vector<double> v, double q) {
        std::sort(v.begin(), v.end());
        const double x = q * double(v.size() - 1);
        const auto i = std::size_t(std::floor(x));
        const double w = x - double(i);
        return i + 1 < v.size() ? (1.0 - w) * v[i] + w * v[i + 1] : v[i];
    };
    s.median = quantile(e, 0.5);
    s.q25 = quantile(e, 0.25);
    s.q75 = quantile(e, 0.75);
    for (double& x : e) x = std::abs(x);
    s.medianAbs = quantile(e, 0.5);
    return s;
}

void scoreCadence(const WristTrial& trial, CadenceScore& score) {
    for (std::size_t k = 0; k < trial.windows.size(); ++k) {
        const CadenceWindow& w = trial.windows[k];
        if (std::isfinite(trial.trueCadence[k])) {
            if (w.walking) {
                ++score.walkingDetected;
                score.errors.push_back(100.0 * (w.cadence - trial.trueCadence[k]) / trial.trueCadence[k]);
            } else {
                ++score.walkingMissed;
            }
        } else if (trial.trueNonWalking[k]) {
            if (w.walking)
                ++score.pauseAsWalking;
            else
                ++score.pauseRejected;
        }
    }
}

void speedRows(const std::vector<WristTrial>& trials, std::vector<WristFeatures>& x, std::vector<double>& v,
               std::vector<double>* cadenceTruth) {
    for (const WristTrial& trial : trials) {
        std::vector<std::size_t> rows;
        const auto features = wristSpeedFeatureRows(trial.windows, trial.recording.tBaro,
                                                    trial.recording.pressure.data(), 1, trial.subject.height, rows);
        for (std::size_t i = 0; i < features.size(); ++i) {
            const double speed = trial.trueSpeed[rows[i]];
            if (!std::isfinite(speed) || speed < 0.2) continue;
            x.push_back(features[i]);
            v.push_back(speed);
            if (cadenceTruth) cadenceTruth->push_back(trial.trueCadence[rows[i]]);
        }
    }
}

}  // namespace athlos::events
