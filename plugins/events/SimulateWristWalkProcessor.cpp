#include "plugins/events/SimulateWristWalkProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/events/WristWalkSimulator.h"

#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "SimulateWristWalkProcessor"};
}  // namespace

QString SimulateWristWalkProcessor::name() const { return tr("Simulate wrist walking"); }

QString SimulateWristWalkProcessor::description() const {
    return tr(
        "Simulates a wrist-worn IMU and barometer during outdoor walking bouts (cadence changing over time, "
        "uphill, downhill and flat paths, arm swing, some bouts with the hand held still) and pauses "
        "(standing, arm gestures), with the truth: cadence, speed, grade, altitude and walking per 0.1 s.");
}

ParameterSpecs SimulateWristWalkProcessor::parameters() const {
    const WristWalkParams d;
    using PS = ParameterSpec;
    return {
        PS::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(), tr("Random seed (deterministic).")),
        PS::number(QStringLiteral("duration"), d.duration, 30.0, 86400.0, QStringLiteral("s"),
                   tr("Length of the recording.")),
        PS::number(QStringLiteral("rate"), d.rate, 25.0, 1000.0, QStringLiteral("Hz"), tr("IMU sampling rate.")),
        PS::number(QStringLiteral("height"), d.height, 1.0, 2.3, QStringLiteral("m"),
                   tr("The walker's height (step length scales with it).")),
        PS::number(QStringLiteral("cadence_min"), d.cadenceMin, 40.0, 200.0, QStringLiteral("steps/min"),
                   tr("Lowest walking cadence.")),
        PS::number(QStringLiteral("cadence_max"), d.cadenceMax, 40.0, 200.0, QStringLiteral("steps/min"),
                   tr("Highest walking cadence.")),
        PS::number(QStringLiteral("max_grade"), d.maxGrade, 0.0, 0.5, QString(),
                   tr("Steepest path (rise over run) of a walking bout.")),
        PS::number(QStringLiteral("walking_share"), d.walkingShare, 0.1, 0.95, QString(),
                   tr("Fraction of the time spent walking.")),
        PS::number(QStringLiteral("acc_noise"), d.accNoise, 0.0, 5.0, QStringLiteral("m/s^2"),
                   tr("Accelerometer white noise (1 SD).")),
        PS::number(QStringLiteral("baro_noise"), d.baroNoise, 0.0, 100.0, QStringLiteral("Pa"),
                   tr("Barometer white noise (1 SD).")),
        PS::number(QStringLiteral("baro_drift"), d.baroDrift, 0.0, 1000.0, QStringLiteral("Pa/h"),
                   tr("Weather drift of the pressure (sign random).")),
    };
}

QList<OutputSpec> SimulateWristWalkProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("imu"), false, QString(), tr("Wrist IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).")},
            OutputSpec{QStringLiteral("barometer"), false, QStringLiteral("barometer"), tr("Pressure (Pa) at 25 Hz.")},
            OutputSpec{QStringLiteral("reference"), false, QStringLiteral("truth"),
                       tr("Truth: cadence (steps/min), speed (m/s), grade, altitude (m), walking (1/0).")}};
}

Expected<std::vector<ProcessorOutput>> SimulateWristWalkProcessor::run(const RunContext& c) const {
    WristWalkParams p;
    p.seed = std::uint64_t(c.integer(QStringLiteral("seed")));
    p.duration = c.number(QStringLiteral("duration"));
    p.rate = c.number(QStringLiteral("rate"));
    p.height = c.number(QStringLiteral("height"));
    p.cadenceMin = c.number(QStringLiteral("cadence_min"));
    p.cadenceMax = c.number(QStringLiteral("cadence_max"));
    p.maxGrade = c.number(QStringLiteral("max_grade"));
    p.walkingShare = c.number(QStringLiteral("walking_share"));
    p.accNoise = c.number(QStringLiteral("acc_noise"));
    p.baroNoise = c.number(QStringLiteral("baro_noise"));
    p.baroDrift = c.number(QStringLiteral("baro_drift"));
    if (p.cadenceMax <= p.cadenceMin)
        return makeError(QStringLiteral("cadence_max: %1 steps/min must be above cadence_min (%2 steps/min)")
                             .arg(p.cadenceMax)
                             .arg(p.cadenceMin));
    c.report(0.0, QStringLiteral("simulating"));
    if (c.isCancelled()) return cancelledError();
    WristWalkRecording rec = simulateWristWalk(p);
    if (c.isCancelled()) return cancelledError();

    StreamData imu;
    imu.columns = 6;
    imu.t = std::move(rec.t);
    imu.values = std::move(rec.imu);
    StreamData baro;
    baro.columns = 1;
    baro.t = std::move(rec.tBaro);
    baro.values = std::move(rec.pressure);
    StreamData truth(rec.tTruth.size(), 5);
    truth.t = rec.tTruth;
    for (std::size_t k = 0; k < truth.rows(); ++k) {
        truth.at(k, 0) = rec.cadence[k];
        truth.at(k, 1) = rec.speed[k];
        truth.at(k, 2) = rec.grade[k];
        truth.at(k, 3) = rec.altitude[k];
        truth.at(k, 4) = rec.walking[k];
    }
    const QJsonObject attributes{{QStringLiteral("simulated"), true},
                                 {QStringLiteral("height"), p.height},
                                 {QStringLiteral("placement"), QStringLiteral("wrist")}};
    std::vector<ProcessorOutput> out;
    out.push_back({QString(), outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                                           columnsOf({"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"},
                                                     {"m/s^2", "m/s^2", "m/s^2", "rad/s", "rad/s", "rad/s"}),
                                           std::move(imu), attributes)});
    out.push_back(
        {QStringLiteral("barometer"), outputStream(QStringLiteral("barometer"), QString(),
                                                   columnsOf({"pressure"}, {"Pa"}), std::move(baro), attributes)});
    QJsonObject truthAttributes = attributes;
    truthAttributes.insert(QStringLiteral("subject_step_factor"), rec.subjectFactor);
    out.push_back({QStringLiteral("truth"), outputStream(QStringLiteral("reference"), QStringLiteral("ENU"),
                                                         columnsOf({"cadence", "speed", "grade", "altitude", "walking"},
                                                                   {"steps/min", "m/s", "1", "m", "1"}),
                                                         std::move(truth), truthAttributes)});
    c.report(1.0);
    return out;
}

}  // namespace athlos::events
