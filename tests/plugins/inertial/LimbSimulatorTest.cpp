// Limb simulator: its IMUs are consistent with its truth (strapdown of the gyroscope reproduces the
// orientation, the accelerometer reads gravity at rest, the thigh and shank see the same knee-centre
// acceleration, spec §10), and its reference angles are the angles of its segment chain.
#include "core/math/Angles.h"
#include "plugins/inertial/LimbSimulator.h"

#include <gtest/gtest.h>

#include <numbers>

using namespace athlos;
using namespace athlos::inertial;
using math::Quat;
using math::Vec3;

namespace {

using math::kDeg;

LimbSimulatorParams ideal() {
    LimbSimulatorParams p;
    p.gyrBias = p.gyrNoise = p.accBias = p.accNoise = 0.0;
    p.walkDuration = 8.0;
    p.squats = 1;
    return p;
}

}  // namespace

TEST(LimbSimulator, GyroscopeIntegratesToTheOrientation) {
    const LimbSimulation sim = simulateLimb(ideal());
    const double dt = sim.t[1] - sim.t[0];
    for (const SimulatedSegment& seg : sim.segments) {
        Quat q = seg.sensor.front();
        double worst = 0.0;
        for (std::size_t k = 1; k < sim.t.size(); ++k) {
            q = math::integrateBodyRate(q, seg.gyr[k], dt);
            worst = std::max(worst, q.angularDistance(seg.sensor[k]));
        }
        EXPECT_LT(worst, 1e-8) << "rad after " << sim.t.back() << " s";
        // The motion is not trivial: the segments turn by tens of degrees.
        EXPECT_GT(seg.sensor.front().angularDistance(seg.sensor[sim.t.size() / 2]), 20 * kDeg);
    }
}

TEST(LimbSimulator, AccelerometerReadsGravityAtRest) {
    const LimbSimulatorParams p = ideal();
    const LimbSimulation sim = simulateLimb(p);
    int counted = 0;
    for (std::size_t k = 0; k < sim.t.size(); ++k) {
        if (sim.t[k] > p.standDuration - 0.5) break;
        for (const SimulatedSegment& seg : sim.segments) {
            EXPECT_LT((seg.sensor[k] * seg.acc[k] - Vec3(0, 0, p.gravity)).norm(), 1e-6);
            EXPECT_LT(seg.gyr[k].norm(), 1e-9);
        }
        ++counted;
    }
    EXPECT_GT(counted, 100);
    // In motion the accelerometer is not just gravity (the walk and squats accelerate the sensors).
    double deviation = 0.0;
    for (std::size_t k = 0; k < sim.t.size(); ++k)
        deviation = std::max(deviation, std::abs(sim[LimbSegment::Shank].acc[k].norm() - p.gravity));
    EXPECT_GT(deviation, 1.0);
}

// Two segments joined at a joint centre see the same joint acceleration (spec §3/§10):
// R (f + ω̇ × r + ω × (ω × r)) is the same for the sensors on either side.
TEST(LimbSimulator, VirtualJointAccelerationsCoincide) {
    LimbSimulatorParams p = ideal();
    p.rate = 1000.0;  // ω̇ from differences of the gyroscope: fine sampling keeps that error small
    const LimbSimulation sim = simulateLimb(p);
    const double dt = 1.0 / p.rate;
    const auto jointAcc = [&](const SimulatedSegment& seg, const Vec3& r, std::size_t k) {
        // Gyro sample k is the mean rate over [t_k − dt, t_k]; the rate at t_k and its derivative
        // come from the neighbouring samples.
        const Vec3 w = 0.5 * (seg.gyr[k] + seg.gyr[k + 1]);
        const Vec3 dw = (seg.gyr[k + 1] - seg.gyr[k]) / dt;
        return Vec3(seg.sensor[k] * (seg.acc[k] + dw.cross(r) + w.cross(w.cross(r))));
    };
    double sumSq = 0.0, signal = 0.0, wrongSq = 0.0;
    long long n = 0;
    for (std::size_t k = 1; k + 1 < sim.t.size(); k += 7) {
        const Vec3 thigh = jointAcc(sim[LimbSegment::Thigh], sim[LimbSegment::Thigh].toKnee, k);
        const Vec3 shank = jointAcc(sim[LimbSegment::Shank], sim[LimbSegment::Shank].toKnee, k);
        const Vec3 pelvis = jointAcc(sim[LimbSegment::Pelvis], sim[LimbSegment::Pelvis].toHip, k);
        const Vec3 thighHip = jointAcc(sim[LimbSegment::Thigh], sim[LimbSegment::Thigh].toHip, k);
        sumSq += (thigh - shank).squaredNorm() + (pelvis - thighHip).squaredNorm();
        // Without the lever arm the sensors disagree: the check has teeth.
        wrongSq += (Vec3(sim[LimbSegment::Thigh].sensor[k] * sim[LimbSegment::Thigh].acc[k]) -
                    Vec3(sim[LimbSegment::Shank].sensor[k] * sim[LimbSegment::Shank].acc[k]))
                       .squaredNorm();
        signal += (thigh - Vec3(0, 0, p.gravity)).squaredNorm();
        ++n;
    }
    const double rms = std::sqrt(sumSq / (2.0 * n)), wrong = std::sqrt(wrongSq / n);
    EXPECT_LT(rms, 0.01) << "m/s²";
    EXPECT_GT(wrong, 0.5) << "m/s²";
    EXPECT_GT(std::sqrt(signal / n), 0.3) << "m/s² of joint-centre acceleration";
}

