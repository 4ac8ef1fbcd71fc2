// Activity recognition on the wrist-IMU simulator, in the form of Table 5.2 of the thesis (seed 000):
// balanced accuracy of each classifier with leave-one-subject-out cross-validation on 3 s windows
// (step 1.5 s), plus the sample-wise balanced accuracy of the default random forest on held-out
// people through the full classify path (smoothing 0 and 1). Figures: docs/validation/activity.md.
//
//   build/bin/athlos-eval-activity [--people N] [--segments S] [--test-people M] [--classifiers C1,C2]
//                                  [--select-features K1,K2]   (a row per classifier and number of features
//                                  kept by mutual information, ranked inside each fold; 0: all)
//                                  [--forest-rows N]   (random forest: rows per part of 10 trees at most; 0: all)
#include "plugins/activity/ActivitySimulator.h"
#include "plugins/activity/ActivityTraining.h"
#include "tools/eval/ClassifierComparison.h"

#include "core/processing/OutputStreams.h"

#include <QCoreApplication>
#include <cstdio>
#include <map>

using namespace athlos;
using namespace athlos::activity;

namespace {
Annotations runsOf(const SimulatedRecording& r) {
    Annotations out;
    const double dt = r.imu.t.size() > 1 ? r.imu.t[1] - r.imu.t[0] : 0.02;
    for (qsizetype i = 0; i < r.labels.size(); ++i) {
        if (out.empty() || out.back().label != r.labels[i]) {
            Annotation a;
            a.label = r.labels[i];
            a.tStart = r.imu.t[std::size_t(i)];
            out.push_back(a);
        }
        out.back().tEnd = r.imu.t[std::size_t(i)] + dt;
    }
    return out;
}

double sampleBalancedAccuracy(const SimulatedRecording& r, const Annotations& predicted) {
    std::map<QString, std::pair<long long, long long>> perClass;
    std::size_t a = 0;
    for (std::size_t i = 0; i < r.imu.t.size(); ++i) {
        while (a + 1 < predicted.size() && predicted[a].tEnd <= r.imu.t[i]) ++a;
        auto& c = perClass[r.labels[qsizetype(i)]];
        c.first += predicted[a].label == r.labels[qsizetype(i)];
        c.second += 1;
    }
    double sum = 0;
    for (const auto& [label, c] : perClass) sum += double(c.first) / double(c.second);
    return sum / double(perClass.size());
}
}  // namespace

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    int people = 10, segments = 14, testPeople = 4;
    QStringList classifiers = Classifier::kinds();
    std::vector<int> selections;  // empty: the classifier table with every feature
    int forestRows = ClassifierOptions{}.forestMaxRows;
    const QStringList args = app.arguments();
    for (qsizetype i = 1; i + 1 < args.size(); i += 2) {
        if (args[i] == u"--people") people = args[i + 1].toInt();
        if (args[i] == u"--segments") segments = args[i + 1].toInt();
        if (args[i] == u"--test-people") testPeople = args[i + 1].toInt();
        if (args[i] == u"--forest-rows") forestRows = args[i + 1].toInt();
        if (args[i] == u"--classifiers") classifiers = args[i + 1].split(QLatin1Char(','), Qt::SkipEmptyParts);
        if (args[i] == u"--select-features")
            for (const QString& k : args[i + 1].split(QLatin1Char(','), Qt::SkipEmptyParts))
                selections.push_back(k.toInt());
    }
    StreamInfo info;
    info.name = info.kind = QStringLiteral("imu");
    info.columns = columnsOf(ActivitySimulator::columnNames(), ActivitySimulator::columnUnits());
    std::vector<TrainingSource> sources;
    for (int p = 1; p <= people; ++p) {
        SimulatedRecording r =
            ActivitySimulator::simulate(SimulatedPerson::random(unsigned(p)), segments, unsigned(p) * 7919u + 1u);
        TrainingSource s;
        s.recording = s.athlete = QStringLiteral("person%1").arg(p);
        s.info = info;
        s.annotations = runsOf(r);
        s.data = std::make_shared<const StreamData>(std::move(r.imu));
        sources.push_back(std::move(s));
    }
    TrainingOptions options;
    options.classifier.forestMaxRows = forestRows;
    auto dataset = buildDataset(sources, options);
    if (!dataset) {
        std::fprintf(stderr, "%s\n", qPrintable(dataset.message()));
        return 1;
    }
    std::printf("%d simulated people, %zu windows of 3 s (step 1.5 s), %lld features, %lld classes\n\n", people,
                dataset->labels.size(), qlonglong(dataset->features.size()), qlonglong(dataset->classes.size()));
    if (printClassifierComparison(*dataset, sources, options, classifiers, selections,
                                  "balanced accuracy (leave-one-subject-out)") != 0)
        return 1;

    // The judged path: the default model on everyone above, classify-actions on unseen people.
    auto model = trainModel(*dataset, options);
    if (!model) return 1;
    std::printf("\nheld-out people, random forest, sample-wise balanced accuracy (smoothing 0 / 1 / 2):\n");
    for (int p = 1; p <= testPeople; ++p) {
        const unsigned id = 1000u + unsigned(p);
        SimulatedRecording r = ActivitySimulator::simulate(SimulatedPerson::random(id), segments, id * 7919u + 1u);
        std::printf("person %u:", id);
        for (int smoothing : {0, 1, 2}) {
            auto predicted = model->classify(info, r.imu, smoothing);
            std::printf(" %.3f", predicted ? sampleBalancedAccuracy(r, *predicted) : 0.0);
        }
        std::printf("\n");
    }
    return 0;
}
