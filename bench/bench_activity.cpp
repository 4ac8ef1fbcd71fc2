// Activity recognition throughput (issue #14: ≥ 10 000 windows/s on one core for features + random
// forest). items_per_second = windows/s (CPU time, OpenCV limited to one thread): FeatureExtraction computes the 143 features of 3 s windows
// (50 Hz, acc + gyr) of a simulated wrist IMU; FeaturesAndForest adds scaling and the class
// probabilities of the default (100-tree) random forest trained on 4 simulated people; Training trains that forest.
// Issue #14 item 6 besides: Training100k trains the default forest (class-balanced, as athlos train's final
// model: parallel parts of 10 trees, each on at most 15 000 rows) on 100 000 windows of simulated people, with
// wall and whole-process CPU time and the balanced accuracy on 12 held-out people, and CnnInference runs
// the committed tiny ONNX CNN (tests/data/activity/tiny_cnn.onnx) through OpenCV dnn on batches of raw
// windows (RawWindowsAndCnn: with cutting and resampling the windows out of the stream, as classify-actions).
#include "plugins/activity/ActivityModel.h"
#include "plugins/activity/ActivitySimulator.h"
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/CnnTraining.h"
#include "plugins/activity/RawWindows.h"
#include "plugins/activity/FeatureExtractor.h"
#include "plugins/activity/Windows.h"

#include "core/processing/OutputStreams.h"

#include <benchmark/benchmark.h>

#include <QFile>
#include <QThread>
#include <QJsonDocument>
#include <cstdio>
#include <cstdlib>
#include <optional>

using namespace athlos;
using namespace athlos::activity;

namespace {

struct Fixture {
    StreamInfo info;
    SimulatedRecording recording;
    std::vector<Window> windows;
    std::vector<TrainingSource> sources;
    TrainingOptions options;

