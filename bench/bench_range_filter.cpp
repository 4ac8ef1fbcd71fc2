// Throughput of the tightly coupled range filter (issue #16 item 7: ≥ 1 M measurements per second on
// one core): 4 anchors, asynchronous 10 Hz ranges per anchor over a 30 min walk (72 000 ranges),
// constant-velocity model, with and without the per-beacon offset states, forward pass only and with
// RTS smoothing (output at 10 Hz). Items = range measurements. Figures in docs/PERFORMANCE.md.
#include "plugins/positioning/RangeFilter.h"

#include <benchmark/benchmark.h>
#include <cmath>
#include <random>

using namespace athlos;
using namespace athlos::positioning;

namespace {

const RangeMeasurements& walk() {
    static const RangeMeasurements ranges = [] {
        RangeMeasurements m;
        m.beacons = {{0.7, 0.9, 0.5}, {2.6, 0.9, 2.0}, {2.6, -0.9, 2.0}, {2.6, -0.9, 0.5}};
        std::mt19937_64 rng(11);
        std::normal_distribution<double> noise(0.0, 0.1);
        for (double t = 0.0; t < 1800.0; t += 0.025) {
            const int beacon = int(std::lround(t / 0.025)) % 4;
            const Eigen::Vector3d p(20.0 + 15.0 * std::cos(t / 20.0), 15.0 * std::sin(t / 20.0), 1.0);
            m.t.push_back(t);
            m.y.push_back({(p - m.beacons[std::size_t(beacon)]).norm() + noise(rng), beacon});
        }
        return m;
    }();
    return ranges;
}

void rangeFilter(benchmark::State& state, bool offsets, estimation::Smoothing smoothing) {
    RangeFilter::Params p;
    p.model = ModelKind::ConstantVelocity;
    p.noise.qAccelCv = 0.3;
    p.rRange = 0.01;
    p.noise.gate = 9.0;
    p.offsets = offsets;
    p.smoothing = smoothing;
    const RangeFilter filter(p);
    const auto& in = walk();
    const std::vector<double> grid = smoothing == estimation::Smoothing::None
                                         ? std::vector<double>{}
                                         : PositionFilter::outputGrid(0.0, 1800.0, 10.0);
    for (auto _ : state) {
        auto r = filter.run(in, grid);
        benchmark::DoNotOptimize(r->filtered.states.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(in.size()));
}

}  // namespace

BENCHMARK_CAPTURE(rangeFilter, cv_forward, false, estimation::Smoothing::None)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(rangeFilter, cv_offsets_forward, true, estimation::Smoothing::None)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(rangeFilter, cv_offsets_rts_10hz, true, estimation::Smoothing::Rts)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
