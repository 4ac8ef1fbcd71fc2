// Opening a large project (metadata only) and loading one stream from it.
// The ~1 GB project (4 recordings × 5 streams × 8 M rows × 1 column, noisy random walks) is built
// once and cached in $TMPDIR (athlos-bench-open-v1.athlos); delete it to rebuild.
// "Cold" variants drop the file from the page cache (posix_fadvise) before each iteration.
#include "core/model/Project.h"
#include "core/store/ProjectFile.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <cstdio>
#include <fcntl.h>
#include <random>
#include <unistd.h>

namespace {

using namespace athlos;

constexpr int kRecordings = 4;
constexpr int kStreamsPerRecording = 5;
constexpr std::size_t kRows = 8'000'000;

QString streamPath(int rec, int s) { return QStringLiteral("rec%1/acc%2").arg(rec).arg(s); }

// A 285.7 Hz accelerometer-like signal: random walk plus sensor noise, so compression cannot
// trivialise it (shuffle+deflate keeps ~78 % of its bytes, ~39 % with t).
Stream makeStream(unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> step(0.0, 0.05), noise(0.0, 0.3);
    StreamData data(kRows, 1);
    double walk = 9.81;
    for (std::size_t i = 0; i < kRows; ++i) {
        data.t[i] = double(i) * 0.0035;
        walk += step(rng);
        data.values[i] = walk + noise(rng);
    }
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.frame = QStringLiteral("sensor");
    info.columns = {{QStringLiteral("acc_x"), QStringLiteral("m/s^2")}};
    return Stream(std::move(info), std::move(data));
}

bool isComplete(const QString& path) {
    if (!QFileInfo::exists(path)) return false;
    auto project = Project::open(path);
    if (!project) return false;
    for (int r = 0; r < kRecordings; ++r)
        for (int s = 0; s < kStreamsPerRecording; ++s) {
            const Stream* stream = (*project)->stream(streamPath(r, s));
            if (!stream || stream->info().rows != static_cast<long long>(kRows)) return false;
        }
    return true;
}

// Built one recording per save (the earlier ones are copied undecoded) to bound memory at ~0.5 GB.
QString benchProject() {
    static const QString path = [] {
        const QString target = QDir(QDir::tempPath()).filePath(QStringLiteral("athlos-bench-open-v1.athlos"));
        if (isComplete(target)) return target;
        const QString partial = target + QStringLiteral(".partial");
        QFile::remove(partial);
        for (int r = 0; r < kRecordings; ++r) {
            std::fprintf(stderr, "building %s: recording %d/%d\n", qPrintable(target), r + 1, kRecordings);
            std::unique_ptr<Project> project;
            if (r == 0) {
                project = Project::create(partial, QStringLiteral("athletics"));
            } else {
                auto opened = Project::open(partial);
                if (!opened) qFatal("%s", qPrintable(opened.message()));
                project = std::move(opened).value();
            }
            for (int s = 0; s < kStreamsPerRecording; ++s)
                project->putStream(streamPath(r, s), makeStream(unsigned(r * 100 + s)));
            if (const Status saved = project->save(); !saved) qFatal("%s", qPrintable(saved.message()));
        }
        QFile::remove(target);
        if (!QFile::rename(partial, target)) qFatal("cannot rename %s", qPrintable(partial));
        return target;
    }();
    return path;
}

void dropFromPageCache(const QString& path) {
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY);
    if (fd < 0) return;
    ::posix_fadvise(fd, 0, 0, POSIX_FADV_DONTNEED);
    ::close(fd);
}

void open(benchmark::State& state, bool cold) {
    const QString path = benchProject();
    for (auto _ : state) {
        if (cold) {
            state.PauseTiming();
            dropFromPageCache(path);
            state.ResumeTiming();
        }
        auto project = Project::open(path);
        if (!project) state.SkipWithError(qPrintable(project.message()));
        benchmark::DoNotOptimize(project);
    }
    state.counters["file_MB"] = double(QFileInfo(path).size()) / 1e6;
}

void loadStream(benchmark::State& state, bool cold) {
    const QString path = benchProject();
    const QString group = QStringLiteral("/recordings/") + streamPath(2, 3);
    for (auto _ : state) {
        if (cold) {
            state.PauseTiming();
            dropFromPageCache(path);
            state.ResumeTiming();
        }
        auto data = ProjectFile::loadStream(path, group, 1);
        if (!data) state.SkipWithError(qPrintable(data.message()));
        benchmark::DoNotOptimize(data);
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(kRows) * 16);  // decoded t + data
}

void BM_ProjectOpen(benchmark::State& state) { open(state, false); }
void BM_ProjectOpenCold(benchmark::State& state) { open(state, true); }
void BM_LoadStream(benchmark::State& state) { loadStream(state, false); }
void BM_LoadStreamCold(benchmark::State& state) { loadStream(state, true); }

// Save of the opened project to a new file: every stream is copied undecoded (H5Ocopy).
void BM_SaveAsUnloaded(benchmark::State& state) {
    const QString path = benchProject();
    const QString copy = path + QStringLiteral(".copy");
    for (auto _ : state) {
        state.PauseTiming();
        auto project = Project::open(path);
        if (!project) state.SkipWithError(qPrintable(project.message()));
        state.ResumeTiming();
        if (const Status saved = (*project)->saveAs(copy); !saved) state.SkipWithError(qPrintable(saved.message()));
        state.PauseTiming();
        QFile::remove(copy);
        state.ResumeTiming();
    }
    state.SetBytesProcessed(int64_t(state.iterations()) * QFileInfo(path).size());
}

BENCHMARK(BM_ProjectOpen)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ProjectOpenCold)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadStream)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadStreamCold)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SaveAsUnloaded)->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace

BENCHMARK_MAIN();
