// Orientation filters: samples per second on one core (judged: 9D ≥ 3 million/s for the default).
// Input: a simulated 100 Hz session (rotations, turns, sway) of 200 000 samples, run as one batch.
#include "plugins/inertial/ImuGnssSimulator.h"
#include "plugins/inertial/OrientationEstimation.h"

#include <benchmark/benchmark.h>

using namespace athlos::inertial;

namespace {
const std::vector<double>& samples() {
    static const std::vector<double> rows = [] {
        SimulatorParams p;
        p.duration = 2000.0;
        p.translation = false;
        const SimulatedData d = simulateImuGnss(p);
        std::vector<double> v;
        v.reserve(d.imuT.size() * 9);
        for (std::size_t k = 0; k < d.imuT.size(); ++k)
            for (const Vec3* x : {&d.acc[k], &d.gyr[k], &d.mag[k]}) v.insert(v.end(), x->data(), x->data() + 3);
        return v;
    }();
    return rows;
}

void run(benchmark::State& state, OrientationAlgorithm algorithm, bool mag, bool offline = false) {
    const auto& v = samples();
    const ImuBatch batch{v.data() + 3, v.data(), mag ? v.data() + 6 : nullptr, v.size() / 9, 9};
    OrientationOptions o;
    o.algorithm = algorithm;
    o.useMagnetometer = mag;
    o.offline = offline;
    for (auto _ : state) {
        auto r = estimateOrientation(o, batch, 0.01);
        benchmark::DoNotOptimize(r.track.q.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(batch.rows));
}

// The filter alone, per sample, without writing a track (the cost of update()).
void vqfUpdateOnly(benchmark::State& state) {
    const auto& v = samples();
    const std::size_t n = v.size() / 9;
    for (auto _ : state) {
        OrientationFilter f(0.01);
        for (std::size_t k = 0; k < n; ++k) {
            const double* r = &v[k * 9];
            const Vec3 m(r[6], r[7], r[8]);
            f.update(Vec3(r[3], r[4], r[5]), Vec3(r[0], r[1], r[2]), &m);
        }
        benchmark::DoNotOptimize(f.quaternion());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(n));
}
}  // namespace

BENCHMARK_CAPTURE(run, vqf_9d, OrientationAlgorithm::Vqf, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, vqf_6d, OrientationAlgorithm::Vqf, false)->Unit(benchmark::kMillisecond);
// Offline mode (issue #17): four filter passes, a strapdown and a zero-phase low-pass.
BENCHMARK_CAPTURE(run, vqf_offline_9d, OrientationAlgorithm::Vqf, true, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, vqf_offline_6d, OrientationAlgorithm::Vqf, false, true)->Unit(benchmark::kMillisecond);
BENCHMARK(vqfUpdateOnly)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, madgwick_9d, OrientationAlgorithm::Madgwick, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, mahony_9d, OrientationAlgorithm::Mahony, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, kalman_9d, OrientationAlgorithm::Kalman, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(run, strapdown, OrientationAlgorithm::Strapdown, false)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
