#include "plugins/activity/ActivitySimulator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::activity {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;

// The movement of one activity (before the person's scaling).
struct Pattern {
    double pitch;      // θ0, rad (forearm below horizontal is negative)
    double swing;      // A, rad
    double stride;     // f, Hz (the step frequency is 2f)
    double bounce;     // vertical acceleration amplitude at 2f, m/s²
    double harmonic;   // relative amplitude of the 4f harmonic (sharper impacts)
    double impact;     // height of heel-strike impulses, m/s²
    double jitter;     // low-frequency wander of the pitch, rad
    double vibration;  // broadband vibration, m/s²
    double roll;       // forearm roll, rad
};

Pattern patternOf(const QString& activity) {
    if (activity == QLatin1String("walking")) return {-1.35, 0.30, 0.92, 1.6, 0.25, 2.0, 0.05, 0.05, 0.0};
    if (activity == QLatin1String("running")) return {-0.45, 0.55, 1.40, 7.0, 0.35, 8.0, 0.05, 0.10, 0.3};
    if (activity == QLatin1String("sitting")) return {-0.10, 0.00, 0.00, 0.0, 0.00, 0.0, 0.15, 0.02, 0.8};
    if (activity == QLatin1String("standing")) return {-1.45, 0.00, 0.00, 0.0, 0.00, 0.0, 0.08, 0.02, 0.1};
    if (activity == QLatin1String("stairs_up")) return {-1.20, 0.18, 0.78, 2.2, 0.60, 1.2, 0.08, 0.05, 0.0};
    if (activity == QLatin1String("stairs_down")) return {-1.25, 0.16, 0.95, 2.6, 0.20, 5.0, 0.08, 0.05, 0.0};
    return {-0.55, 0.03, 1.20, 0.3, 0.10, 0.0, 0.03, 0.60, 1.4};  // cycling: hands on the bars, road vibration
}
}  // namespace

SimulatedPerson SimulatedPerson::random(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    SimulatedPerson p;
    p.amplitude = 0.75 + 0.5 * u(rng);
    p.cadence = 0.85 + 0.3 * u(rng);
    p.mountRoll = (u(rng) - 0.5) * 2.0 * 0.6;  // ±35°
    p.mountTilt = (u(rng) - 0.5) * 2.0 * 0.2;  // ±11°
    p.accNoise = 0.05 + 0.2 * u(rng);
    p.gyrNoise = 0.01 + 0.04 * u(rng);
    p.rate = u(rng) < 0.5 ? 50.0 : 52.0;
    return p;
}

QStringList ActivitySimulator::activities() {
    return {QStringLiteral("walking"),  QStringLiteral("running"),   QStringLiteral("sitting"),
            QStringLiteral("standing"), QStringLiteral("stairs_up"), QStringLiteral("stairs_down"),
            QStringLiteral("cycling")};
}

QStringList ActivitySimulator::columnNames() {
    return {QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z"),
            QStringLiteral("gyr_x"), QStringLiteral("gyr_y"), QStringLiteral("gyr_z"),
            QStringLiteral("mag_x"), QStringLiteral("mag_y"), QStringLiteral("mag_z")};
}

QStringList ActivitySimulator::columnUnits() {
    return {QStringLiteral("m/s^2"), QStringLiteral("m/s^2"), QStringLiteral("m/s^2"),
            QStringLiteral("rad/s"), QStringLiteral("rad/s"), QStringLiteral("rad/s"),
            QStringLiteral("T"),     QStringLiteral("T"),     QStringLiteral("T")};
}

