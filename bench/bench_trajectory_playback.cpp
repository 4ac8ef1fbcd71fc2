// Team playback: 22 athletes at 10 Hz over 90 minutes (simulate-team's code), rendered frame after
// frame at 1280×800 into a QImage while the cursor advances as playback at 1× and 4× would at
// 30 frames per second; plus the one-off costs (simulation, preparing the tracks of the match).
// "fps" is frames per wall-clock second of rendering alone (the budget for 30 fps is 33 ms/frame).
//
//   QT_QPA_PLATFORM is forced to offscreen; run: bench_trajectory_playback [--benchmark_filter=...]
#include "bench/QtBenchmarkMain.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/team/SimulateTeamProcessor.h"
#include "plugins/team/TeamSimulator.h"
#include "ui/TimeController.h"
#include "ui/views/PlaybackCanvas.h"
#include "ui/views/PlaybackTracks.h"
#include "ui/views/PlaybackView.h"

#include <QApplication>
#include <QDir>
#include <QImage>
#include <QPainter>
#include <benchmark/benchmark.h>

#include <memory>

using namespace athlos;
using namespace athlos::ui;

namespace {

constexpr double kMatch = 5400.0;
constexpr double kFps = 30.0;

Project& match() {
    static std::unique_ptr<Project> project = [] {
        auto p = Project::create(QDir::temp().filePath(QStringLiteral("athlos-bench-playback.athlos")));
        const auto out = runProcessor(*p, team::SimulateTeamProcessor(),
                                      {QStringLiteral("simulate-team"),
                                       {},
                                       QStringLiteral("match/player"),
                                       {{QStringLiteral("seed"), 1}, {QStringLiteral("duration"), kMatch}}});
        if (!out) qFatal("simulate-team: %s", qPrintable(out.message()));
        return p;
    }();
    return *project;
}

struct Playback {
    TimeController time;
    PlaybackView view{&match()};
    QImage image{1280, 800, QImage::Format_ARGB32_Premultiplied};

    explicit Playback(double trail) {
        time.setBounds(0.0, kMatch);
        view.setAttribute(Qt::WA_DontShowOnScreen);
        view.resize(image.size());
        view.show();
        view.setTimeController(&time);
        if (!view.setRecording(QStringLiteral("match"))) qFatal("no match recording");
        view.setTrailSeconds(trail);
        QCoreApplication::processEvents();
        view.canvas()->frameAll();
    }
};

// The time column is ms per frame (real time); fps is its inverse.
void reportFrames(benchmark::State& state) {
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}

}  // namespace

static void BM_SimulateMatch(benchmark::State& state) {
    team::TeamSimulator::Params p;
    p.duration = kMatch;
    for (auto _ : state) {
        const auto r = team::TeamSimulator::simulate(p);
        benchmark::DoNotOptimize(r.tracks.data());
    }
    state.counters["samples"] = double(22 * (kMatch * 10 + 1));
}
BENCHMARK(BM_SimulateMatch)->Unit(benchmark::kMillisecond)->Iterations(3);

// Reading the 22 streams into flat arrays with speed and colour bins (done once per recording).
static void BM_PrepareMatchTracks(benchmark::State& state) {
    Project& project = match();
    for (auto _ : state) {
        const auto tracks = PlaybackTracks::readRecording(project, QStringLiteral("match"));
        benchmark::DoNotOptimize(tracks.data());
        if (tracks.size() != 22) state.SkipWithError("expected 22 athletes");
    }
}
BENCHMARK(BM_PrepareMatchTracks)->Unit(benchmark::kMillisecond)->Iterations(10);

// The whole view (controls and canvas) rendered into a 1280×800 image per frame; the cursor moves
// by speed/30 s per frame through the match. Args: playback speed ×1 / ×4, trail seconds.
static void BM_PlaybackFrame(benchmark::State& state) {
    const double speed = double(state.range(0)), trail = double(state.range(1));
    Playback p(trail);
    double t = 600.0;
    for (auto _ : state) {
        t += speed / kFps;
        if (t > kMatch) t = trail;
        p.time.setCursor(t);
        p.view.render(&p.image);
    }
    benchmark::DoNotOptimize(p.image.constBits());
    reportFrames(state);
}
BENCHMARK(BM_PlaybackFrame)
    ->Args({1, 10})
    ->Args({4, 10})
    ->Args({1, 60})
    ->ArgNames({"speed", "trail_s"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The canvas alone (what a cursor change repaints): venue pixmap, trails, dots, labels, legend.
static void BM_PlaybackCanvasFrame(benchmark::State& state) {
    const double speed = double(state.range(0));
    Playback p(10.0);
    PlaybackCanvas* canvas = p.view.canvas();
    QImage image(canvas->size(), QImage::Format_ARGB32_Premultiplied);
    double t = 600.0;
    for (auto _ : state) {
        t += speed / kFps;
        if (t > kMatch) t = 10.0;
        p.time.setCursor(t);
        QPainter painter(&image);
        canvas->paintFrame(painter);
    }
    benchmark::DoNotOptimize(image.constBits());
    state.counters["canvas_w"] = canvas->width();
    state.counters["canvas_h"] = canvas->height();
    reportFrames(state);
}
BENCHMARK(BM_PlaybackCanvasFrame)->Arg(1)->Arg(4)->ArgName("speed")->Unit(benchmark::kMillisecond)->UseRealTime();

ATHLOS_QT_BENCHMARK_MAIN()
