#include "plugins/inertial/ImuGnssSimulator.h"

#include <cmath>
#include <limits>
#include <random>

namespace athlos::inertial {

namespace {

// One phase of the scripted motion: run towards a target speed with a limited acceleration while
// turning at a given rate.
struct Phase {
    double duration;  // s
    double speed;     // m/s target
    double turnRate;  // rad/s
    bool sprint;      // a 10 m sprint from standstill starts here (for the per-zone tables)
};

std::vector<Phase> script(std::mt19937_64& rng, double duration, double rest) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Phase> phases{{rest, 0.0, 0.0, false}};
    double t = rest;
    while (t < duration) {
        // sprint from standstill, decelerate, turn while jogging, short stop
        const double vmax = 7.0 + 2.0 * u(rng);
        const double turn = (u(rng) < 0.5 ? -1.0 : 1.0) * (1.0 + 1.5 * u(rng));
        const std::vector<Phase> block{{3.5 + u(rng), vmax, 0.0, true},
                                       {1.5, 1.5, 0.0, false},
                                       {2.0 + u(rng), 2.0 + u(rng), turn, false},
                                       {3.0 + 2.0 * u(rng), 3.0 + 2.0 * u(rng), 0.2 * turn, false},
                                       {2.0 + u(rng), 0.0, 0.0, false}};
        for (const Phase& p : block) phases.push_back(p);
        for (const Phase& p : block) t += p.duration;
    }
    return phases;
}

Quat bodyOrientation(double yaw, double pitch, double roll) {
    return math::headingRotation(yaw) * Quat(Eigen::AngleAxisd(pitch, Vec3::UnitY())) *
           Quat(Eigen::AngleAxisd(roll, Vec3::UnitX()));
}

}  // namespace