    Fixture() {
        const Columns columns = columnsOf(ActivitySimulator::columnNames(), ActivitySimulator::columnUnits());
        info.name = QStringLiteral("imu");
        info.kind = QStringLiteral("imu");
        info.columns = columns;
        recording = ActivitySimulator::simulate(SimulatedPerson::random(99), 14, 5);
        windows = slidingWindows(recording.imu, 3.0, 1.5);
        for (unsigned person = 1; person <= 4; ++person) {
            SimulatedRecording r = ActivitySimulator::simulate(SimulatedPerson::random(person), 14, person);
            TrainingSource s;
            s.recording = s.athlete = QStringLiteral("p%1").arg(person);
            s.info = info;
            s.annotations = labelRunsOf(r);
            s.data = std::make_shared<const StreamData>(std::move(r.imu));
            sources.push_back(std::move(s));
        }
    }
    static Annotations labelRunsOf(const SimulatedRecording& r) {
        Annotations out;
        for (qsizetype i = 0; i < r.labels.size(); ++i) {
            if (out.empty() || out.back().label != r.labels[i]) {
                Annotation a;
                a.label = r.labels[i];
                a.tStart = r.imu.t[std::size_t(i)];
                out.push_back(a);
            }
            out.back().tEnd = r.imu.t[std::size_t(i)] + 0.02;
        }
        return out;
    }
};

Fixture& fixture() {
    static Fixture f;
    return f;
}

void FeatureExtraction(benchmark::State& state) {
    Fixture& f = fixture();
    auto extractor = FeatureExtractor::create(f.info, f.options.sensors);
    std::vector<float> out(std::size_t(extractor->size()));
    std::size_t i = 0;
    for (auto _ : state) {
        const Window& w = f.windows[i++ % f.windows.size()];
        extractor->compute(f.recording.imu, w.begin, w.end, out.data());
        benchmark::DoNotOptimize(out.data());
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(FeatureExtraction);

void FeaturesAndForest(benchmark::State& state) {
    Fixture& f = fixture();
    static const ActivityModel model = [&] {
        auto dataset = buildDataset(f.sources, f.options);
        return *trainModel(*dataset, f.options);
    }();
    auto extractor = FeatureExtractor::create(f.info, f.options.sensors);
    // One batch of 1000 windows per iteration, as classify-actions predicts a whole stream at once.
    const int batch = 1000;
    cv::Mat samples(batch, extractor->size(), CV_32F), p;
    std::size_t i = 0;
    for (auto _ : state) {
        for (int k = 0; k < batch; ++k) {
            const Window& w = f.windows[i++ % f.windows.size()];
            extractor->compute(f.recording.imu, w.begin, w.end, samples.ptr<float>(k));
        }
        model.probabilities(samples, p);
        benchmark::DoNotOptimize(p.data);
    }
    state.SetItemsProcessed(state.iterations() * batch);
}
BENCHMARK(FeaturesAndForest)->Unit(benchmark::kMillisecond);

void Training(benchmark::State& state) {
    Fixture& f = fixture();
    auto dataset = buildDataset(f.sources, f.options);
    for (auto _ : state) {
        auto model = trainModel(*dataset, f.options);
        benchmark::DoNotOptimize(model.ok());
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(dataset->labels.size()));
}
BENCHMARK(Training)->Unit(benchmark::kMillisecond)->UseRealTime()->MeasureProcessCPUTime()->Iterations(1);

// 100 000 labelled windows (3 s, step 1.5 s) of as many simulated people as it takes.
const Dataset& largeDataset() {
    static const Dataset d = [] {
        Fixture& f = fixture();
        std::vector<TrainingSource> sources;
        std::size_t windows = 0;
        for (unsigned person = 100; windows < 100000; ++person) {
            SimulatedRecording r = ActivitySimulator::simulate(SimulatedPerson::random(person), 14, person);
            TrainingSource s;
            s.recording = s.athlete = QStringLiteral("p%1").arg(person);
            s.info = f.info;
            s.annotations = Fixture::labelRunsOf(r);
            s.data = std::make_shared<const StreamData>(std::move(r.imu));
            windows += slidingWindows(*s.data, 3.0, 1.5).size() * 95 / 100;  // a few are unlabelled
            sources.push_back(std::move(s));
        }
        Dataset out = *buildDataset(sources, f.options);
        const int n = std::min(100000, out.samples.rows);
        out.samples = out.samples.rowRange(0, n).clone();
        out.labels.resize(std::size_t(n));
        out.source.resize(std::size_t(n));
        std::fprintf(stderr, "large dataset: %d windows of %zu people, %lld features\n", n, sources.size(),
                     qlonglong(out.features.size()));
        return out;
    }();
    return d;
}

// Windows of 12 more simulated people, never trained on: the held-out balanced accuracy of each forest.
const Dataset& heldOutDataset() {
    static const Dataset d = [] {
        Fixture& f = fixture();
        std::vector<TrainingSource> sources;
        for (unsigned person = 5000; person < 5012; ++person) {
            SimulatedRecording r = ActivitySimulator::simulate(SimulatedPerson::random(person), 14, person);
            TrainingSource s;
            s.recording = s.athlete = QStringLiteral("p%1").arg(person);
            s.info = f.info;
            s.annotations = Fixture::labelRunsOf(r);
            s.data = std::make_shared<const StreamData>(std::move(r.imu));
            sources.push_back(std::move(s));
        }
        TrainingOptions options = f.options;
        options.classes = largeDataset().classes;  // the same class indices
        return *buildDataset(sources, options);
    }();
    return d;
}

double heldOutBalancedAccuracy(const ActivityModel& model) {
    const Dataset& d = heldOutDataset();
    cv::Mat p;
    model.probabilities(d.samples, p);
    std::vector<double> correct(std::size_t(p.cols), 0), total(std::size_t(p.cols), 0);
    for (int i = 0; i < p.rows; ++i) {
        const float* row = p.ptr<float>(i);
        const int predicted = int(std::max_element(row, row + p.cols) - row);
        const auto truth = std::size_t(d.labels[std::size_t(i)]);
        total[truth] += 1;
        correct[truth] += predicted == int(truth);
    }
    double sum = 0;
    int present = 0;
    for (std::size_t c = 0; c < total.size(); ++c)
        if (total[c] > 0) {
            sum += correct[c] / total[c];
            ++present;
        }
    return present ? sum / present : 0.0;
}

void Training100k(benchmark::State& state) {
    const Dataset& d = largeDataset();
    heldOutDataset();
    TrainingOptions options = fixture().options;
    options.selectFeatures = int(state.range(0));
    options.classifier.trees = int(state.range(1));
    options.classifier.forestMaxRows = int(state.range(2));
    options.classifier.forestTreesPerPart = int(state.range(3));
    // One OpenCV forest of every tree (the forest before the parts) runs on one thread.
    options.classifier.threads = state.range(3) >= state.range(1) ? 1 : 0;
    std::optional<ActivityModel> model;
    for (auto _ : state) {
        auto trained = trainModel(d, options);
        if (!trained) {
            state.SkipWithError(qPrintable(trained.message()));
            return;
        }
        model = std::move(*trained);
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(d.labels.size()));
    state.counters["threads"] =
        options.classifier.threads > 0 ? options.classifier.threads : QThread::idealThreadCount();
    state.counters["heldout_bacc"] = heldOutBalancedAccuracy(*model);
}
// Args: features kept by MI (0: all 242), trees, rows per part at most (0: all), trees per part. The default
// of athlos train is {0, 100, 15000, 10}; {0, 100, 0, 100} is the single OpenCV forest it trained before.
// Wall time (real) and the CPU time of the whole process (all threads).
BENCHMARK(Training100k)
    ->Args({0, 100, 30000, 10})
    ->Args({0, 100, 20000, 10})
    ->Args({0, 100, 15000, 10})
    ->Args({0, 100, 0, 10})
    ->Args({0, 100, 0, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime()
    ->Iterations(1);

// The mutual-information ranking of all 242 features on the 100 000 windows (done once per CV fold with
// --select-features, equal-frequency bins).
void MutualInformation100k(benchmark::State& state) {
    const Dataset& d = largeDataset();
    for (auto _ : state) {
        const auto mi = mutualInformation(d.samples, d.labels, int(d.classes.size()), FeatureSelection::kDefaultBins);
        benchmark::DoNotOptimize(mi.data());
    }
    state.SetItemsProcessed(state.iterations() * std::int64_t(d.labels.size()));
}
BENCHMARK(MutualInformation100k)->Unit(benchmark::kMillisecond)->Iterations(1);

QByteArray testData(const QString& name) {
    QFile file(QStringLiteral(ATHLOS_BENCH_TEST_DATA_DIR "/activity/") + name);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

const ActivityModel& tinyCnn() {
    static const ActivityModel model = [] {
        auto m = importCnn(testData(QStringLiteral("tiny_cnn.onnx")),
                           QJsonDocument::fromJson(testData(QStringLiteral("tiny_cnn.json"))).object(),
                           QStringLiteral("tiny_cnn.onnx"));
        if (!m) {
            std::fprintf(stderr, "tiny_cnn.onnx: %s\n", qPrintable(m.message()));
            std::exit(1);
        }
        return *m;
    }();
    return model;
}

// Raw windows (channels × length) of the simulated stream, as classify-actions cuts them for the CNN.
cv::Mat rawBatch(const ActivityModel& model, std::size_t first, int batch) {
    Fixture& f = fixture();
    std::vector<int> columns;
    for (const QString& c : model.inputColumns) columns.push_back(f.info.columnIndex(c));
    const int length = model.cnn->length();
    static const std::vector<Window> windows = slidingWindows(f.recording.imu, model.window, model.step);
    cv::Mat raw(batch, model.cnn->channels() * length, CV_32F);
    for (int k = 0; k < batch; ++k) {
        const Window& w = windows[(first + std::size_t(k)) % windows.size()];
        rawWindow(f.recording.imu, columns, w.tStart, w.tEnd, length, raw.ptr<float>(k));
    }
    return raw;
}

void CnnInference(benchmark::State& state) {
    const ActivityModel& model = tinyCnn();
    const int batch = int(state.range(0));
    const cv::Mat raw = rawBatch(model, 0, batch);
    cv::Mat p;
    for (auto _ : state) {
        if (!model.cnn->probabilities(raw, p)) state.SkipWithError("cnn failed");
        benchmark::DoNotOptimize(p.data);
    }
    state.SetItemsProcessed(state.iterations() * batch);
}
BENCHMARK(CnnInference)->Arg(1)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

void RawWindowsAndCnn(benchmark::State& state) {
    const ActivityModel& model = tinyCnn();
    const int batch = 1000;
    std::size_t first = 0;
    cv::Mat p;
    for (auto _ : state) {
        const cv::Mat raw = rawBatch(model, first, batch);
        first += batch;
        if (!model.cnn->probabilities(raw, p)) state.SkipWithError("cnn failed");
        benchmark::DoNotOptimize(p.data);
    }
    state.SetItemsProcessed(state.iterations() * batch);
}
BENCHMARK(RawWindowsAndCnn)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
    cv::setNumThreads(1);  // one core, as the target says (OpenCV would otherwise spread predictions)
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
