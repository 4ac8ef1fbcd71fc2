// gait-parameters' algorithm (gyroscope bias, stride segmentation, ZUPT integration): samples per
// second on one core. Input: 10 minutes of simulated walking at 102.4 Hz (FootMotionSimulator,
// ~550 strides with turns, noise and biases), run as one batch as the processor does; with each of
// the two methods: `instant` (per stride, StrideIntegrator) and `rts` (the default: the ZUPT Kalman
// smoother over the whole recording, ZuptKalmanSmoother).
#include "plugins/events/FootMotionSimulator.h"
#include "plugins/events/StaticGyroBias.h"
#include "plugins/events/StrideIntegrator.h"
#include "plugins/events/ZuptKalmanSmoother.h"

#include <benchmark/benchmark.h>

using namespace athlos::events;

namespace {
const SimRecording& walk() {
    static const SimRecording rec = [] {
        SimConfig c;
        for (int i = 0; i < 545; ++i) {
            SimStride s;
            s.length = 1.2 + 0.02 * (i % 10);
            s.turn = i % 20 < 2 ? 0.8 : 0.0;  // a turn every 20 strides
            c.strides.push_back(s);
        }
        return simulateFoot(c);
    }();
    return rec;
}

template <bool Rts>
void gaitParameters(benchmark::State& state) {
    const SimRecording& rec = walk();
    const std::size_t n = rec.t.size();
    const double* v = rec.values.data();
    const StrideSegmentationParams params;
    std::size_t strides = 0;
    for (auto _ : state) {
        const StaticGyroBias bias =
            estimateStaticGyroBias(rec.t.data(), v + 3, n, 6, params.restWindow, params.staticThreshold, 1.0);
        std::vector<double> gyr(3 * n);
        for (std::size_t k = 0; k < n; ++k)
            for (std::size_t i = 0; i < 3; ++i) gyr[3 * k + i] = v[6 * k + 3 + i] - bias.bias[int(i)];
        const StrideSegmentation s = segmentStrides(params, rec.t.data(), gyr.data(), n, 3);
        const FootTrajectory t = Rts ? smoothStrides({}, s.strides, rec.t.data(), v, 6, gyr.data(), 3, n)
                                     : integrateStrides({}, s.strides, rec.t.data(), v, 6, gyr.data(), 3, n);
        strides = t.strides.size();
        benchmark::DoNotOptimize(t.position.data());
    }
    state.counters["strides"] = double(strides);
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(n));
}
}  // namespace

BENCHMARK(gaitParameters<false>)->Name("gaitParametersInstant")->Unit(benchmark::kMillisecond);
BENCHMARK(gaitParameters<true>)->Name("gaitParametersRts")->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
