#include "plugins/positioning/SimulateGatesProcessor.h"

#include "core/math/Angles.h"
#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/positioning/GateRunSimulator.h"
#include "plugins/positioning/GateTable.h"

#include <limits>

namespace athlos::positioning {

namespace {
constexpr Translator tr{"athlos::positioning", "SimulateGatesProcessor"};
}  // namespace

QString SimulateGatesProcessor::name() const { return tr("Simulate giant-slalom run with gate magnets"); }

QString SimulateGatesProcessor::description() const {
    return tr(
        "Simulates a giant-slalom run (turns about 27 m apart at 15-25 m/s, standing at start and finish) "
        "with a sacrum IMU (bias, noise, gyroscope drift, vibration) and magnets buried at the gates whose "
        "field adds to the magnetometer (Fasel thesis eq. 9.1), plus the truth and the gate table.");
}

ParameterSpecs SimulateGatesProcessor::parameters() const {
    const GateRunSimulator::Params d;
    using PS = ParameterSpec;
    return {
        PS::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(), tr("Random seed (deterministic).")),
        PS::integer(QStringLiteral("course_seed"), 0, 0, std::numeric_limits<int>::max(),
                    tr("Seed of the gates' magnet offsets; the same value gives the same course for several runs (0: "
                       "from seed).")),
        PS::integer(QStringLiteral("gates"), d.gates, 2, 200, tr("Number of gates (one turn each).")),
        PS::number(QStringLiteral("gate_spacing"), d.gateSpacing, 10.0, 100.0, QStringLiteral("m"),
                   tr("Distance between turns along the fall line (thesis course: 21.8-27.8 m between gates).")),
        PS::number(QStringLiteral("amplitude"), d.amplitude, 0.0, 20.0, QStringLiteral("m"),
                   tr("Lateral excursion of the sacrum line.")),
        PS::number(QStringLiteral("slope"), d.slope, 0.0, 0.8, QStringLiteral("rad"), tr("Slope angle.")),
        PS::number(QStringLiteral("mean_speed"), d.meanSpeed, 2.0, 40.0, QStringLiteral("m/s"), tr("Mean speed.")),
        PS::number(QStringLiteral("speed_amplitude"), d.speedAmplitude, 0.0, 20.0, QStringLiteral("m/s"),
                   tr("Slow speed variation around the mean.")),
        PS::number(QStringLiteral("imu_rate"), d.imuRate, 50.0, 1000.0, QStringLiteral("Hz"),
                   tr("Sampling rate of the IMU (acc, gyr, mag).")),
        PS::number(QStringLiteral("gyr_bias"), d.gyrBias, 0.0, 0.1, QStringLiteral("rad/s"),
                   tr("Gyroscope bias, SD per axis (0.15 deg/s drift).")),
        PS::number(QStringLiteral("rest"), d.restStart, 0.5, 60.0, QStringLiteral("s"),
                   tr("Standing time at the start and at the finish.")),
    };
}

QList<OutputSpec> SimulateGatesProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("imu"), false, QString(), tr("Simulated sacrum IMU: acc, gyr, mag.")},
            OutputSpec{QStringLiteral("trajectory"), false, QStringLiteral("truth"),
                       tr("Ground truth x, y, z (m), vx, vy, vz, speed (m/s), ENU.")},
            OutputSpec{QStringLiteral("gates"), true, QStringLiteral("gates"),
                       tr("Magnet positions: id, east, north, up (m).")}};
}

Expected<std::vector<ProcessorOutput>> SimulateGatesProcessor::run(const RunContext& c) const {
    GateRunSimulator::Params p;
    p.seed = static_cast<std::uint64_t>(c.integer(QStringLiteral("seed")));
    p.courseSeed = static_cast<std::uint64_t>(c.integer(QStringLiteral("course_seed")));
    p.gates = c.integer(QStringLiteral("gates"));
    p.gateSpacing = c.number(QStringLiteral("gate_spacing"));
    p.amplitude = c.number(QStringLiteral("amplitude"));
    p.slope = c.number(QStringLiteral("slope"));
    p.meanSpeed = c.number(QStringLiteral("mean_speed"));
    p.speedAmplitude = c.number(QStringLiteral("speed_amplitude"));
    p.imuRate = c.number(QStringLiteral("imu_rate"));
    p.gyrBias = c.number(QStringLiteral("gyr_bias"));
    p.restStart = p.restEnd = c.number(QStringLiteral("rest"));
    if (p.speedAmplitude >= p.meanSpeed)
        return makeError(QStringLiteral("parameter 'speed_amplitude' must be below 'mean_speed'"));
    c.report(0.0, QStringLiteral("simulating"));
    const auto sim = GateRunSimulator::simulate(p);
    if (c.isCancelled()) return cancelledError();

    const std::size_t n = sim.t.size();
    StreamData imu(n, 9);
    imu.t = sim.t;
    StreamData truth(n, 7);
    truth.t = sim.t;
    for (std::size_t k = 0; k < n; ++k) {
        for (int i = 0; i < 3; ++i) {
            imu.at(k, i) = sim.acc[k][i];
            imu.at(k, 3 + i) = sim.gyr[k][i];
            imu.at(k, 6 + i) = sim.mag[k][i];
            truth.at(k, i) = sim.position[k][i];
            truth.at(k, 3 + i) = sim.velocity[k][i];
        }
        truth.at(k, 6) = sim.velocity[k].norm();
    }
    const QJsonObject simulated{{QStringLiteral("simulated"), true}, {QStringLiteral("sampling_rate"), p.imuRate}};
    Stream imuStream =
        outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                     columnsOf({"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "mag_x", "mag_y", "mag_z"},
                               {"m/s^2", "m/s^2", "m/s^2", "rad/s", "rad/s", "rad/s", "uT", "uT", "uT"}),
                     std::move(imu), simulated);
    Stream truthStream =
        outputStream(QStringLiteral("trajectory"), QStringLiteral("ENU"),
                     columnsOf({"x", "y", "z", "vx", "vy", "vz", "speed"}, {"m", "m", "m", "m/s", "m/s", "m/s", "m/s"}),
                     std::move(truth), simulated);

    Table gates = gatesTable(sim.gates);
    gates.attributes =
        QJsonObject{{QStringLiteral("simulated"), true}, {QStringLiteral("frame"), QStringLiteral("ENU")}};

    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(imuStream)});
    outputs.push_back({QStringLiteral("truth"), std::move(truthStream)});
    outputs.push_back({QStringLiteral("gates"), std::move(gates)});
    c.report(1.0);
    return outputs;
}

}  // namespace athlos::positioning
