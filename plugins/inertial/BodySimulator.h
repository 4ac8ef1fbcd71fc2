#pragma once
// Simulated whole lower body + trunk with eight IMUs and full ground truth (issue #17 item 5, spec §10):
// the kinematic chain pelvis → hip → thigh → knee → shank → ankle → foot on both sides and pelvis →
// lumbar joint → thorax, driven by joint-angle curves for a calibration block (upright standing, then
// squats), followed by walking or an alpine skiing run (sinusoidal turns `turnDistance` apart at
// `skiSpeed` on a slope, the pelvis leaning into each turn) and a final stand.
//
// It generalises LimbSimulator (one leg, three sensors) to any number of segments hanging from the
// pelvis: a segment's orientation is its parent's times the joint's relative rotation
// (relativeFromAnatomical, so the reference angles are exact by construction), joint centres are
// chained through the segments, and each sensor sits off the joint axes with a known misaligned mount.
// The ideal IMU follows LimbSimulator's construction (gyroscope = the constant body rate between
// consecutive true orientations; accelerometer = Rᵀ(p̈ + g e_z) of the sensor position), then the
// errors of spec §1/§10 are added: constant bias, a slow bias change of magnitude `gyrDrift` (the
// residual drift an online bias estimate cannot follow, ≈ 0.15°/s on snow, thesis ch. 5), scale
// factor, g-sensitivity, white noise, 15–30 Hz vibration and short impacts while skiing.
//
// Truth per sample: segment and sensor orientations, joint angles of the seven joints and joint-centre
// positions in the earth frame (ENU) — the latter are what a centre-of-mass estimate (issue #18) needs,
// together with the sensor-to-joint vectors of every joint in both sensors' frames.
#include "core/math/Angles.h"
#include "plugins/inertial/JointAngles.h"

#include <QString>
#include <array>
#include <cstdint>
#include <random>
#include <vector>