SimulatedData simulateImuGnss(const SimulatorParams& p) {
    std::mt19937_64 rng(p.seed);
    std::normal_distribution<double> n01(0.0, 1.0);
    std::uniform_real_distribution<double> u11(-1.0, 1.0);
    const auto phases = script(rng, p.duration, p.initialRest);

    // Fine integration grid (sub-steps per IMU sample) for the translational motion.
    const double dt = 1.0 / p.imuRate;
    constexpr int sub = 10;
    const double h = dt / sub;
    const auto n = static_cast<std::size_t>(std::floor(p.duration * p.imuRate)) + 1;

    SimulatedData d;
    d.imuT.resize(n);
    d.position.resize(n);
    d.velocity.resize(n);
    d.orientation.resize(n);
    d.distance.resize(n);
    d.sprint.assign(n, -1);
    d.sprintDistance.assign(n, std::numeric_limits<double>::quiet_NaN());
    std::vector<Vec3> accE(n);

    double speed = 0.0, heading = 0.3, turnRate = 0.0, dist = 0.0, stepPhase = 0.0, lean = 0.0;
    Vec3 pos = Vec3::Zero();
    std::size_t phase = 0;
    double phaseStart = 0.0;
    int sprintIndex = -1;
    double sprintStart = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k) * dt;
        while (phase + 1 < phases.size() && t >= phaseStart + phases[phase].duration) {
            phaseStart += phases[phase].duration;
            ++phase;
            if (phases[phase].sprint) {
                ++sprintIndex;
                sprintStart = dist;
            }
        }
        const Phase& ph = phases[phase];
        double accel = 0.0;
        // Sprint: v̇ = a_max (1 − v/v_max) (exponential speed model); otherwise a bounded approach.
        for (int s = 0; s < sub; ++s) {
            if (ph.speed > speed)
                accel = ph.sprint ? 7.0 * (1.0 - speed / ph.speed) : std::min(3.0, (ph.speed - speed) / 0.5);
            else
                accel = std::max(-5.0, (ph.speed - speed) / 0.4);
            turnRate += (ph.turnRate - turnRate) * (h / 0.3);
            const Vec3 dir(std::cos(heading), std::sin(heading), 0.0);
            pos += speed * dir * h;
            dist += speed * h;
            speed = std::max(0.0, speed + accel * h);
            heading += turnRate * h * std::min(1.0, speed / 1.0);
        }
        const double yawRate = turnRate * std::min(1.0, speed / 1.0);
        const Vec3 dir(std::cos(heading), std::sin(heading), 0.0), lat(-std::sin(heading), std::cos(heading), 0.0);
        // Running bounce: vertical oscillation at step frequency, amplitude growing with speed.
        const double stepFreq = 2.0 + 0.15 * speed;
        stepPhase += 2.0 * std::numbers::pi * stepFreq * dt;
        const double amp = 0.004 * speed;
        const double w = 2.0 * std::numbers::pi * stepFreq;
        d.imuT[k] = t;
        if (p.translation) {
            d.position[k] = pos + Vec3(0.0, 0.0, amp * std::sin(stepPhase));
            d.velocity[k] = speed * dir + Vec3(0.0, 0.0, amp * w * std::cos(stepPhase));
            accE[k] = accel * dir + speed * yawRate * lat - Vec3(0.0, 0.0, amp * w * w * std::sin(stepPhase));
        } else {
            d.position[k] = d.velocity[k] = accE[k] = Vec3::Zero();
        }
        d.distance[k] = dist;
        if (sprintIndex >= 0 && ph.sprint && dist - sprintStart < 10.0) {
            d.sprint[k] = sprintIndex;
            d.sprintDistance[k] = dist - sprintStart;
        }
        // Trunk: leans into the acceleration (smoothly: a body does not tilt in one sample) and the
        // turn, sways with the steps.
        lean += (accel - lean) * std::min(1.0, dt / 0.2);
        const double pitch =
            0.05 + 0.5 * std::atan(lean / p.gravity) + 0.03 * std::sin(stepPhase) * std::min(1.0, speed);
        const double roll =
            -0.5 * std::atan(speed * yawRate / p.gravity) + 0.03 * std::cos(0.5 * stepPhase) * std::min(1.0, speed);
        d.orientation[k] = bodyOrientation(heading + p.mountYaw, pitch, roll);
    }

    // IMU errors.
    Vec3 gyrScale, accScale;
    for (int i = 0; i < 3; ++i) {
        d.gyrBias[i] = p.gyrBias * u11(rng);
        d.accBias[i] = p.accBias * u11(rng);
        gyrScale[i] = 1.0 + p.gyrScale * u11(rng);
        accScale[i] = 1.0 + p.accScale * u11(rng);
    }
    d.acc.resize(n);
    d.gyr.resize(n);
    d.mag.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Quat& q = d.orientation[k];
        // Sample k is the constant body rate over [t_k−1, t_k]: a filter that integrates sample k and
        // then reports reproduces q_k exactly from error-free data.
        const Vec3 omega =
            k > 0 ? Vec3(math::rotationVectorFromQuat(d.orientation[k - 1].conjugate() * q) / dt) : Vec3::Zero();
        const Vec3 f = q.conjugate() * (accE[k] + Vec3(0.0, 0.0, p.gravity));
        Vec3 g, a, m;
        for (int i = 0; i < 3; ++i) {
            g[i] = std::clamp(gyrScale[i] * omega[i] + d.gyrBias[i] + p.gyrNoise * n01(rng), -p.gyrRange, p.gyrRange);
            a[i] = std::clamp(accScale[i] * f[i] + d.accBias[i] + p.accNoise * n01(rng), -p.accRange, p.accRange);
        }
        m = q.conjugate() * p.magField;
        for (int i = 0; i < 3; ++i) m[i] += p.magNoise * n01(rng);
        d.gyr[k] = g;
        d.acc[k] = a;
        d.mag[k] = m;
    }

    // GNSS at its own rate: white + first-order Gauss–Markov error.
    const double gdt = 1.0 / p.gnssRate;
    const double phi = std::exp(-gdt / p.gnssCorrelationTime);
    Vec3 corr(p.gnssCorrelatedSigma * n01(rng), p.gnssCorrelatedSigma * n01(rng), p.gnssCorrelatedSigma * n01(rng));
    const double hs = p.gnssHorizontalSigma / std::numbers::sqrt2;
    const auto step = static_cast<std::size_t>(std::llround(p.imuRate / p.gnssRate));
    for (std::size_t k = 0; k < n; k += step) {
        for (int i = 0; i < 3; ++i)
            corr[i] = phi * corr[i] + std::sqrt(1.0 - phi * phi) * p.gnssCorrelatedSigma * n01(rng);
        const Vec3 white(hs * n01(rng), hs * n01(rng), p.gnssVerticalSigma * n01(rng));
        d.gnssT.push_back(d.imuT[k]);
        d.gnssPosition.push_back(d.position[k] + corr + white);
        d.gnssVelocity.push_back(d.velocity[k] + p.gnssVelocitySigma * Vec3(n01(rng), n01(rng), n01(rng)));
    }
    return d;
}

}  // namespace athlos::inertial
