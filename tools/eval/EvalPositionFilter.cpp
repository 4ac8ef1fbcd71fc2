// athlos-eval-position-filter: reproduces the filter comparison of seed 001 / thesis §4.2 on
// simulated 400 m and 800 m runs. Noise parameters and α are estimated per filter on separate
// training runs (no ground truth), then U-, P-, M-EKF and U-, P-, M-SRUKF filter the test runs onto a
// 10 Hz grid. Prints a Markdown table: RMSE mean ± SD, regression slope of output vs input RMSE,
// mean error by time since the last measurement, relative computation time (U-EKF = 100 %).
#include "plugins/positioning/PositionFilter.h"
#include "plugins/positioning/TrackRunSimulator.h"

#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

using namespace athlos;
using namespace athlos::positioning;

namespace {

struct Options {
    int runs = 30;
    int train = 4;
    std::uint64_t seed = 2016;
    bool quick = false;
    std::string smoother = "none";
};

void usage() {
    std::fprintf(
        stderr,
        "usage: athlos-eval-position-filter [--runs N] [--train N] [--seed S] [--quick] [--smoother none|rts]\n"
        "  --runs N    test runs (default 30)      --train N   training runs for estimation (default 4)\n"
        "  --seed S    base seed (default 2016)    --quick     6 test / 2 training runs, small search\n");
}

TrackRunSimulator::Params runParams(std::uint64_t seed) {
    std::mt19937_64 rng(seed * 7919 + 17);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    TrackRunSimulator::Params p;
    p.seed = seed;
    p.distance = seed % 2 ? 800.0 : 400.0;
    p.lane = 1 + static_cast<int>(u(rng) * (p.distance > 400 ? 6 : 4));
    p.topSpeed = p.distance > 400 ? 5.8 + 1.2 * u(rng) : 6.8 + 1.4 * u(rng);
    return p;
}

struct Stats {
    double mean = 0, sd = 0;
};
Stats stats(const std::vector<double>& v) {
    Stats s;
    for (double x : v) s.mean += x / double(v.size());
    for (double x : v) s.sd += (x - s.mean) * (x - s.mean) / double(std::max<std::size_t>(v.size() - 1, 1));
    s.sd = std::sqrt(s.sd);
    return s;
}
double slope(const std::vector<double>& x, const std::vector<double>& y) {
    const Stats sx = stats(x), sy = stats(y);
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        sxy += (x[i] - sx.mean) * (y[i] - sy.mean);
        sxx += (x[i] - sx.mean) * (x[i] - sx.mean);
    }
    return sxx > 0 ? sxy / sxx : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        auto next = [&](const char* name) -> const char* {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "%s needs a value\n", name);
                std::exit(2);
            }
            return argv[++i];
        };
        if (!std::strcmp(argv[i], "--runs"))
            o.runs = std::atoi(next("--runs"));
        else if (!std::strcmp(argv[i], "--train"))
            o.train = std::atoi(next("--train"));
        else if (!std::strcmp(argv[i], "--seed"))
            o.seed = std::strtoull(next("--seed"), nullptr, 10);
        else if (!std::strcmp(argv[i], "--smoother"))
            o.smoother = next("--smoother");
        else if (!std::strcmp(argv[i], "--quick"))
            o.quick = true;
        else {
            usage();
            return std::strcmp(argv[i], "--help") ? 2 : 0;
        }
    }
    if (o.quick) {
        o.runs = std::min(o.runs, 6);
        o.train = std::min(o.train, 2);
    }
    if (o.runs < 1 || o.train < 1) {
        usage();
        return 2;
    }

    std::fprintf(stderr, "simulating %d training and %d test runs (seed %llu)\n", o.train, o.runs,
                 static_cast<unsigned long long>(o.seed));
    std::vector<TrackRunSimulator::Result> train, test;
    for (int i = 0; i < o.train; ++i) train.push_back(TrackRunSimulator::simulate(runParams(o.seed + 1000 + i)));
    for (int i = 0; i < o.runs; ++i) test.push_back(TrackRunSimulator::simulate(runParams(o.seed + i)));
    std::vector<PositionSamples> trainSamples;
    for (const auto& r : train) trainSamples.push_back(r.measured);
    std::vector<double> inputRmse;
    for (const auto& r : test) inputRmse.push_back(TrackRunSimulator::rmse(r.truth, r.measured.t, r.measured.p));

    struct Variant {
        const char* name;
        FilterKind filter;
        ModelKind model;
    };
    const std::vector<Variant> variants = {
        {"U-EKF", FilterKind::Ekf, ModelKind::Unconstrained}, {"P-EKF", FilterKind::Ekf, ModelKind::Pseudo},
        {"M-EKF", FilterKind::Ekf, ModelKind::Augmented},     {"U-SRUKF", FilterKind::SrUkf, ModelKind::Unconstrained},
        {"P-SRUKF", FilterKind::SrUkf, ModelKind::Pseudo},    {"M-SRUKF", FilterKind::SrUkf, ModelKind::Augmented}};
    const std::vector<double> bins = {0.1, 0.5, 2.0, 5.0, 1e9};

    std::printf(
        "| Filter | RMSE mean ± SD (m) | slope vs input RMSE | err. Δt<0.1 s | 0.1–0.5 s | 0.5–2 s | 2–5 s | >5 s |"
        " rel. time | estimated (q_p, q_v, q_a, q_φ, q_ω, r_x, r_y, α) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    double baseTime = 0.0;
    for (const auto& variant : variants) {
        PositionFilter::Params params;
        params.filter = variant.filter;
        params.model = variant.model;
        params.track = std::make_shared<const TrackGeometry>(TrackGeometry::iaaf400m());
        params.smoothing = o.smoother == "rts" ? estimation::Smoothing::Rts : estimation::Smoothing::None;
        estimation::NoiseEstimator::Params search;
        search.seed = o.seed;
        if (o.quick) {
            search.starts = 2;
            search.evaluationsPerStart = 150;
            search.polishEvaluations = 100;
        }
        const auto t0 = std::chrono::steady_clock::now();
        int shown = -1;
        const auto estimate = PositionFilter::estimateNoise(params, trainSamples, search, [&](double f) {
            if (int(10 * f) != shown)
                std::fprintf(stderr, "\r%-8s estimating noise %3d %%", variant.name, 10 * (shown = int(10 * f)));
            return true;
        });
        const double estSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        params.noise = estimate.noise;
        std::fprintf(stderr, "\r%-8s estimated in %.1f s (%d evaluations)\n", variant.name, estSeconds,
                     estimate.evaluations);

        std::vector<double> rmse;
        std::vector<double> binSum(bins.size(), 0.0), binCount(bins.size(), 0.0);
        double filterSeconds = 0.0;
        const PositionFilter filter(params);
        for (std::size_t r = 0; r < test.size(); ++r) {
            const auto& run = test[r];
            const auto grid = PositionFilter::outputGrid(run.measured.t.front(), run.measured.t.back(), 10.0);
            // Process CPU time, not wall time: the comparison must not depend on other load.
            const std::clock_t f0 = std::clock();
            const auto out = filter.run(run.measured, grid);
            filterSeconds += double(std::clock() - f0) / CLOCKS_PER_SEC;
            std::vector<Eigen::Vector2d> p;
            for (const auto& s : out.states) p.emplace_back(s.x, s.y);
            rmse.push_back(TrackRunSimulator::rmse(run.truth, out.t, p));
            std::size_t last = 0;
            for (std::size_t k = 0; k < out.t.size(); ++k) {
                while (last + 1 < run.measured.t.size() && run.measured.t[last + 1] <= out.t[k]) ++last;
                const double since = out.t[k] - run.measured.t[last];
                const double err = (p[k] - TrackRunSimulator::truthAt(run.truth, out.t[k])).norm();
                const auto b =
                    static_cast<std::size_t>(std::lower_bound(bins.begin(), bins.end(), since) - bins.begin());
                binSum[b] += err;
                binCount[b] += 1;
            }
            std::fprintf(stderr, "\r%-8s filtering run %zu/%zu ", variant.name, r + 1, test.size());
        }
        std::fprintf(stderr, "\n");
        if (baseTime == 0.0) baseTime = filterSeconds;
        const Stats s = stats(rmse);
        std::printf("| %s | %.2f ± %.2f | %.3f |", variant.name, s.mean, s.sd, slope(inputRmse, rmse));
        for (std::size_t b = 0; b < bins.size(); ++b)
            binCount[b] > 0 ? std::printf(" %.2f |", binSum[b] / binCount[b]) : std::printf(" – |");
        const auto& n = params.noise;
        std::printf(" %.0f %% | %.2g, %.2g, %.2g, %.2g, %.2g, %.2g, %.2g, %.3g |\n", 100.0 * filterSeconds / baseTime,
                    n.ctra.qPosition, n.ctra.qSpeed, n.ctra.qAccel, n.ctra.qHeading, n.ctra.qTurnRate, n.ctra.rX,
                    n.ctra.rY, n.gate);
        std::fflush(stdout);
    }
    const Stats in = stats(inputRmse);
    std::printf("\nInput (raw LPS) RMSE: %.2f ± %.2f m over %zu test runs.\n", in.mean, in.sd, inputRmse.size());
    return 0;
}
