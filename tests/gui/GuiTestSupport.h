#pragma once
// Shared by the GUI tests: a small in-memory project with an IMU stream, a position stream on a
// 400 m track, a beacon table and a processor result with provenance.
#include "core/model/Project.h"

#include <QDateTime>
#include <QDir>
#include <QSettings>
#include <QStandardPaths>
#include <cmath>
#include <memory>
#include <numbers>

namespace athlos::testing {

inline Stream makeImuStream(std::size_t rows = 2000, double rate = 100.0) {
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.frame = QStringLiteral("sensor");
    info.columns = {{"acc_x", "m/s^2"}, {"acc_y", "m/s^2"}, {"acc_z", "m/s^2"},
                    {"gyr_x", "rad/s"}, {"gyr_y", "rad/s"}, {"gyr_z", "rad/s"}};
    StreamData data(rows, 6);
    for (std::size_t i = 0; i < rows; ++i) {
        const double t = double(i) / rate;
        data.t[i] = t;
        data.at(i, 0) = std::sin(2 * std::numbers::pi * 1.0 * t);
        data.at(i, 1) = 0.5 * std::cos(2 * std::numbers::pi * 0.5 * t);
        data.at(i, 2) = 9.81 + 0.2 * std::sin(2 * std::numbers::pi * 3.0 * t);
        data.at(i, 3) = 0.1 * t;
        data.at(i, 4) = -0.3;
        data.at(i, 5) = std::sin(t);
    }
    return Stream(std::move(info), std::move(data));
}

// One lap of the 400 m track (straights along x, bend centres at ±42.195 m).
inline Stream makeTrackStream(std::size_t rows = 800) {
    StreamInfo info;
    info.kind = QStringLiteral("lps-position");
    info.frame = QStringLiteral("track");
    info.columns = {{"x", "m"}, {"y", "m"}, {"z", "m"}};
    StreamData data(rows, 3);
    const double r = 36.8, straight = 84.39;
    const double lap = 2 * straight + 2 * std::numbers::pi * r;
    for (std::size_t i = 0; i < rows; ++i) {
        const double s = lap * double(i) / double(rows);  // distance along the lap, start of home straight
        double x, y;
        if (s < straight) {
            x = -42.195 + s;
            y = -r;
        } else if (s < straight + std::numbers::pi * r) {
            const double a = -std::numbers::pi / 2 + (s - straight) / r;
            x = 42.195 + r * std::cos(a);
            y = r * std::sin(a);
        } else if (s < 2 * straight + std::numbers::pi * r) {
            x = 42.195 - (s - straight - std::numbers::pi * r);
            y = r;
        } else {
            const double a = std::numbers::pi / 2 + (s - 2 * straight - std::numbers::pi * r) / r;
            x = -42.195 + r * std::cos(a);
            y = r * std::sin(a);
        }
        data.t[i] = 0.1 * double(i);
        data.at(i, 0) = x;
        data.at(i, 1) = y;
        data.at(i, 2) = 0.0;
    }
    return Stream(std::move(info), std::move(data));
}

inline Table makeBeaconTable() {
    Table table;
    table.kind = QStringLiteral("beacons");
    TableColumn id{QStringLiteral("id"), {}, true, {}, {QStringLiteral("B1"), QStringLiteral("B2")}};
    TableColumn x{QStringLiteral("x"), QStringLiteral("m"), false, {-50.0, 50.0}, {}};
    TableColumn y{QStringLiteral("y"), QStringLiteral("m"), false, {-40.0, 40.0}, {}};
    table.columns = {id, x, y};
    return table;
}

inline std::unique_ptr<Project> makeProject(const QString& path) {
    std::unique_ptr<Project> project = Project::create(path, QStringLiteral("athletics"));
    project->putStream(QStringLiteral("run1/imu"), makeImuStream());
    project->putStream(QStringLiteral("run1/lps"), makeTrackStream());
    project->putTable(QStringLiteral("run1/beacons"), makeBeaconTable());

    Stream filtered = makeImuStream(500);
    Provenance p;
    p.processorId = QStringLiteral("butterworth");
    p.processorVersion = QStringLiteral("1.0");
    p.parameters = QJsonObject{{"cutoff", 5.0}, {"order", 4}};
    p.inputs = {{QStringLiteral("run1/imu"), QByteArray("0123456789abcdef")}};
    p.appVersion = QStringLiteral("0.1.0");
    p.time = QDateTime(QDate(2024, 5, 1), QTime(12, 0), Qt::UTC);
    filtered.info().provenance = p;
    project->putStream(QStringLiteral("run2/imu-filtered"), std::move(filtered));
    return project;
}

// Keeps QSettings (recent projects) of the tests away from the user's.
inline void isolateSettings(const QString& dir) {
    QStandardPaths::setTestModeEnabled(true);
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir);
}

}  // namespace athlos::testing
