// Activity recognition throughput (issue #14: ≥ 10 000 windows/s on one core for features + random
// forest). items_per_second = windows/s (CPU time, OpenCV limited to one thread): FeatureExtraction computes the 143 features of 3 s windows
// (50 Hz, acc + gyr) of a simulated wrist IMU; FeaturesAndForest adds scaling and the class
// probabilities of the default (100-tree) random forest trained on 4 simulated people; Training trains that forest.
#include "plugins/activity/ActivityModel.h"
#include "plugins/activity/ActivitySimulator.h"
#include "plugins/activity/ActivityTraining.h"
#include "plugins/activity/FeatureExtractor.h"
#include "plugins/activity/Windows.h"

#include "core/processing/OutputStreams.h"

#include <benchmark/benchmark.h>

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
BENCHMARK(Training)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
    cv::setNumThreads(1);  // one core, as the target says (OpenCV would otherwise spread predictions)
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
