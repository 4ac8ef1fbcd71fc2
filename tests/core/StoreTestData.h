#pragma once
// Test data for the project store tests: a project with every kind of content, and file helpers.
#include "core/model/Project.h"

#include <hdf5.h>

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <random>

namespace athlos::test {

// Strictly increasing, deliberately non-uniform times (jittered ~100 Hz) and noisy values.
inline StreamData makeSamples(std::size_t rows, int columns, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> jitter(0.0, 0.004), value(-50.0, 50.0);
    StreamData data(rows, columns);
    double t = 12.5;
    for (std::size_t i = 0; i < rows; ++i) {
        t += 0.008 + jitter(rng);
        data.t[i] = t;
        for (int c = 0; c < columns; ++c) data.at(i, c) = value(rng);
    }
    return data;
}

inline Stream makeStream(const QString& kind, const Columns& columns, StreamData data, Provenance provenance = {}) {
    StreamInfo info;
    info.kind = kind;
    info.frame = QStringLiteral("sensor");
    info.columns = columns;
    info.attributes =
        QJsonObject{{QStringLiteral("sampling_rate"), 100.0}, {QStringLiteral("device"), QStringLiteral("Gerät µ-7")}};
    info.provenance = std::move(provenance);
    return Stream(std::move(info), std::move(data));
}

inline Columns imuColumns() {
    return {{"acc_x", "m/s^2"}, {"acc_y", "m/s^2"}, {"acc_z", "m/s^2"},
            {"gyr_x", "rad/s"}, {"gyr_y", "rad/s"}, {"gyr_z", "rad/s"}};
}

// A project with every kind of content the store knows.
inline std::unique_ptr<Project> makeFullProject(const QString& path) {
    auto project = Project::create(path, QStringLiteral("athletics"));
    project->meta().extra =
        QJsonObject{{QStringLiteral("venue"), QStringLiteral("Stade Charléty")}, {QStringLiteral("laps"), 4}};

    project->putStream(QStringLiteral("run1/imu"),
                       makeStream(QStringLiteral("imu"), imuColumns(), makeSamples(1000, 6, 1)));
    project->putStream(
        QStringLiteral("run1/empty"),
        makeStream(QStringLiteral("lps-position"), {{"x", "m"}, {"y", "m"}, {"z", "m"}}, StreamData(0, 3)));
    project->putStream(QStringLiteral("run1/events"), makeStream(QStringLiteral("events"), {}, makeSamples(7, 0, 2)));
    // Several chunks and several write blocks.
    project->putStream(
        QStringLiteral("run2/lps"),
        makeStream(QStringLiteral("lps-position"), {{"x", "m"}, {"y", "m"}, {"z", "m"}}, makeSamples(300000, 3, 3)));

    Provenance provenance;
    provenance.processorId = QStringLiteral("signal.butterworth");
    provenance.processorVersion = QStringLiteral("1.2.0");
    provenance.parameters = QJsonObject{{QStringLiteral("cutoff"), 6.0}, {QStringLiteral("order"), 4}};
    provenance.inputs = {{QStringLiteral("run2/lps"), project->stream(QStringLiteral("run2/lps"))->info().contentHash}};
    provenance.appVersion = QStringLiteral("0.1.0");
    provenance.time = QDateTime(QDate(2024, 5, 17), QTime(9, 30, 12, 345), Qt::UTC);
    project->putStream(
        QStringLiteral("run2/filtered"),
        makeStream(QStringLiteral("trajectory"), {{"x", "m"}, {"y", "m"}}, makeSamples(500, 2, 4), provenance));

    Table beacons;
    beacons.kind = QStringLiteral("beacons");
    beacons.attributes = QJsonObject{{QStringLiteral("surveyed"), QStringLiteral("2024-05-01")}};
    beacons.provenance.processorId = QStringLiteral("import:csv");
    beacons.provenance.sourceFile = QStringLiteral("/data/beacons ä.csv");
    beacons.columns = {
        {QStringLiteral("id"), {}, true, {}, {QStringLiteral("B1"), QStringLiteral("Bäke 2"), QString()}},
        {QStringLiteral("x"), QStringLiteral("m"), false, {0.0, 42.195, -1e-300}, {}},
        {QStringLiteral("a/b"), QStringLiteral("m"), false, {1.0, 2.0, 3.0}, {}},
        {QStringLiteral("x"), QStringLiteral("s"), false, {4.0, 5.0, 6.0}, {}}};
    project->putTable(QStringLiteral("run1/beacons"), beacons);
    Table empty;
    empty.kind = QStringLiteral("report");
    project->putTable(QStringLiteral("run2/report"), empty);

    project->ensureRecording(QStringLiteral("run1")).metadata = QJsonObject{
        {QStringLiteral("athlete"), QStringLiteral("Zoë")}, {QStringLiteral("date"), QStringLiteral("2024-05-17")}};
    project->ensureRecording(QStringLiteral("run1")).annotations = {
        {QStringLiteral("sprint"), 13.0, 15.5, QStringLiteral("anna"), 0.9, QStringLiteral("manual")},
        {QStringLiteral("Fußaufsatz"), 14.0, 14.0, QString(), 1.0, QStringLiteral("events.footstrike")}};
    // A recording holding only metadata and annotations.
    Recording& notes = project->ensureRecording(QStringLiteral("Notizen äö"));
    notes.metadata = QJsonObject{{QStringLiteral("notes"), QStringLiteral("warm-up only")}};
    notes.annotations = {{QStringLiteral("jog"), 0.0, 600.0, QStringLiteral("coach"), 0.5, QStringLiteral("manual")}};

    project->geometry()[QStringLiteral("track400")] =
        QJsonObject{{QStringLiteral("type"), QStringLiteral("track")}, {QStringLiteral("radius"), 36.5}};
    project->geometry()[QStringLiteral("beacons-north")] =
        QJsonObject{{QStringLiteral("type"), QStringLiteral("beacons")}};
    project->annotationClasses() = {QStringLiteral("sprint"), QStringLiteral("jog"), QStringLiteral("Ruhe")};
    project->pipelineHistory().append(
        QJsonObject{{QStringLiteral("name"), QStringLiteral("clean")},
                    {QStringLiteral("steps"), QJsonArray{QStringLiteral("signal.butterworth")}}});
    return project;
}

inline QByteArray fileBytes(const QString& path) {
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

inline bool writeBytes(const QString& path, const QByteArray& bytes) {
    QFile file(path);
    return file.open(QIODevice::WriteOnly | QIODevice::Truncate) && file.write(bytes) == bytes.size();
}

// Files in dir other than the ones named.
inline QStringList strayFiles(const QString& dir, const QStringList& expected) {
    QStringList stray;
    for (const QString& name : QDir(dir).entryList(QDir::Files | QDir::Hidden | QDir::NoDotAndDotDot))
        if (!expected.contains(name)) stray << name;
    return stray;
}

// Tests tamper with files through the HDF5 C API; expected failures should not spam stderr.
inline void quietHdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

}  // namespace athlos::test
