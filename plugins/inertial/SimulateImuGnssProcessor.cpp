#include "plugins/inertial/SimulateImuGnssProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/ImuGnssSimulator.h"

#include <cmath>
#include <limits>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "SimulateImuGnssProcessor"};
}  // namespace

QString SimulateImuGnssProcessor::name() const { return tr("Simulate IMU and GNSS"); }

QString SimulateImuGnssProcessor::description() const {
    return tr(
        "Simulated football session with known truth: sprints from standstill, decelerations, turns and jogging. "
        "IMU (acc, gyr, mag) with bias, noise, scale errors and saturation at <output>; GNSS (local ENU x, y, z, "
        "vx, vy, vz) with white and slowly correlated errors at <output>-gnss; the truth at <output>-truth.");
}

ParameterSpecs SimulateImuGnssProcessor::parameters() const {
    const SimulatorParams d;
    return {
        ParameterSpec::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(), tr("Random seed.")),
        ParameterSpec::number(QStringLiteral("duration"), d.duration, 10.0, 36000.0, QStringLiteral("s"),
                              tr("Length of the session.")),
        ParameterSpec::number(QStringLiteral("imu_rate"), d.imuRate, 10.0, 10000.0, QStringLiteral("Hz"),
                              tr("IMU sampling rate.")),
        ParameterSpec::number(QStringLiteral("gnss_rate"), d.gnssRate, 0.1, 100.0, QStringLiteral("Hz"),
                              tr("GNSS rate (the IMU rate must be a multiple of it).")),
        ParameterSpec::number(QStringLiteral("gnss_sigma"), d.gnssHorizontalSigma, 0.0, 100.0, QStringLiteral("m"),
                              tr("Horizontal RMS of the white GNSS position error.")),
        ParameterSpec::number(QStringLiteral("gyr_bias"), d.gyrBias, 0.0, 1.0, QStringLiteral("rad/s"),
                              tr("Largest gyroscope bias per axis (drawn uniformly).")),
    };
}

QList<OutputSpec> SimulateImuGnssProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("imu"), false, QString(), tr("acc_x..z, gyr_x..z, mag_x..z.")},
            OutputSpec{QStringLiteral("gnss"), false, QStringLiteral("gnss"), tr("x, y, z, vx, vy, vz (ENU).")},
            OutputSpec{QStringLiteral("trajectory"), false, QStringLiteral("truth"),
                       tr("True x, y, z, vx, vy, vz, qw..qz, speed, distance.")}};
}

Expected<std::vector<ProcessorOutput>> SimulateImuGnssProcessor::run(const RunContext& c) const {
    SimulatorParams p;
    if (c.has(QStringLiteral("seed"))) p.seed = static_cast<std::uint64_t>(c.integer(QStringLiteral("seed")));
    if (c.has(QStringLiteral("duration"))) p.duration = c.number(QStringLiteral("duration"));
    if (c.has(QStringLiteral("imu_rate"))) p.imuRate = c.number(QStringLiteral("imu_rate"));
    if (c.has(QStringLiteral("gnss_rate"))) p.gnssRate = c.number(QStringLiteral("gnss_rate"));
    if (c.has(QStringLiteral("gnss_sigma"))) p.gnssHorizontalSigma = c.number(QStringLiteral("gnss_sigma"));
    if (c.has(QStringLiteral("gyr_bias"))) p.gyrBias = c.number(QStringLiteral("gyr_bias"));
    const double ratio = p.imuRate / p.gnssRate;
    if (std::abs(ratio - std::round(ratio)) > 1e-9)
        return makeError(
            QStringLiteral("gnss_rate: %1 Hz does not divide imu_rate %2 Hz").arg(p.gnssRate).arg(p.imuRate));
    c.report(0.1, QStringLiteral("simulating"));
    const SimulatedData d = simulateImuGnss(p);
    if (c.isCancelled()) return cancelledError();
    const std::size_t n = d.imuT.size();
    StreamData imu(n, 9), truth(n, 12), gnss(d.gnssT.size(), 6);
    imu.t = truth.t = d.imuT;
    for (std::size_t k = 0; k < n; ++k) {
        for (int i = 0; i < 3; ++i) {
            imu.at(k, i) = d.acc[k][i];
            imu.at(k, 3 + i) = d.gyr[k][i];
            imu.at(k, 6 + i) = d.mag[k][i];
            truth.at(k, i) = d.position[k][i];
            truth.at(k, 3 + i) = d.velocity[k][i];
        }
        const Quat& q = d.orientation[k];
        truth.at(k, 6) = q.w();
        truth.at(k, 7) = q.x();
        truth.at(k, 8) = q.y();
        truth.at(k, 9) = q.z();
        truth.at(k, 10) = d.velocity[k].head<2>().norm();
        truth.at(k, 11) = d.distance[k];
    }
    gnss.t = d.gnssT;
    for (std::size_t g = 0; g < d.gnssT.size(); ++g)
        for (int i = 0; i < 3; ++i) {
            gnss.at(g, i) = d.gnssPosition[g][i];
            gnss.at(g, 3 + i) = d.gnssVelocity[g][i];
        }
    const QJsonObject attrs{{"simulated", true}, {"seed", static_cast<double>(p.seed)}};
    std::vector<ProcessorOutput> out;
    out.push_back(
        {QString(),
         outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                      columnsOf({"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "mag_x", "mag_y", "mag_z"},
                                {"m/s^2", "m/s^2", "m/s^2", "rad/s", "rad/s", "rad/s", "uT", "uT", "uT"}),
                      std::move(imu), attrs)});
    out.push_back({QStringLiteral("gnss"),
                   outputStream(QStringLiteral("gnss"), QStringLiteral("ENU"),
                                columnsOf({"x", "y", "z", "vx", "vy", "vz"}, {"m", "m", "m", "m/s", "m/s", "m/s"}),
                                std::move(gnss), attrs)});
    out.push_back(
        {QStringLiteral("truth"),
         outputStream(QStringLiteral("trajectory"), QStringLiteral("ENU"),
                      columnsOf({"x", "y", "z", "vx", "vy", "vz", "qw", "qx", "qy", "qz", "speed", "distance"},
                                {"m", "m", "m", "m/s", "m/s", "m/s", "1", "1", "1", "1", "m/s", "m"}),
                      std::move(truth), attrs)});
    c.report(1.0);
    return out;
}

}  // namespace athlos::inertial
