// Throughput of the signal family on 10 M samples: Butterworth (4th-order low-pass, causal and
// zero-phase) and resampling (linear, cubic, quaternion SLERP). items_per_second = samples/s,
// counting one sample per output row and column (a quaternion row counts as one sample).
#include "plugins/signal/Butterworth.h"
#include "plugins/signal/Resampler.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

using namespace athlos;
using namespace athlos::signal;

namespace {

constexpr Eigen::Index kSamples = 10'000'000;

Eigen::VectorXd noisySine() {
    std::mt19937 rng(1);
    std::normal_distribution<double> noise(0.0, 0.1);
    Eigen::VectorXd x(kSamples);
    for (Eigen::Index i = 0; i < kSamples; ++i) x[i] = std::sin(0.01 * double(i)) + noise(rng);
    return x;
}

// 10 M rows at a nominal 100 Hz with ±20 % jitter; columns: one ordinary, or a quaternion (qw..qz).
StreamData jitteredStream(bool quaternion) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    StreamData d(static_cast<std::size_t>(kSamples), quaternion ? 4 : 1);
    for (std::size_t i = 0; i < d.rows(); ++i) {
        d.t[i] = (double(i) + jitter(rng)) * 0.01;
        if (quaternion) {
            const double half = 0.5 * std::sin(0.001 * double(i));
            d.at(i, 0) = std::cos(half);
            d.at(i, 1) = std::sin(half) * 0.6;
            d.at(i, 2) = 0.0;
            d.at(i, 3) = std::sin(half) * 0.8;
        } else {
            d.at(i, 0) = std::sin(0.01 * double(i));
        }
    }
    return d;
}

void filterBench(benchmark::State& state, bool zeroPhase) {
    const Butterworth lowpass({Butterworth::Type::LowPass, 4, 10.0, 0.0, 100.0});
    const Eigen::VectorXd x = noisySine();
    Eigen::VectorXd y(kSamples);
    for (auto _ : state) {
        y = x;
        zeroPhase ? lowpass.filtFilt(y) : lowpass.filter(y);
        benchmark::DoNotOptimize(y.data());
    }
    state.SetItemsProcessed(state.iterations() * kSamples);
}

void resampleBench(benchmark::State& state, Resampler::Method method, bool quaternion) {
    const StreamData in = jitteredStream(quaternion);
    const QStringList names = quaternion ? QStringList{"qw", "qx", "qy", "qz"} : QStringList{"x"};
    const ColumnGroups groups = ColumnGroups::detect(names);
    std::size_t rows = 0;
    for (auto _ : state) {
        const Resampler resampler({100.0, method}, in.t);  // grid construction is part of the cost
        const StreamData out = resampler.resample(in, groups);
        rows = out.rows();
        benchmark::DoNotOptimize(out.values.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(rows));
}

}  // namespace

BENCHMARK_CAPTURE(filterBench, lowpass4_causal, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(filterBench, lowpass4_zero_phase, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(resampleBench, linear, Resampler::Method::Linear, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(resampleBench, cubic, Resampler::Method::Cubic, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(resampleBench, quaternion_slerp, Resampler::Method::Linear, true)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
