#pragma once
// Test helpers: simulated wrist-IMU recordings in a project, and sample-wise scoring of predicted
// annotations against the per-sample ground truth.
#include "core/io/AnnotationIo.h"
#include "core/model/Project.h"
#include "core/processing/OutputStreams.h"
#include "plugins/activity/ActivitySimulator.h"

#include <map>
#include <set>

namespace athlos::activity::test {

// Adds <rec>/imu (kind imu) and, with labels, its ground truth as imported annotations. Returns the
// per-sample labels.
inline SimulatedRecording addSimulated(Project& project, const QString& rec, unsigned person, int segments,
                                       bool labels) {
    SimulatedRecording sim =
        ActivitySimulator::simulate(SimulatedPerson::random(person), segments, person * 7919u + 1u);
    StreamData data = sim.imu;
    project.putStream(
        rec + QStringLiteral("/imu"),
        outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                     columnsOf(ActivitySimulator::columnNames(), ActivitySimulator::columnUnits()), std::move(data)));
    Recording& r = *project.recording(rec);
    r.metadata[QStringLiteral("athlete")] = QStringLiteral("person %1").arg(person);
    if (labels) r.annotations = labelRuns(sim.imu.t, sim.labels, QStringLiteral("import"), QStringLiteral("sim"));
    return sim;
}

// Balanced accuracy over samples: the label of the annotation covering each sample's time.
inline double sampleBalancedAccuracy(const std::vector<double>& t, const QStringList& truth,
                                     const Annotations& predicted) {
    std::map<QString, std::pair<long long, long long>> perClass;  // correct, total
    std::size_t a = 0;
    for (std::size_t i = 0; i < t.size(); ++i) {
        while (a + 1 < predicted.size() && predicted[a].tEnd <= t[i]) ++a;
        const QString label = predicted.empty() ? QString() : predicted[a].label;
        auto& c = perClass[truth[qsizetype(i)]];
        c.first += label == truth[qsizetype(i)];
        c.second += 1;
    }
    double sum = 0;
    for (const auto& [label, c] : perClass) sum += double(c.first) / double(c.second);
    return perClass.empty() ? 0.0 : sum / double(perClass.size());
}

}  // namespace athlos::activity::test