TEST(LimbSimulator, ReferenceAnglesAreTheSegmentChain) {
    for (Side side : {Side::Right, Side::Left}) {
        LimbSimulatorParams p = ideal();
        p.side = side;
        const LimbSimulation sim = simulateLimb(p);
        JointAngles::Params kp;
        kp.joint = Joint::Knee;
        kp.side = side;
        JointAngles::Params hp = kp;
        hp.joint = Joint::Hip;
        const JointAngles knee(kp), hip(hp);
        double maxKnee = 0, maxAbd = 0, maxRot = 0, worst = 0;
        for (std::size_t k = 0; k < sim.t.size(); ++k) {
            const auto a = knee.update(sim[LimbSegment::Thigh].segment[k], sim[LimbSegment::Shank].segment[k]).angles;
            const auto h = hip.update(sim[LimbSegment::Pelvis].segment[k], sim[LimbSegment::Thigh].segment[k]).angles;
            worst = std::max({worst, (a.vector() - sim.knee[k].vector()).cwiseAbs().maxCoeff(),
                              (h.vector() - sim.hip[k].vector()).cwiseAbs().maxCoeff()});
            // The same segments through the sensors and their mounts give the same angles.
            JointAngles::Params mp = kp;
            mp.proximalMount = sim[LimbSegment::Thigh].mount;
            mp.distalMount = sim[LimbSegment::Shank].mount;
            const auto m =
                JointAngles(mp).update(sim[LimbSegment::Thigh].sensor[k], sim[LimbSegment::Shank].sensor[k]).angles;
            worst = std::max(worst, (m.vector() - sim.knee[k].vector()).cwiseAbs().maxCoeff());
            maxKnee = std::max(maxKnee, sim.knee[k].flexion);
            maxAbd = std::max(maxAbd, std::abs(sim.knee[k].abduction));
            maxRot = std::max(maxRot, std::abs(sim.knee[k].rotation));
        }
        EXPECT_LT(worst, 1e-9);
        EXPECT_NEAR(maxKnee, 90 * kDeg, 1 * kDeg);  // squat depth
        EXPECT_GT(maxAbd, 1.5 * kDeg);              // 3 DOF: small ab/adduction and rotation
        EXPECT_GT(maxRot, 4 * kDeg);
        // The mounts are far from the segment axes (a missing calibration must show).
        for (const SimulatedSegment& seg : sim.segments)
            EXPECT_GT(seg.mount.angularDistance(Quat::Identity()), 60 * kDeg);
    }
}

TEST(LimbSimulator, NoiseAndBiasFollowTheParameters) {
    LimbSimulatorParams p;
    p.walkDuration = 4.0;
    p.squats = 0;
    const LimbSimulation noisy = simulateLimb(p), again = simulateLimb(p);
    const LimbSimulation clean = simulateLimb(ideal());
    // Same seed, same data; the first rest phase shows bias + noise around the ideal values.
    EXPECT_EQ(noisy[LimbSegment::Thigh].gyr[10], again[LimbSegment::Thigh].gyr[10]);
    Vec3 mean = Vec3::Zero();
    const int n = 250;
    for (int k = 0; k < n; ++k) mean += noisy[LimbSegment::Thigh].gyr[k] - clean[LimbSegment::Thigh].gyr[k];
    mean /= n;
    EXPECT_LT((mean - noisy[LimbSegment::Thigh].gyrBias).norm(), 4 * p.gyrNoise / std::sqrt(double(n)));
    EXPECT_LE(noisy[LimbSegment::Thigh].gyrBias.cwiseAbs().maxCoeff(), p.gyrBias);
    EXPECT_GT(noisy[LimbSegment::Thigh].gyrBias.norm(), 0.0);
}
