// Body simulator: its ideal IMUs are consistent with its truth (strapdown reproduces the sensor
// orientation, two sensors linked by a joint see the same joint-centre acceleration through their
// sensor-to-joint vectors, spec §10), its reference angles are those of its segment chain, its joint
// centres are where the chain puts them, and the skiing run has the asked speed and turn spacing.
#include "core/math/Angles.h"
#include "plugins/inertial/BodySimulator.h"

#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::inertial;
using math::kDeg;
using math::Quat;
using math::Vec3;

namespace {

BodySimulatorParams ideal(BodyScenario scenario) {
    BodySimulatorParams p;
    p.scenario = scenario;
    p.gyrBias = p.gyrDrift = p.gyrNoise = p.gyrScale = p.gSensitivity = 0.0;
    p.accBias = p.accNoise = p.accScale = p.vibration = p.impactRate = 0.0;
    p.uprightDuration = 2.0;
    p.squats = 1;
    p.motionDuration = 30.0;
    return p;
}

}  // namespace

TEST(BodySimulator, GyroscopeIntegratesToTheOrientation) {
    for (BodyScenario scenario : {BodyScenario::Skiing, BodyScenario::Walking}) {
        const BodySimulation sim = simulateBody(ideal(scenario));
        const double dt = sim.t[1] - sim.t[0];
        for (const BodySensor& s : sim.sensors) {
            Quat q = s.sensor.front();
            double worst = 0.0;
            for (std::size_t k = 1; k < sim.t.size(); ++k) {
                q = math::integrateBodyRate(q, s.gyr[k], dt);
                worst = std::max(worst, q.angularDistance(s.sensor[k]));
            }
            EXPECT_LT(worst, 1e-7);
            double range = 0.0;
            for (const Quat& q : s.sensor) range = std::max(range, q.angularDistance(s.sensor.front()));
            EXPECT_GT(range, 20 * kDeg);
        }
    }
}

TEST(BodySimulator, LinkedSensorsSeeTheSameJointAcceleration) {
    // At 1 kHz, so that ω and ω̇ by finite differences of the true orientations are accurate.
    BodySimulatorParams p = ideal(BodyScenario::Skiing);
    p.rate = 1000.0;
    const BodySimulation sim = simulateBody(p);
    const double dt = sim.t[1] - sim.t[0];
    // ã = a + ω̇ × r + ω × (ω × r) in the earth frame (Fasel 2017 Eqs. 5.1–5.4) with exact ω, ω̇ from the truth.
    const auto omega = [&](const BodySensor& s, std::size_t k) -> Vec3 {
        return math::rotationVectorFromQuat(s.sensor[k - 1].conjugate() * s.sensor[k + 1]) / (2.0 * dt);
    };
    for (int j = 0; j < kBodyJoints; ++j) {
        const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
        const BodySensor& p = sim[info.proximal];
        const BodySensor& d = sim[info.distal];
        const BodyJointTruth& truth = sim.joints[j];
        double worst = 0.0, typical = 0.0;
        int count = 0;
        for (std::size_t k = 2; k + 2 < sim.t.size(); k += 37) {
            const auto virtualAcc = [&](const BodySensor& s, const Vec3& r) {
                const Vec3 w = omega(s, k), wd = (omega(s, k + 1) - omega(s, k - 1)) / (2.0 * dt);
                return Vec3(s.sensor[k] * (s.acc[k] + wd.cross(r) + w.cross(w.cross(r))));
            };
            const Vec3 ap = virtualAcc(p, truth.proximalToJoint), ad = virtualAcc(d, truth.distalToJoint);
            worst = std::max(worst, (ap - ad).norm());
            // The wrong vector (the sensor's own position) gives clearly different accelerations.
            typical += (virtualAcc(d, Vec3::Zero()) - ap).norm();
            ++count;
        }
        EXPECT_LT(worst, 0.05) << qUtf8Printable(bodyJointName(static_cast<BodyJoint>(j)));
        EXPECT_GT(typical / count, 0.05) << qUtf8Printable(bodyJointName(static_cast<BodyJoint>(j)));
    }
}