namespace athlos::inertial {

enum class BodySegment { Sacrum = 0, Sternum, RightThigh, RightShank, RightFoot, LeftThigh, LeftShank, LeftFoot };
inline constexpr int kBodySegments = 8;
enum class BodyJoint { Lumbar = 0, RightHip, RightKnee, RightAnkle, LeftHip, LeftKnee, LeftAnkle };
inline constexpr int kBodyJoints = 7;
enum class BodyScenario { Squats, Walking, Skiing };

// "sacrum", "sternum", "right-thigh", … ; "lumbar", "right-hip", …
QString bodySegmentName(BodySegment segment);
QString bodyJointName(BodyJoint joint);
Expected<BodyScenario> parseBodyScenario(const QString& name);  // "squats", "walking", "skiing"

// The joint between two segments (proximal → distal) and its angle convention.
struct BodyJointInfo {
    BodySegment proximal, distal;
    Joint joint;
    Side side;
};
BodyJointInfo bodyJointInfo(BodyJoint joint);

struct BodySimulatorParams {
    std::uint64_t seed = 1;
    BodyScenario scenario = BodyScenario::Skiing;
    double rate = 100.0;            // Hz
    double uprightDuration = 10.0;  // s, calibration: stand still (spec §4)
    int squats = 3;                 // calibration squats
    double squatDuration = 4.0;     // s each
    // Further calibration movements of the functional protocol (spec §4), after the squats; all off
    // by default (0 repetitions) so that the default simulation stays unchanged. Each block starts
    // after `calibrationPause` s of standing still.
    int trunkRotations = 0;              // rotations about the vertical, hips fixed, starting right
    double trunkRotationDuration = 4.0;  // s each (right, back through neutral to the left, back)
    double trunkRotationAmplitude = 40.0 * math::kDeg;
    int hipAbductions = 0;              // ab/adductions per leg, straight knee (right leg first)
    double hipAbductionDuration = 3.0;  // s each
    double hipAbductionAmplitude = 25.0 * math::kDeg;
    // Arm swings ×3 (optional, spec §4; Fasel §7.2.2): the lower body and trunk stand still while the
    // arms, which this simulator does not model, swing in the sagittal plane (body::simulateWholeBody
    // moves and instruments them). The block: a pause, `armGrip` s to grip the pole, a pause, the
    // swings, a pause and `armGrip` s to let go.
    int armSwings = 0;
    double armSwingDuration = 4.0;  // s each (up to the horizontal and back)
    double armGrip = 1.0;           // s to grip (pronate) before and let go after the swings
    double calibrationPause = 2.0;  // s standing still before each further block
    double standDuration = 3.0;     // s, between calibration and motion and at the end
    double motionDuration = 120.0;  // s, walking or skiing (incl. speed ramps)
    double initialHeading = 0.4;    // rad, fall line / walking direction counter-clockwise from East
    double gaitPeriod = 1.1;        // s per stride
    double walkSpeed = 1.2;         // m/s
    double skiSpeed = 20.0;         // m/s along the slope (spec §10)
    double turnDistance = 27.0;     // m between turn switches along the fall line (spec §10)
    double turnAmplitude = 2.5;     // m, lateral amplitude of the sinusoidal path
    double slope = 26.0 * math::kDeg;
    // Errors (per axis, drawn uniformly in ±value unless said otherwise)
    double gyrBias = 0.3 * math::kDeg;              // rad/s, constant
    double gyrDrift = 0.15 * math::kDeg;            // rad/s, norm of the slow bias change (random direction)
    double gyrNoise = 0.004;                        // rad/s, σ per sample
    double gyrScale = 0.01;                         // relative
    double gSensitivity = 0.1 * math::kDeg / 9.81;  // rad/s per m/s² (0.1 °/s/g)
    double accBias = 0.05;                          // m/s²
    double accNoise = 0.04;                         // m/s², σ per sample
    double accScale = 0.01;                         // relative
    double vibration = 2.0;                         // m/s², amplitude at the feet while skiing (15–30 Hz)
    double impactRate = 0.3;                        // 1/s while skiing
    double impactPeak = 150.0;                      // m/s², half-sine over 10 ms at the feet (attenuated upwards)
    double gravity = 9.81;
};

struct BodySensor {
    math::Quat mount = math::Quat::Identity();  // segment → sensor coordinates (JointAngles::Params)
    math::Vec3 gyrBias = math::Vec3::Zero(), gyrDrift = math::Vec3::Zero(), accBias = math::Vec3::Zero();
    std::vector<math::Vec3> acc, gyr;  // sensor frame, m/s², rad/s
    std::vector<math::Quat> sensor;    // true sensor → earth (ENU)
    std::vector<math::Quat> segment;   // true segment → earth (ENU)
    std::vector<math::Vec3> position;  // true sensor position in ENU (m)
};

struct BodyJointTruth {
    // Sensor-to-joint-centre vectors in the proximal and distal sensors' frames (m, constant).
    math::Vec3 proximalToJoint = math::Vec3::Zero(), distalToJoint = math::Vec3::Zero();
    std::vector<math::Vec3> centre;        // joint centre in ENU (m)
    std::vector<AnatomicalAngles> angles;  // reference angles (rad), signs as in JointAngles.h
};

struct BodySimulation {
    std::vector<double> t;
    std::array<BodySensor, kBodySegments> sensors;
    std::array<BodyJointTruth, kBodyJoints> joints;
    // 0 stand, 1 squat, 2 walk, 3 ski, 4 trunk rotation, 5 right, 6 left abduction, 7 arm swings (the body stands)
    std::vector<unsigned char> phase;
    double uprightEnd = 0, squatBegin = 0, squatEnd = 0, motionBegin = 0, motionEnd = 0;
    // The further calibration blocks (begin = end when off); arm swings: the swings only, without the grip.
    double trunkBegin = 0, trunkEnd = 0, rightAbductionBegin = 0, rightAbductionEnd = 0, leftAbductionBegin = 0,
           leftAbductionEnd = 0, armSwingBegin = 0, armSwingEnd = 0;
    std::vector<double> impacts;  // s, start of each ski impact (10 ms half-sine)
    const BodySensor& operator[](BodySegment s) const { return sensors[static_cast<int>(s)]; }
    const BodyJointTruth& operator[](BodyJoint j) const { return joints[static_cast<int>(j)]; }
};

BodySimulation simulateBody(const BodySimulatorParams& params);

// The simulated body at any instant t (s): segment orientations (segment → ENU), joint centres (ENU)
// and the share of the full speed (0–1, what scales the ski vibration) — exactly what simulateBody
// samples at its sample times. For simulators that hang further segments on this chain
// (body::simulateWholeBody) and differentiate their sensors' positions as simulateBody does.
struct BodyPose {
    std::array<math::Quat, kBodySegments> segment;
    std::array<math::Vec3, kBodyJoints> joint;
    double speedShare = 0.0;
};
BodyPose bodyPoseAt(const BodySimulatorParams& params, double t);

// The IMU of simulateBody, for every simulated sensor on the body (also body::simulateWholeBody's head,
// back and arm sensors). The ideal signals follow LimbSimulator: the gyroscope measures the constant
// body rate between consecutive true sensor orientations, the accelerometer the specific force
// Rᵀ(p̈ + g e_z) with p̈ from a central second difference of the sensor position.
math::Vec3 idealRate(const math::Quat& previous, const math::Quat& current, double dt);
math::Vec3 idealSpecificForce(const math::Quat& sensor, const math::Vec3& before, const math::Vec3& at,
                              const math::Vec3& after, double h, double gravity);

// One sensor's constant errors (spec §1/§10, the magnitudes of BodySimulatorParams).
struct ImuErrors {
    math::Vec3 gyrBias = math::Vec3::Zero(), gyrDrift = math::Vec3::Zero(), accBias = math::Vec3::Zero();
    math::Vec3 gyrScale = math::Vec3::Ones(), accScale = math::Vec3::Ones();
    Eigen::Matrix3d gSensitivity = Eigen::Matrix3d::Zero();  // rad/s per m/s², row i = gyroscope axis i
    std::array<double, 9> vibration{};                       // per axis: frequency (Hz), phase, amplitude share
};

// The random source of the error model: draws each sensor's constant errors and each sample's noise
// in a fixed order, so a simulation is reproducible from its seed.
class ImuErrorSource {
public:
    ImuErrorSource(std::uint64_t seed, const BodySimulatorParams& params) : rng_(seed), params_(params) {}
    // Constant bias, the slow bias change (norm gyrDrift, random direction), scale factors, g-sensitivity,
    // vibration frequencies and phases.
    ImuErrors draw();
    // The vibration pattern at t (per axis in ±1, times the amplitude share): scaled by the speed share,
    // BodySimulatorParams::vibration and how much of it reaches the sensor.
    static math::Vec3 shake(const ImuErrors& e, double t);
    // Share of the slow gyroscope bias change at t: 0 before the motion, ramping to 1 over 20 s after it starts.
    static double driftShare(double t, double motionBegin);
    // Measured gyroscope and accelerometer samples from the ideal rate ω and specific force f (sensor frame,
    // vibration and impacts already in f): scale, bias, drift, g-sensitivity and white noise.
    void measure(const ImuErrors& e, const math::Vec3& omega, const math::Vec3& f, double driftShare, math::Vec3& gyr,
                 math::Vec3& acc);
    std::mt19937_64& engine() { return rng_; }

private:
    math::Vec3 normal3();
    math::Vec3 uniform3();
    std::mt19937_64 rng_;
    std::normal_distribution<double> normal_{0.0, 1.0};
    std::uniform_real_distribution<double> uniform_{-1.0, 1.0};
    const BodySimulatorParams& params_;
};

}  // namespace athlos::inertial
