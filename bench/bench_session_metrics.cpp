// Session metrics of one 90-min player at 10 Hz (54 000 fixes, one core): the smoothing with noise=auto
// on the representative subsample (8 × 60 s chunks) against the whole recording, the smoothing with
// given noise, and the metrics of a period on the smoothed motion. Figures go to docs/PERFORMANCE.md
// (issue #15: position filtering of a 90-min player ≤ 2 s; the whole report well under a minute).
#include "plugins/metrics/MotionFromPositions.h"
#include "plugins/metrics/SessionMetrics.h"
#include "plugins/team/TeamSimulator.h"

#include <benchmark/benchmark.h>
#include <random>

using namespace athlos;
using namespace athlos::metrics;

namespace {

const positioning::PositionSamples& player90() {
    static const positioning::PositionSamples fixes = [] {
        team::TeamSimulator::Params p;
        p.seed = 4;
        p.duration = 5400.0;
        const auto match = team::TeamSimulator::simulate(p);
        std::mt19937_64 rng(9);
        std::normal_distribution<double> noise(0.0, 0.1);
        positioning::PositionSamples s;
        s.t = match.t;
        for (std::size_t k = 0; k < match.t.size(); ++k)
            s.p.emplace_back(match.tracks[6].x[k] + noise(rng), match.tracks[6].y[k] + noise(rng));
        return s;
    }();
    return fixes;
}

void smoothing(benchmark::State& state, int chunks, bool estimate) {
    MotionParams params;
    params.noiseChunks = chunks;
    params.estimateNoise = estimate;
    params.noise.qAccelCv = 2.0;
    params.noise.ctra.rX = params.noise.ctra.rY = 0.01;
    params.noise.gate = 9.0;
    for (auto _ : state) {
        auto motion = motionFromPositions(player90(), params);
        benchmark::DoNotOptimize(motion->series.x.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(player90().t.size()));
}

void periodMetrics(benchmark::State& state) {
    MotionParams params;
    params.estimateNoise = false;
    params.noise.qAccelCv = 2.0;
    params.noise.ctra.rX = params.noise.ctra.rY = 0.01;
    const auto motion = motionFromPositions(player90(), params);
    for (auto _ : state) {
        auto m = computePeriod(motion->series, 0.0, 5400.0, MetricsParams{});
        benchmark::DoNotOptimize(m.distance);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(motion->series.size()));
}

}  // namespace

BENCHMARK_CAPTURE(smoothing, noiseAutoChunks8, 8, true)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK_CAPTURE(smoothing, noiseAutoWhole, 0, true)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK_CAPTURE(smoothing, noiseGiven, 8, false)->Unit(benchmark::kMillisecond);
BENCHMARK(periodMetrics)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
