#include "tools/eval/ScrumEvaluation.h"

#include "core/processing/OutputStreams.h"

#include <algorithm>
#include <cmath>

namespace athlos::activity {

ScrumScore evaluateScrums(const RugbySimulator::Result& sim, const TorsoPitch::Params& pitchParams,
                          const ScrumDetector::Params& detectorParams) {
    ScrumScore score;
    StreamInfo info;
    info.name = info.kind = QStringLiteral("imu");
    info.columns = columnsOf(RugbySimulator::imuColumns(),
                             {QStringLiteral("m/s^2"), QStringLiteral("m/s^2"), QStringLiteral("m/s^2"),
                              QStringLiteral("rad/s"), QStringLiteral("rad/s"), QStringLiteral("rad/s")});
    auto busy = [&](double t) {
        for (const auto& s : sim.scrums)
            if (t > s.tStart - 8.0 && t < s.tEnd + 2.0) return true;
        for (const auto& k : sim.tackles)
            if (t > k.t - 1.0 && t < k.t + 4.0) return true;
        return false;
    };
    std::vector<ScrumDetector::Player> players;
    double se = 0.0, n = 0.0, seRun = 0.0, nRun = 0.0;
    for (const auto& track : sim.tracks) {
        auto pitch = TorsoPitch::compute(info, track.imu, pitchParams);
        if (!pitch) return score;
        for (std::size_t i = 0; i < pitch->size(); ++i) {
            const double t = track.imu.t[i];
            if (t < 6.0 || t > track.imu.t.back() - 2.0) continue;  // after the standing period, before the end
            const double e = (*pitch)[i] - track.pitch[i];
            se += e * e;
            n += 1.0;
            if (!busy(t)) seRun += e * e, nRun += 1.0;
        }
        players.push_back({track.imu.t, std::move(*pitch), sim.tPosition, track.x, track.y});
    }
    score.pitchRmse = std::sqrt(se / std::max(n, 1.0));
    score.pitchRmseRunning = std::sqrt(seRun / std::max(nRun, 1.0));
    auto detected = ScrumDetector::detect(players, detectorParams);
    if (!detected) return score;
    score.scrums = int(sim.scrums.size());
    score.detections = int(detected->scrums.size());
    auto overlaps = [](double a0, double a1, double b0, double b1) { return a0 < b1 && b0 < a1; };
    int matched = 0;
    for (const auto& s : sim.scrums) {
        for (const auto& d : detected->scrums) {
            if (!overlaps(s.tStart, s.tEnd, d.tStart, d.tEnd)) continue;
            ++score.found;
            ++matched;
            score.startError += std::abs(d.tStart - s.tStart);
            score.endError += std::abs(d.tEnd - s.tEnd);
            break;
        }
    }
    if (matched) score.startError /= matched, score.endError /= matched;
    for (const auto& d : detected->scrums)
        for (const auto& s : sim.scrums)
            if (overlaps(s.tStart, s.tEnd, d.tStart, d.tEnd)) {
                ++score.correct;
                break;
            }
    score.minTopInScrum = 1e9;
    for (std::size_t g = 0; g < detected->t.size(); ++g) {
        const double t = detected->t[g], v = detected->top[g];
        if (!std::isfinite(v)) continue;
        bool inside = false, near = false;
        for (const auto& s : sim.scrums) {
            inside = inside || (t > s.tStart + 1.5 && t < s.tEnd - 0.5);
            near = near || (t > s.tStart - 2.0 && t < s.tEnd + 2.0);
        }
        if (inside) score.minTopInScrum = std::min(score.minTopInScrum, v);
        if (!near && t > 6.0) score.maxTopOutside = std::max(score.maxTopOutside, v);
    }
    return score;
}

}  // namespace athlos::activity
