// Plot responsiveness with 10 million samples: min/max pyramid build, decimation per x-range
// change, and full replots of a TimeSeriesPanel at full range, zoomed and while panning, offscreen.
// For comparison, QCustomPlot fed all 10 M points directly (its own adaptive sampling).
//
//   QT_QPA_PLATFORM is forced to offscreen; run: bench_plot_repaint [--benchmark_filter=...]
#include "bench/QtBenchmarkMain.h"
#include "core/model/Stream.h"
#include "ui/MinMaxPyramid.h"
#include "ui/TimeSeriesPanel.h"

#include <QApplication>
#include <benchmark/benchmark.h>
#include <qcustomplot.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>

using namespace athlos;
using namespace athlos::ui;

namespace {

constexpr std::size_t kSamples = 10'000'000;
constexpr double kRate = 1000.0;  // Hz: 10 M samples ≈ 2.8 h at 1 kHz

// A 1 kHz signal: slow drift, a 1 Hz oscillation, noise and a few isolated spikes.
std::shared_ptr<const StreamData> samples() {
    static std::shared_ptr<const StreamData> data = [] {
        auto d = std::make_shared<StreamData>(kSamples, 1);
        std::mt19937_64 rng(1);
        std::normal_distribution<double> noise(0.0, 0.05);
        for (std::size_t i = 0; i < kSamples; ++i) {
            const double t = double(i) / kRate;
            d->t[i] = t;
            d->at(i, 0) = std::sin(2 * std::numbers::pi * t) + 0.1 * std::sin(t / 600.0) + noise(rng);
        }
        for (std::size_t i = 12345; i < kSamples; i += 1'000'003) d->at(i, 0) += 8.0;
        return std::shared_ptr<const StreamData>(std::move(d));
    }();
    return data;
}

std::shared_ptr<const Stream> stream() {
    static std::shared_ptr<const Stream> s = [] {
        StreamInfo info;
        info.name = QStringLiteral("acc");
        info.kind = QStringLiteral("imu");
        info.columns = {{QStringLiteral("acc_x"), QStringLiteral("m/s^2")}};
        return std::make_shared<const Stream>(info, *samples());
    }();
    return s;
}

// One panel for all plot benchmarks, 1280×800 like the screenshots, loaded once.
TimeSeriesPanel& panel() {
    static TimeSeriesPanel* p = [] {
        auto* panel = new TimeSeriesPanel;
        panel->resize(1280, 800);
        panel->show();
        panel->setStream(stream(), QStringLiteral("bench/acc"));
        panel->waitForLoad();
        QCoreApplication::processEvents();
        panel->plot()->replot(QCustomPlot::rpImmediateRefresh);
        return panel;
    }();
    return *p;
}

void setRangeAndReplot(TimeSeriesPanel& p, double lower, double upper) {
    p.plot()->xAxis->setRange(lower, upper);  // → redecimate() via rangeChanged
    p.plot()->replot(QCustomPlot::rpImmediateRefresh);
}

}  // namespace

static void BM_PyramidBuild10M(benchmark::State& state) {
    const auto data = samples();
    for (auto _ : state) {
        MinMaxPyramid pyramid(data, 0);
        benchmark::DoNotOptimize(pyramid.levelCount());
    }
    state.SetItemsProcessed(state.iterations() * int64_t(kSamples));
}
BENCHMARK(BM_PyramidBuild10M)->Unit(benchmark::kMillisecond)->Iterations(5);

static void BM_DecimateFullRange10M(benchmark::State& state) {
    const MinMaxPyramid pyramid(samples(), 0);
    const int pixels = int(state.range(0));
    std::size_t points = 0;
    for (auto _ : state) {
        const DecimatedSeries s = pyramid.decimate(0.0, double(kSamples - 1) / kRate, pixels);
        points = std::size_t(s.keys.size());
        benchmark::DoNotOptimize(points);
    }
    state.counters["points"] = double(points);
}
BENCHMARK(BM_DecimateFullRange10M)->Arg(1200)->Arg(4000)->Unit(benchmark::kMicrosecond);

static void BM_ReplotFullRange10M(benchmark::State& state) {
    TimeSeriesPanel& p = panel();
    const double end = double(kSamples - 1) / kRate;
    bool flip = false;
    for (auto _ : state) {
        // Alternate by one sample so every iteration really re-decimates.
        setRangeAndReplot(p, 0.0, end - (flip ? 1.0 / kRate : 0.0));
        flip = !flip;
    }
    state.counters["points"] = double(p.plottedPointCount());
    state.counters["width_px"] = p.decimationWidth();
}
BENCHMARK(BM_ReplotFullRange10M)->Unit(benchmark::kMillisecond);

// Zoomed to a window of `range(0)` seconds in the middle: 60 s = 60 k samples (decimated),
// 1 s = 1000 samples (raw samples, ≤ 2 per pixel).
static void BM_ReplotZoomed10M(benchmark::State& state) {
    TimeSeriesPanel& p = panel();
    const double width = double(state.range(0)) / 1000.0;
    const double mid = 0.5 * double(kSamples) / kRate;
    bool flip = false;
    for (auto _ : state) {
        const double shift = flip ? 0.5 / kRate : 0.0;
        setRangeAndReplot(p, mid - width / 2 + shift, mid + width / 2 + shift);
        flip = !flip;
    }
    state.counters["points"] = double(p.plottedPointCount());
}
BENCHMARK(BM_ReplotZoomed10M)
    ->Arg(3'600'000)
    ->Arg(60'000)
    ->Arg(1'000)
    ->ArgName("window_ms")
    ->Unit(benchmark::kMillisecond);

// Dragging: each iteration pans a 10-minute window by 1 %, as a mouse move would.
static void BM_Pan10M(benchmark::State& state) {
    TimeSeriesPanel& p = panel();
    const double width = 600.0;
    double lower = 1000.0;
    for (auto _ : state) {
        lower += 0.01 * width;
        if (lower + width > double(kSamples) / kRate) lower = 0.0;
        setRangeAndReplot(p, lower, lower + width);
    }
}
BENCHMARK(BM_Pan10M)->Unit(benchmark::kMillisecond);

// Reference: all 10 M points handed to QCustomPlot (adaptive sampling on, its default).
static void BM_NaiveQCustomPlotFullRange10M(benchmark::State& state) {
    QCustomPlot plot;
    plot.resize(1280, 800);
    plot.show();
    const auto data = samples();
    QVector<QCPGraphData> points(static_cast<qsizetype>(kSamples));
    for (std::size_t i = 0; i < kSamples; ++i) points[qsizetype(i)] = QCPGraphData(data->t[i], data->values[i]);
    QCPGraph* graph = plot.addGraph();
    graph->data()->set(points, true);
    points.clear();
    plot.xAxis->setRange(0.0, double(kSamples - 1) / kRate);
    plot.yAxis->setRange(-2, 10);
    QCoreApplication::processEvents();
    for (auto _ : state) plot.replot(QCustomPlot::rpImmediateRefresh);
}
BENCHMARK(BM_NaiveQCustomPlotFullRange10M)->Unit(benchmark::kMillisecond)->Iterations(5);

ATHLOS_QT_BENCHMARK_MAIN()
