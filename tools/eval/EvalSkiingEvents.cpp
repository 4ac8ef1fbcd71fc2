// athlos-eval-skiing-events [--seeds N] [--cycles N]
// Skiing events on the simulators with ground truth (plugins/events/SkiingSimulator.h), the figures of
// docs/validation/skiing-events.md:
//  - cross-country (xc-skiing-cycles defaults): cycle speed error (m/s and %), thrust start/end,
//    gliding start, pole plant and lift timing (mean ± SD), missed and extra cycles;
//  - ski mountaineering (skimo-phases defaults): cycle speed and slope error, elevation gain;
//  - alpine (alpine-turns defaults): turn switch timing, wrong sides, missed and extra turns.
// A true cycle is matched by the detected one whose thrust start is within 0.1 s (the first cycle
// merges with the initial stand and is not scored); a true turn by the detected one starting within
// 0.3 s.
#include "plugins/events/PoleEventDetector.h"
#include "plugins/events/SkiCycleAnalyzer.h"
#include "plugins/events/SkiImu.h"
#include "plugins/events/SkiingSimulator.h"
#include "plugins/events/TurnSwitchDetector.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

using namespace athlos::events;

namespace {

struct Stat {
    std::vector<double> v;
    void add(double x) { v.push_back(x); }
    double mean() const {
        double s = 0;
        for (double x : v) s += x;
        return v.empty() ? 0.0 : s / double(v.size());
    }
    double sd() const {
        const double m = mean();
        double s = 0;
        for (double x : v) s += (x - m) * (x - m);
        return v.size() > 1 ? std::sqrt(s / double(v.size() - 1)) : 0.0;
    }
    double maxAbs() const {
        double m = 0;
        for (double x : v) m = std::max(m, std::abs(x));
        return m;
    }
};

void split(const std::vector<double>& rows, std::vector<double>& acc, std::vector<double>& gyr) {
    for (std::size_t i = 0; i + 5 < rows.size(); i += 6)
        for (int a = 0; a < 3; ++a) {
            acc.push_back(rows[i + a]);
            gyr.push_back(rows[i + 3 + a]);
        }
}

struct CycleScores {
    Stat speed, speedPct, thrustStart, thrustEnd, glide, plant, lift, slopeDeg, elevation;
    int truth = 0, matched = 0, extra = 0;
    double gain = 0, gainTrue = 0;
};

void scoreCycles(const SkiCycleRecording& rec, const SkiCycleResult& r, CycleScores& s) {
    std::vector<bool> used(r.cycles.size(), false);
    for (std::size_t k = 1; k < rec.truth.size(); ++k) {
        const SkiCycleTruth& t = rec.truth[k];
        ++s.truth;
        for (std::size_t j = 0; j < r.cycles.size(); ++j) {
            const SkiCycle& c = r.cycles[j];
            if (used[j] || std::abs(c.thrustStart - t.thrustStart) >= 0.1) continue;
            used[j] = true;
            ++s.matched;
            s.speed.add(c.speed - t.speed);
            s.speedPct.add(100.0 * (c.speed - t.speed) / t.speed);
            s.thrustStart.add(1000.0 * (c.thrustStart - t.thrustStart));
            s.thrustEnd.add(1000.0 * (c.thrustEnd - t.thrustEnd));
            s.glide.add(1000.0 * (c.glideStart - t.glideStart));
            s.slopeDeg.add((c.slope - t.slope) * 180.0 / M_PI);
            s.elevation.add(c.elevation - t.elevation);
            s.gain += c.elevation;
            s.gainTrue += t.elevation;
            break;
        }
    }
    for (bool u : used) s.extra += u ? 0 : 1;
}

void line(const char* name, const Stat& s, const char* unit) {
    std::printf("  %-22s %+8.4f ± %7.4f %s (max |e| %.4f, n = %zu)\n", name, s.mean(), s.sd(), unit, s.maxAbs(),
                s.v.size());
}

}  // namespace

