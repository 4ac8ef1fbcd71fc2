#include "plugins/activity/EventSimulator.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace athlos::activity {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kG = 9.81;

struct VolleyballAction {
    const char* name;
    double swingDuration;  // s
    double swing;          // m/s², peak of the swing burst
    double hit;            // m/s², peak of the contact ring-down
    double armPitch;       // rad, forearm elevation at contact (+ up, − down)
    double hitElevation;   // rad, hit direction above the horizontal (world)
    double jump;           // m/s², take-off push 0.5 s before contact (0: none)
};

// The nine actions (seed 000 §5.2), parameters chosen so that their swings and contacts differ the
// way the thesis describes (spikes and jump serves strongest, sets soft, block without a swing).
constexpr VolleyballAction kActions[] = {
    {"underhand_serve", 0.50, 14.0, 70.0, -1.1, 0.9, 0.0},
    {"overhead_serve", 0.45, 22.0, 75.0, 1.2, 0.2, 0.0},
    {"jump_serve", 0.40, 34.0, 85.0, 1.3, -0.2, 14.0},
    {"underarm_set", 0.30, 8.0, 65.0, -0.3, 1.2, 0.0},
    {"overhead_set", 0.30, 9.0, 65.0, 1.4, 1.4, 0.0},
    {"shot_attack", 0.35, 18.0, 70.0, 1.3, 0.3, 12.0},
    {"spike", 0.35, 40.0, 95.0, 1.3, -0.5, 16.0},
    {"block", 0.15, 6.0, 70.0, 1.5, -1.2, 12.0},
    {"dig", 0.25, 10.0, 65.0, -0.6, 1.0, 0.0},
};

double halfSine(double t, double start, double duration) {
    if (t < start || t > start + duration) return 0.0;
    return std::sin(kPi * (t - start) / duration);
}

double ringDown(double t, double t0, double tau, double frequency) {
    if (t < t0) return 0.0;
    return std::exp(-(t - t0) / tau) * std::cos(2.0 * kPi * frequency * (t - t0));
}

Eigen::Vector3d direction(double heading, double elevation) {
    return {std::cos(elevation) * std::cos(heading), std::cos(elevation) * std::sin(heading), std::sin(elevation)};
}
}  // namespace

QStringList EventSimulator::volleyballActions() {
    QStringList out;
    for (const auto& a : kActions) out << QString::fromLatin1(a.name);
    return out;
}

