// CPU time of the anchor pipeline (rest-aligned strapdown, gate detection, three smoother passes of
// 16 states at 100 Hz, low-pass) on a simulated 55-s giant-slalom run (200 Hz IMU, 24 gates), with the
// simulator's orientation as input. Figure in docs/PERFORMANCE.md.
#include "plugins/positioning/AnchorPipeline.h"
#include "plugins/positioning/GateRunSimulator.h"

#include <benchmark/benchmark.h>

using namespace athlos;
using namespace athlos::positioning;

static void BM_AnchorPipeline(benchmark::State& state) {
    GateRunSimulator::Params p;
    p.seed = 3;
    const auto sim = GateRunSimulator::simulate(p);
    AnchorPipelineInput in;
    in.t = sim.t;
    in.acc = sim.acc;
    in.gyr = sim.gyr;
    in.mag = sim.mag;
    in.orientation = sim.orientation;
    in.gates = sim.gates;
    for (auto _ : state) {
        auto r = runAnchorPipeline(in, AnchorPipelineParams{});
        benchmark::DoNotOptimize(r);
    }
    state.counters["imu_samples"] = double(sim.t.size());
}
BENCHMARK(BM_AnchorPipeline)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