int main(int argc, char** argv) {
    int seeds = 10, count = 40;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--seeds"))
            seeds = std::atoi(argv[i + 1]);
        else if (!std::strcmp(argv[i], "--cycles"))
            count = std::atoi(argv[i + 1]);
    }
    if (seeds < 1 || count < 3) {
        std::fprintf(stderr, "usage: athlos-eval-skiing-events [--seeds N ≥ 1] [--cycles N ≥ 3]\n");
        return 2;
    }

    CycleScores xc;
    Stat plant, lift;
    int poleTruth = 0, poleFound = 0;
    for (int seed = 1; seed <= seeds; ++seed) {
        SkiCycleSimConfig config;
        config.seed = unsigned(seed);
        config.cycles = count;
        const SkiCycleRecording rec = simulateSkiCycles(config);
        std::vector<double> acc, gyr, pacc, pgyr;
        split(rec.ski, acc, gyr);
        const SkiCycleResult r =
            SkiCycleAnalyzer(SkiCycleParams{}).analyze(toSkiFrame(rec.t, acc, gyr, {1, 0, 0}, {0, 1, 0}));
        scoreCycles(rec, r, xc);
        split(rec.pole, pacc, pgyr);
        std::vector<double> norm;
        for (std::size_t i = 0; i + 2 < pacc.size(); i += 3)
            norm.push_back(std::sqrt(pacc[i] * pacc[i] + pacc[i + 1] * pacc[i + 1] + pacc[i + 2] * pacc[i + 2]));
        const auto events = detectPoleEvents(rec.t, norm, PoleEventParams{});
        for (const SkiCycleTruth& t : rec.truth) {
            ++poleTruth;
            for (const PoleEvents& e : events)
                if (std::abs(e.plant - t.polePlant) < 0.1) {
                    ++poleFound;
                    plant.add(1000.0 * (e.plant - t.polePlant));
                    lift.add(1000.0 * (e.lift - t.poleLift));
                    break;
                }
        }
    }
    std::printf("Cross-country diagonal stride: %d seeds × %d cycles, 200 Hz\n", seeds, count);
    std::printf("  cycles matched %d / %d, extra %d\n", xc.matched, xc.truth, xc.extra);
    line("cycle speed", xc.speed, "m/s");
    line("cycle speed", xc.speedPct, "%");
    line("thrust start", xc.thrustStart, "ms");
    line("thrust end", xc.thrustEnd, "ms");
    line("gliding start", xc.glide, "ms");
    std::printf("  pole plants found %d / %d\n", poleFound, poleTruth);
    line("pole plant", plant, "ms");
    line("pole lift", lift, "ms");

    CycleScores sk;
    for (int seed = 1; seed <= seeds; ++seed) {
        SkiCycleSimConfig config = skimoConfig(unsigned(seed));
        config.cycles = count;
        const SkiCycleRecording rec = simulateSkiCycles(config);
        std::vector<double> acc, gyr;
        split(rec.ski, acc, gyr);
        SkiCycleParams p;
        p.mode = SkiCycleParams::Mode::Mountaineering;
        p.maxCycle = 4.0;
        scoreCycles(rec, SkiCycleAnalyzer(p).analyze(toSkiFrame(rec.t, acc, gyr, {1, 0, 0}, {0, 1, 0})), sk);
    }
    std::printf("Ski mountaineering: %d seeds × %d cycles, 200 Hz\n", seeds, count);
    std::printf("  cycles matched %d / %d, extra %d\n", sk.matched, sk.truth, sk.extra);
    line("cycle speed", sk.speed, "m/s");
    line("slope", sk.slopeDeg, "deg");
    line("cycle elevation", sk.elevation, "m");
    std::printf("  elevation gain of matched cycles %.2f m (true %.2f m, %+.2f %%)\n", sk.gain, sk.gainTrue,
                100.0 * (sk.gain - sk.gainTrue) / sk.gainTrue);

    Stat sw;
    int turnsTruth = 0, turnsFound = 0, wrongSide = 0, extraTurns = 0;
    for (int seed = 1; seed <= seeds; ++seed) {
        AlpineSimConfig config;
        config.seed = unsigned(seed);
        config.turns = count;
        const AlpineRecording rec = simulateAlpine(config);
        std::vector<double> acc, gyr;
        split(rec.sacrum, acc, gyr);
        const auto turns = detectTurns(rec.t, gyr, acc, TurnSwitchParams{});
        std::vector<bool> used(turns.size(), false);
        for (std::size_t k = 1; k + 1 < rec.turns.size(); ++k) {
            ++turnsTruth;
            for (std::size_t j = 0; j < turns.size(); ++j)
                if (!used[j] && std::abs(turns[j].start - rec.turns[k].start) < 0.3) {
                    used[j] = true;
                    ++turnsFound;
                    sw.add(1000.0 * (turns[j].start - rec.turns[k].start));
                    wrongSide += turns[j].left != rec.turns[k].left;
                    break;
                }
        }
        for (bool u : used) extraTurns += u ? 0 : 1;
    }
    std::printf("Alpine (sacrum IMU, 26° slope, 20 m/s): %d seeds × %d turns, 200 Hz\n", seeds, count);
    std::printf("  turns matched %d / %d, extra %d, wrong side %d\n", turnsFound, turnsTruth, extraTurns, wrongSide);
    line("turn switch", sw, "ms");
    return 0;
}