SimulatedRecording ActivitySimulator::simulate(const SimulatedPerson& person, int segments, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    QStringList order = activities();
    std::vector<QString> plan;
    while (int(plan.size()) < segments) {
        std::shuffle(order.begin(), order.end(), rng);
        for (const QString& a : order)
            if (int(plan.size()) < segments) plan.push_back(a);
    }
    const Eigen::Matrix3d mount = (Eigen::AngleAxisd(person.mountRoll, Eigen::Vector3d::UnitX()) *
                                   Eigen::AngleAxisd(person.mountTilt, Eigen::Vector3d::UnitY()))
                                      .toRotationMatrix();
    const Eigen::Vector3d earthField(20e-6, 0.0, -40e-6);
    const double dt = 1.0 / person.rate;
    SimulatedRecording out;
    out.imu.columns = 9;
    double t = 0.0;
    for (const QString& activity : plan) {
        Pattern p = patternOf(activity);
        // Each bout varies a little around the person's own style.
        const double f = p.stride * person.cadence * (0.95 + 0.1 * u(rng));
        const double swing = p.swing * person.amplitude * (0.9 + 0.2 * u(rng));
        const double bounce = p.bounce * person.amplitude * (0.85 + 0.3 * u(rng));
        const double impact = p.impact * person.amplitude * (0.8 + 0.4 * u(rng));
        const double pitch0 = p.pitch + 0.15 * (u(rng) - 0.5);
        const double heading = 2.0 * kPi * u(rng);
        const double phase = 2.0 * kPi * u(rng);
        const double duration = 20.0 + 40.0 * u(rng);
        const Eigen::Matrix3d yaw = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).toRotationMatrix();
        const Eigen::Matrix3d roll = Eigen::AngleAxisd(p.roll, Eigen::Vector3d::UnitX()).toRotationMatrix();
        double wander = 0.0, wanderRate = 0.0;  // low-frequency pitch wander (2nd-order random walk)
        const long long n = (long long)(duration / dt);
        for (long long k = 0; k < n; ++k, t += dt) {
            const double w = 2.0 * kPi * f;
            const double s = w * (t - 0) + phase;
            wanderRate = 0.995 * wanderRate + p.jitter * 0.05 * gauss(rng);
            wander = 0.99 * wander + wanderRate * dt;
            const double theta = pitch0 + swing * std::sin(s) + wander;
            const double thetaDot = swing * w * std::cos(s) + wanderRate;
            const double thetaDdot = -swing * w * w * std::sin(s);
            // Vertical wrist acceleration: bounce at the step frequency, a harmonic and heel-strike impulses.
            const double stepPhase = std::fmod(2.0 * s, 2.0 * kPi);
            double up = bounce * std::sin(2.0 * s) + p.harmonic * bounce * std::sin(4.0 * s + 0.7);
            if (impact > 0) up += impact * std::exp(-std::pow((stepPhase - 0.6) / 0.25, 2));
            const double forward = 0.35 * thetaDdot * std::cos(theta);
            Eigen::Vector3d accWorld(forward, 0.0, up + kG);
            for (int i = 0; i < 3; ++i) accWorld[i] += p.vibration * gauss(rng);
            const Eigen::Matrix3d posture = Eigen::AngleAxisd(-theta, Eigen::Vector3d::UnitY()).toRotationMatrix();
            const Eigen::Matrix3d r = yaw * posture * roll * mount;  // world ← sensor
            const Eigen::Vector3d omegaWorld = yaw * Eigen::Vector3d(0.0, -thetaDot, 0.0);
            const Eigen::Vector3d acc = r.transpose() * accWorld;
            const Eigen::Vector3d gyr = r.transpose() * omegaWorld;
            const Eigen::Vector3d mag = r.transpose() * earthField;
            out.imu.t.push_back(t);
            for (int i = 0; i < 3; ++i) out.imu.values.push_back(acc[i] + person.accNoise * gauss(rng));
            for (int i = 0; i < 3; ++i) out.imu.values.push_back(gyr[i] + person.gyrNoise * gauss(rng));
            for (int i = 0; i < 3; ++i) out.imu.values.push_back(mag[i] + 0.3e-6 * gauss(rng));
            out.labels << activity;
        }
    }
    return out;
}

}  // namespace athlos::activity