SimulatedEvents EventSimulator::volleyball(unsigned player, int actions, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::mt19937 prng(player * 2654435761u + 17u);
    std::uniform_real_distribution<double> pu(0.0, 1.0);
    const double strength = 0.8 + 0.4 * pu(prng);
    const double tempo = 0.9 + 0.2 * pu(prng);
    const double mountRoll = (pu(prng) - 0.5) * 0.8;
    const double rate = 38.5 + pu(prng);  // the BMA280's ~39 Hz
    const Eigen::Matrix3d mount = Eigen::AngleAxisd(mountRoll, Eigen::Vector3d::UnitX()).toRotationMatrix();

    // Plan: actions 5–12 s apart, Null motions in between.
    struct Planned {
        double t;
        int action;  // -1 arm swing, -2 clap, -3 landing (Null)
        double heading, scale;
        double elevation = 0.0, posture = 0.0, timing = 1.0;  // this execution's deviations (rad, rad, ×)
    };
    // How this player executes each action: offsets of the hit direction and arm posture.
    std::vector<double> styleElevation(9), stylePosture(9);
    for (int i = 0; i < 9; ++i) {
        styleElevation[std::size_t(i)] = (pu(prng) - 0.5) * 0.6;
        stylePosture[std::size_t(i)] = (pu(prng) - 0.5) * 0.6;
    }
    std::vector<Planned> plan;
    double t = 3.0;
    for (int k = 0; k < actions; ++k) {
        const int nulls = int(u(rng) * 3.0);
        for (int j = 0; j < nulls; ++j) {
            plan.push_back({t + 1.0 + 1.5 * j + u(rng), -1 - int(u(rng) * 3.0), 2 * kPi * u(rng), 0.6 + 0.8 * u(rng)});
        }
        t += 1.5 * nulls + 2.5 + 3.0 * u(rng);
        const int action = int(u(rng) * 9.0) % 9;
        plan.push_back({t, action, 2 * kPi * u(rng), strength * (0.85 + 0.3 * u(rng)),
                        styleElevation[std::size_t(action)] + 0.5 * (u(rng) - 0.5),
                        stylePosture[std::size_t(action)] + 0.5 * (u(rng) - 0.5), tempo * (0.8 + 0.4 * u(rng))});
        t += 2.5 + 2.0 * u(rng);
    }
    const double end = t + 3.0;
    SimulatedEvents out;
    out.imu.columns = 3;
    const double dt = 1.0 / rate;
    double walkPhase = 0.0, pitchWander = 0.0;
    for (double now = 0.0; now < end; now += dt) {
        Eigen::Vector3d a(0.0, 0.0, 0.0);
        double pitch = -1.2 + pitchWander;  // arm hanging
        double heading = 0.0;
        // Walking between rallies: a bounce at the step frequency.
        walkPhase += 2.0 * kPi * 1.8 * dt;
        a.z() += 1.2 * std::sin(walkPhase);
        pitchWander = 0.995 * pitchWander + 0.01 * gauss(rng);
        for (const Planned& p : plan) {
            if (now < p.t - 1.5 || now > p.t + 0.8) continue;
            if (p.action >= 0) {
                const VolleyballAction& va = kActions[p.action];
                const double swingStart = p.t - va.swingDuration * p.timing;
                // The arm rises to its contact posture during the second before the contact.
                const double w =
                    std::clamp((now - (p.t - 1.0)) / 0.6, 0.0, 1.0) * std::clamp((p.t + 0.6 - now) / 0.3, 0.0, 1.0);
                pitch = (1.0 - w) * pitch + w * (va.armPitch + p.posture);
                heading = p.heading;
                const Eigen::Vector3d hitDir = direction(p.heading, va.hitElevation + p.elevation);
                a += p.scale * va.swing * halfSine(now, swingStart, va.swingDuration * p.timing) * hitDir;
                a -= p.scale * va.hit * ringDown(now, p.t, 0.05, 12.0) * hitDir;
                if (va.jump > 0) a.z() += va.jump * halfSine(now, p.t - 0.75, 0.3);
            } else if (p.action == -1) {  // an arm swing without a hit
                a += p.scale * 12.0 * halfSine(now, p.t, 0.7) * direction(p.heading, 0.4);
            } else if (p.action == -2) {  // a clap
                a += p.scale * 30.0 * ringDown(now, p.t, 0.03, 12.0) * direction(p.heading, 0.0);
            } else {  // landing from a jump
                a.z() += p.scale * 22.0 * ringDown(now, p.t, 0.05, 8.0);
            }
        }
        const Eigen::Matrix3d r = Eigen::AngleAxisd(heading, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                                  Eigen::AngleAxisd(-pitch, Eigen::Vector3d::UnitY()).toRotationMatrix() * mount;
        Eigen::Vector3d acc = r.transpose() * (a + Eigen::Vector3d(0.0, 0.0, kG));
        out.imu.t.push_back(now);
        for (int i = 0; i < 3; ++i)
            out.imu.values.push_back(std::clamp(acc[i] + 0.3 * gauss(rng), -16.0 * kG, 16.0 * kG));  // ±16 g
    }
    for (const Planned& p : plan) {
        if (p.action < 0) continue;
        Annotation an;
        an.label = QString::fromLatin1(kActions[p.action].name);
        an.tStart = p.t - 0.5;
        an.tEnd = p.t + 0.5;
        an.source = QStringLiteral("import");
        out.annotations.push_back(an);
        out.times.push_back(p.t);
    }
    return out;
}

QStringList EventSimulator::rugbyColumns() {
    return {QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z"),
            QStringLiteral("gyr_x"), QStringLiteral("gyr_y"), QStringLiteral("gyr_z")};
}

SimulatedEvents EventSimulator::rugby(unsigned player, int tackles, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> gauss(0.0, 1.0);
    std::mt19937 prng(player * 40503u + 5u);
    std::uniform_real_distribution<double> pu(0.0, 1.0);
    const double cadence = 2.6 + 0.6 * pu(prng);
    const double stepImpact = 5.0 + 5.0 * pu(prng);
    const double mountPitch = (pu(prng) - 0.5) * 0.3;
    struct Planned {
        double t;
        bool tackle;
        double size, duration, fall;
    };
    std::vector<Planned> plan;
    double t = 5.0;
    for (int k = 0; k < tackles; ++k) {
        // Contacts and sprints that are not tackles come between them.
        const int others = int(u(rng) * 3.0);
        for (int j = 0; j < others; ++j) {
            plan.push_back({t + 3.0 + 4.0 * j + u(rng), false, 5.0 + 4.0 * u(rng), 0.3 + 0.4 * u(rng), 0.0});
        }
        t += 4.0 * others + 6.0 + 6.0 * u(rng);
        plan.push_back({t, true, 15.0 + 15.0 * u(rng), 0.4 + 0.4 * u(rng), 0.9 + 0.5 * u(rng)});
        t += 6.0 + 4.0 * u(rng);
    }
    const double end = t + 5.0;
    const double rate = 200.0, dt = 1.0 / rate;
    SimulatedEvents out;
    out.imu.columns = 6;
    double stepPhase = 0.0, surge = 0.0, pitchPrev = 0.2;
    for (double now = 0.0; now < end; now += dt) {
        stepPhase += 2.0 * kPi * cadence * dt;
        // Running: vertical step impacts; slow surges (sprints and decelerations) of a few m/s².
        surge = 0.999 * surge + 0.08 * gauss(rng);
        Eigen::Vector3d a(std::clamp(surge, -6.0, 6.0), 0.0, 0.0);
        a.z() += stepImpact * std::pow(std::max(0.0, std::sin(stepPhase)), 6) - stepImpact * 0.3125;
        double pitch = 0.2;  // forward lean while running
        for (const Planned& p : plan) {
            if (now < p.t - 1.0 || now > p.t + 4.0) continue;
            a.x() -= p.size * halfSine(now, p.t - 0.5 * p.duration, p.duration);
            if (p.tackle) {
                // To the ground and up again: pitch towards horizontal, a landing impact.
                const double down =
                    std::clamp((now - p.t) / 0.6, 0.0, 1.0) * std::clamp((p.t + 3.0 - now) / 1.0, 0.0, 1.0);
                pitch += down * p.fall;
                a.z() += 12.0 * ringDown(now, p.t + 0.7, 0.08, 5.0);
            }
        }
        const double pitchRate = (pitch - pitchPrev) / dt;
        pitchPrev = pitch;
        const Eigen::Matrix3d r = Eigen::AngleAxisd(pitch + mountPitch, Eigen::Vector3d::UnitY()).toRotationMatrix();
        const Eigen::Vector3d acc = r.transpose() * (a + Eigen::Vector3d(0.0, 0.0, kG));
        out.imu.t.push_back(now);
        for (int i = 0; i < 3; ++i) out.imu.values.push_back(acc[i] + 0.2 * gauss(rng));
        out.imu.values.push_back(0.05 * gauss(rng));
        out.imu.values.push_back(pitchRate + 0.05 * gauss(rng));
        out.imu.values.push_back(0.3 * std::sin(stepPhase * 0.5) + 0.05 * gauss(rng));
    }
    for (const Planned& p : plan) {
        if (!p.tackle) continue;
        Annotation an;
        an.label = QStringLiteral("tackle");
        an.tStart = p.t - 1.0;
        an.tEnd = p.t + 1.0;
        an.source = QStringLiteral("import");
        out.annotations.push_back(an);
        out.times.push_back(p.t);
    }
    return out;
}

}  // namespace athlos::activity