TEST(BodySimulator, JointCentresAndAnglesFollowTheChain) {
    const BodySimulation sim = simulateBody(ideal(BodyScenario::Skiing));
    for (std::size_t k = 0; k < sim.t.size(); k += 97) {
        for (int j = 0; j < kBodyJoints; ++j) {
            const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
            const BodySensor& p = sim[info.proximal];
            const BodySensor& d = sim[info.distal];
            const Quat relative = p.segment[k].conjugate() * d.segment[k];
            EXPECT_LT(relative.angularDistance(relativeFromAnatomical(sim.joints[j].angles[k], info.joint, info.side)),
                      1e-9);
            // Both sensors' positions plus their rotated sensor-to-joint vectors meet at the joint centre.
            EXPECT_LT((p.position[k] + p.sensor[k] * sim.joints[j].proximalToJoint - sim.joints[j].centre[k]).norm(),
                      1e-9);
            EXPECT_LT((d.position[k] + d.sensor[k] * sim.joints[j].distalToJoint - sim.joints[j].centre[k]).norm(),
                      1e-9);
            EXPECT_GT(sim.joints[j].distalToJoint.norm(), 0.05);
        }
    }
    // Knee flexion during the skiing run is within the ranges of Fasel 2017 Table 6.5 (about 35–75°).
    double lo = 1e9, hi = -1e9;
    for (std::size_t k = 0; k < sim.t.size(); ++k)
        if (sim.t[k] > sim.motionBegin + 8.0 && sim.t[k] < sim.motionEnd - 8.0) {
            lo = std::min(lo, sim.joints[static_cast<int>(BodyJoint::RightKnee)].angles[k].flexion);
            hi = std::max(hi, sim.joints[static_cast<int>(BodyJoint::RightKnee)].angles[k].flexion);
        }
    EXPECT_GT(lo, 30 * kDeg);
    EXPECT_LT(hi, 85 * kDeg);
    EXPECT_GT(hi - lo, 20 * kDeg);
}

TEST(BodySimulator, SkiingRunHasTheSpeedAndTurnSpacing) {
    BodySimulatorParams p = ideal(BodyScenario::Skiing);
    p.motionDuration = 40.0;
    const BodySimulation sim = simulateBody(p);
    const std::vector<Vec3>& hip = sim.joints[static_cast<int>(BodyJoint::RightHip)].centre;
    const double dt = sim.t[1] - sim.t[0];
    // Speed along the slope in the middle of the run.
    const std::size_t k = static_cast<std::size_t>((sim.motionBegin + 20.0) / dt);
    const double speed = (hip[k + 50] - hip[k - 50]).norm() / (100 * dt);
    EXPECT_NEAR(speed, p.skiSpeed, 1.5);
    // Turn switches (sign changes of the sacrum's yaw rate) are turnDistance apart along the fall line.
    const Vec3 fall(std::cos(p.initialHeading), std::sin(p.initialHeading), 0.0);
    std::vector<double> switches;
    double previous = 0.0;
    for (std::size_t i = 1; i < sim.t.size(); ++i) {
        if (sim.t[i] < sim.motionBegin + 8.0 || sim.t[i] > sim.motionEnd - 8.0) continue;
        const double yaw = math::headingAngle(sim[BodySegment::Sacrum].segment[i]) -
                           math::headingAngle(sim[BodySegment::Sacrum].segment[i - 1]);
        const double rate = math::wrapAngle(yaw);
        if (previous != 0.0 && (rate > 0) != (previous > 0)) switches.push_back(hip[i].dot(fall));
        previous = rate;
    }
    ASSERT_GE(switches.size(), 4u);
    for (std::size_t i = 1; i < switches.size(); ++i) EXPECT_NEAR(switches[i] - switches[i - 1], p.turnDistance, 3.0);
}

TEST(BodySimulator, ErrorsAreThere) {
    BodySimulatorParams p = ideal(BodyScenario::Skiing);
    const BodySimulation clean = simulateBody(p);
    p.gyrDrift = 0.15 * kDeg;
    const BodySimulation drifting = simulateBody(p);
    // The bias changes by gyrDrift once the motion is under way.
    const std::size_t k = clean.t.size() - 10;
    for (int s = 0; s < kBodySegments; ++s)
        EXPECT_NEAR((drifting.sensors[s].gyr[k] - clean.sensors[s].gyr[k]).norm(), 0.15 * kDeg, 1e-9);
}
