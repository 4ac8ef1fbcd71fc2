// athlos-eval-session-metrics: the effect of filtering on the coach's metrics (docs/validation/
// session-metrics.md). A simulated match (simulate-team's TeamSimulator, exact positions = truth) is
// observed through a noise model, and the metrics of the whole match are computed from the truth, from
// the raw noisy positions (filter=none) and from the smoothed ones (filter=auto, the default). Prints a
// Markdown table of the errors over the players: distance (%), maximum speed (m/s), HSR distance (%),
// sprint, acceleration and deceleration counts, plus the time per player.
//
// Noise models: lps  — white σ per axis, outliers (probability p, 2–10 m off), as an LPS;
//               gnss — a first-order Gauss–Markov error (σ_gm, τ) plus white σ, as a 10 Hz GNSS receiver
//                      whose errors wander slowly (multipath, atmosphere), and outliers.
#include "plugins/metrics/MotionFromPositions.h"
#include "plugins/metrics/SessionMetrics.h"
#include "plugins/team/TeamSimulator.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace athlos;
using namespace athlos::metrics;

namespace {

struct Options {
    std::string noise = "lps";
    double sigma = 0.1;        // m, white noise per axis
    double sigmaGm = 0.5;      // m, Gauss–Markov error (gnss)
    double tau = 60.0;         // s, its correlation time
    double outliers = 0.005;   // probability per fix
    double duration = 2700.0;  // s
    int players = 22;
    std::uint64_t seed = 11;
    std::string model = "constant-velocity";
    bool verbose = false;
};

void usage() {
    std::fprintf(stderr,
                 "usage: athlos-eval-session-metrics [--noise lps|gnss] [--sigma M] [--sigma-gm M] [--tau S]\n"
                 "         [--outliers P] [--duration S] [--players N] [--seed S] [--model constant-velocity|ctra]\n"
                 "         [--verbose]\n");
}

positioning::PositionSamples observe(const std::vector<double>& t, const team::TeamSimulator::Track& track,
                                     const Options& o, std::mt19937_64& rng) {
    std::normal_distribution<double> white(0.0, o.sigma), unit(0.0, 1.0);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    positioning::PositionSamples fixes;
    double gx = 0, gy = 0;
    const double dt = t.size() > 1 ? t[1] - t[0] : 0.1;
    const double phi = std::exp(-dt / o.tau), drive = o.sigmaGm * std::sqrt(1 - phi * phi);
    if (o.noise == "gnss") gx = o.sigmaGm * unit(rng), gy = o.sigmaGm * unit(rng);
    for (std::size_t k = 0; k < t.size(); ++k) {
        if (o.noise == "gnss") {
            gx = phi * gx + drive * unit(rng);
            gy = phi * gy + drive * unit(rng);
        }
        double x = track.x[k] + gx + white(rng), y = track.y[k] + gy + white(rng);
        if (u(rng) < o.outliers) {
            const double r = 2.0 + 8.0 * u(rng), a = 6.283185307179586 * u(rng);
            x += r * std::cos(a);
            y += r * std::sin(a);
        }
        fixes.t.push_back(t[k]);
        fixes.p.emplace_back(x, y);
    }
    return fixes;
}

struct Errors {
    std::vector<double> distance, maxSpeed, hsr, sprints, accels, decels, seconds;
};

void add(Errors& e, const PeriodMetrics& truth, const PeriodMetrics& m, double seconds) {
    e.distance.push_back(100.0 * (m.distance / truth.distance - 1.0));
    e.maxSpeed.push_back(m.maxSpeed - truth.maxSpeed);
    e.hsr.push_back(truth.hsrDistance > 0 ? 100.0 * (m.hsrDistance / truth.hsrDistance - 1.0) : 0.0);
    e.sprints.push_back(m.sprintCount - truth.sprintCount);
    e.accels.push_back(m.accelerationCount - truth.accelerationCount);
    e.decels.push_back(m.decelerationCount - truth.decelerationCount);
    e.seconds.push_back(seconds);
}

std::string meanSd(const std::vector<double>& v, const char* format) {
    double mean = 0, sd = 0;
    for (double x : v) mean += x / double(v.size());
    for (double x : v) sd += (x - mean) * (x - mean) / double(std::max<std::size_t>(v.size() - 1, 1));
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, format, mean, std::sqrt(sd));
    return buffer;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        auto next = [&]() -> const char* {
            if (i + 1 >= argc) usage(), std::exit(2);
            return argv[++i];
        };
        if (!std::strcmp(argv[i], "--noise"))
            o.noise = next();
        else if (!std::strcmp(argv[i], "--sigma"))
            o.sigma = std::atof(next());
        else if (!std::strcmp(argv[i], "--sigma-gm"))
            o.sigmaGm = std::atof(next());
        else if (!std::strcmp(argv[i], "--tau"))
            o.tau = std::atof(next());
        else if (!std::strcmp(argv[i], "--outliers"))
            o.outliers = std::atof(next());
        else if (!std::strcmp(argv[i], "--duration"))
            o.duration = std::atof(next());
        else if (!std::strcmp(argv[i], "--players"))
            o.players = std::atoi(next());
        else if (!std::strcmp(argv[i], "--seed"))
            o.seed = std::strtoull(next(), nullptr, 10);
        else if (!std::strcmp(argv[i], "--model"))
            o.model = next();
        else if (!std::strcmp(argv[i], "--verbose"))
            o.verbose = true;
        else
            return usage(), 2;
    }
    if (o.noise != "lps" && o.noise != "gnss") return usage(), 2;
    team::TeamSimulator::Params sp;
    sp.seed = o.seed;
    sp.duration = o.duration;
    const auto match = team::TeamSimulator::simulate(sp);
    std::mt19937_64 rng(o.seed * 31 + 7);
    const MetricsParams params;
    MotionParams raw, smoothed;
    raw.filter = false;
    smoothed.model =
        o.model == "ctra" ? positioning::ModelKind::Unconstrained : positioning::ModelKind::ConstantVelocity;
    Errors rawErrors, smoothedErrors;
    double truthDistance = 0, truthSprints = 0, truthAccels = 0;
    const int players = std::min<int>(o.players, static_cast<int>(match.tracks.size()));
    for (int p = 0; p < players; ++p) {
        positioning::PositionSamples exact;
        exact.t = match.t;
        for (std::size_t k = 0; k < match.t.size(); ++k)
            exact.p.emplace_back(match.tracks[p].x[k], match.tracks[p].y[k]);
        const auto truthMotion = motionFromPositions(exact, raw);
        const auto fixes = observe(match.t, match.tracks[p], o, rng);
        const auto t0 = std::chrono::steady_clock::now();
        const auto rawMotion = motionFromPositions(fixes, raw);
        const auto t1 = std::chrono::steady_clock::now();
        const auto smoothMotion = motionFromPositions(fixes, smoothed);
        const auto t2 = std::chrono::steady_clock::now();
        if (!truthMotion || !rawMotion || !smoothMotion) return std::fprintf(stderr, "motion failed\n"), 1;
        const double end = match.t.back();
        const PeriodMetrics truth = computePeriod(truthMotion->series, 0, end, params);
        truthDistance += truth.distance / players;
        truthSprints += double(truth.sprintCount) / players;
        truthAccels += double(truth.accelerationCount) / players;
        if (o.verbose)
            std::printf("player %d: truth %.0f m, %.2f m/s, %d acc; smoothed %+.2f %%, %+.2f m/s, %d acc\n", p,
                        truth.distance, truth.maxSpeed, truth.accelerationCount,
                        100 * (computePeriod(smoothMotion->series, 0, end, params).distance / truth.distance - 1),
                        computePeriod(smoothMotion->series, 0, end, params).maxSpeed - truth.maxSpeed,
                        computePeriod(smoothMotion->series, 0, end, params).accelerationCount);
        add(rawErrors, truth, computePeriod(rawMotion->series, 0, end, params),
            std::chrono::duration<double>(t1 - t0).count());
        add(smoothedErrors, truth, computePeriod(smoothMotion->series, 0, end, params),
            std::chrono::duration<double>(t2 - t1).count());
    }
    std::printf(
        "Simulated match: %d players × %.0f s at 10 Hz (seed %llu); truth per player: %.0f m, %.1f sprints, "
        "%.1f accelerations.\n",
        players, o.duration, static_cast<unsigned long long>(o.seed), truthDistance, truthSprints, truthAccels);
    if (o.noise == "lps")
        std::printf("Noise: lps, white σ = %.3g m per axis, outliers p = %.3g.\n\n", o.sigma, o.outliers);
    else
        std::printf("Noise: gnss, Gauss–Markov σ = %.3g m, τ = %.3g s, white σ = %.3g m, outliers p = %.3g.\n\n",
                    o.sigmaGm, o.tau, o.sigma, o.outliers);
    std::printf(
        "| positions | distance error %% | max speed error m/s | HSR error %% | sprints Δ | accelerations Δ | "
        "decelerations Δ | s per player |\n|---|---|---|---|---|---|---|---|\n");
    for (int row = 0; row < 2; ++row) {
        const Errors& e = row ? smoothedErrors : rawErrors;
        std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", row ? "smoothed (filter=auto)" : "raw (filter=none)",
                    meanSd(e.distance, "%+.2f ± %.2f").c_str(), meanSd(e.maxSpeed, "%+.2f ± %.2f").c_str(),
                    meanSd(e.hsr, "%+.1f ± %.1f").c_str(), meanSd(e.sprints, "%+.1f ± %.1f").c_str(),
                    meanSd(e.accels, "%+.1f ± %.1f").c_str(), meanSd(e.decels, "%+.1f ± %.1f").c_str(),
                    meanSd(e.seconds, "%.2f ± %.2f").c_str());
    }
    return 0;
}
