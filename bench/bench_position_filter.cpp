// Throughput of the position filters (samples per second, one core): unconstrained / augmented /
// pseudo-measurement CTRA with EKF, UKF and SRUKF on a simulated 800 m run (non-uniform input,
// outliers, outages), output at the input time stamps, no smoothing, manual noise. Figures go to
// docs/validation/position-filter.md (issue #3: U-EKF ≥ 2 M samples/s, augmented overhead ≤ 10 %).
#include "plugins/positioning/PositionFilter.h"
#include "plugins/positioning/TrackRunSimulator.h"

#include <benchmark/benchmark.h>

using namespace athlos;
using namespace athlos::positioning;

namespace {

const TrackRunSimulator::Result& run800() {
    static const TrackRunSimulator::Result run = [] {
        TrackRunSimulator::Params p;
        p.seed = 7;
        p.distance = 800.0;
        return TrackRunSimulator::simulate(p);
    }();
    return run;
}

void filterBenchmark(benchmark::State& state, FilterKind filter, ModelKind model, estimation::Smoothing smoothing) {
    PositionFilter::Params params;
    params.filter = filter;
    params.model = model;
    params.track = std::make_shared<const TrackGeometry>(TrackGeometry::iaaf400m());
    params.noise.ctra = {0.0, 0.02, 0.2, 0.003, 0.005, 0.005, 0.016};
    params.noise.gate = 10.0;
    params.smoothing = smoothing;
    const PositionFilter pf(params);
    const auto& in = run800().measured;
    for (auto _ : state) {
        auto out = pf.run(in, {});
        benchmark::DoNotOptimize(out.states.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(in.t.size()));
}

}  // namespace

BENCHMARK_CAPTURE(filterBenchmark, U_EKF, FilterKind::Ekf, ModelKind::Unconstrained, estimation::Smoothing::None);
BENCHMARK_CAPTURE(filterBenchmark, M_EKF, FilterKind::Ekf, ModelKind::Augmented, estimation::Smoothing::None);
BENCHMARK_CAPTURE(filterBenchmark, P_EKF, FilterKind::Ekf, ModelKind::Pseudo, estimation::Smoothing::None);
BENCHMARK_CAPTURE(filterBenchmark, CV_EKF, FilterKind::Ekf, ModelKind::ConstantVelocity, estimation::Smoothing::None);
BENCHMARK_CAPTURE(filterBenchmark, U_UKF, FilterKind::Ukf, ModelKind::Unconstrained, estimation::Smoothing::None);
BENCHMARK_CAPTURE(filterBenchmark, U_SRUKF, FilterKind::SrUkf, ModelKind::Unconstrained, estimation::Smoothing::None);
BENCHMARK_CAPTURE(filterBenchmark, M_SRUKF, FilterKind::SrUkf, ModelKind::Augmented, estimation::Smoothing::None);
BENCHMARK_CAPTURE(filterBenchmark, P_SRUKF, FilterKind::SrUkf, ModelKind::Pseudo, estimation::Smoothing::None);
BENCHMARK_CAPTURE(filterBenchmark, M_EKF_RTS, FilterKind::Ekf, ModelKind::Augmented, estimation::Smoothing::Rts);

BENCHMARK_MAIN();
