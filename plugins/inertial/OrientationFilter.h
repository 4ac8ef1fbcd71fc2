#pragma once
// The default orientation filter: our implementation of the method of Laidig & Seel, "VQF: Highly
// Accurate IMU Orientation Estimation with Bias Estimation and Magnetic Disturbance Rejection",
// Information Fusion 91, 2023 (written from the paper, not from its code).
//
// The orientation is factored as q = δ_mag ⊗ q_acc ⊗ q_gyr (eq. 3):
//  - q_gyr: strapdown integration of the bias-corrected gyroscope, giving an "almost inertial" frame I;
//  - q_acc: inclination correction. The accelerometer is rotated into I, low-pass filtered there
//    (2nd-order Butterworth, τ_acc) and rotated into E; q_acc is then rotated so that this filtered
//    vector points up. Filtering in the almost inertial frame averages out the athlete's own
//    accelerations and shocks (they integrate to a velocity change, i.e. to ~0 over a few seconds)
//    while gravity stays constant — this is how high dynamics are rejected without a threshold;
//  - δ_mag: heading correction about the vertical only, so the magnetometer never tilts the
//    inclination; first-order filter with τ_mag, paused/slowed while a disturbance is detected
//    (rejection for at most maxRejectionTime, then reduced gain);
//  - gyroscope bias: a 3-state Kalman filter fed at rest with the low-pass gyro and in motion with the
//    inclination corrections expressed as angular rates (horizontal axes; the vertical one only
//    decays), eqs. 20–27.
// All time constants are in seconds, so the same parameters work at any sampling rate.
#include "core/math/Angles.h"
#include "plugins/inertial/LowPass2.h"
#include "plugins/inertial/MagDisturbance.h"
#include "plugins/inertial/OrientationTypes.h"
#include "plugins/inertial/RestDetector.h"

namespace athlos::inertial {

class OrientationFilter {
public:
    struct Params {
        double tauAcc = 3.0;  // s
        double tauMag = 9.0;  // s
        bool restBiasEstimation = true;
        bool motionBiasEstimation = true;
        bool magDisturbanceRejection = true;
        double biasSigmaInit = 0.5 * math::kDeg;    // rad/s, initial bias uncertainty
        double biasForgettingTime = 100.0;          // s, time for the uncertainty to grow back by 0.1 °/s
        double biasClip = 2.0 * math::kDeg;         // rad/s, largest bias the filter accepts
        double biasSigmaMotion = 0.1 * math::kDeg;  // rad/s, motion-update measurement noise
        double biasVerticalForgettingFactor = 1e-4;
        double biasSigmaRest = 0.03 * math::kDeg;  // rad/s, rest-update measurement noise
        RestDetector::Params rest;
        MagDisturbance::Params mag;
        double magMaxRejectionTime = 60.0;  // s, longest ride-out of a disturbance
        double magRejectionFactor = 2.0;    // gain divisor after it, and recovery speed of the budget
        // Saturation gate (our addition to VQF): a sample with any accelerometer axis at the sensor's
        // range is replaced by the gravity the filter currently expects. Real shocks integrate to ~0
        // in the almost inertial frame and need no gate (gating by |a| − g > 3 g, 6 g broke BROAD's
        // fast-translation trial: 0.75° → 21°, 11°), but clipped ones lose part of their integral.
        // 0 = range unknown, gate off.
        double accRange = 0.0;  // m/s²
        double gravity = 9.81;  // m/s², magnitude of the substituted sample
    };

    // ts: nominal sampling interval (s); the filters' coefficients are derived from it.
    OrientationFilter(double ts, const Params& params);
    explicit OrientationFilter(double ts);
    void reset();

    // One sample; mag == nullptr runs 6D. acc or mag of exactly zero are treated as missing.
    void update(const Vec3& gyr, const Vec3& acc, const Vec3* mag);
    void updateBatch(const ImuBatch& in, OrientationTrack& out) { runBatch(*this, in, out); }

    Quat quaternion() const { return hasMag_ ? quaternion9D() : quaternion6D(); }
    Quat quaternion6D() const { return (accQuat_ * gyrQuat_).normalized(); }
    Quat quaternion9D() const { return (headingQuat_ * accQuat_ * gyrQuat_).normalized(); }
    const Vec3& bias() const { return bias_; }
    double biasSigma() const;  // rad/s, from the largest diagonal element of P
    bool restDetected() const { return rest_.isRest(); }
    bool magDisturbed() const { return hasMag_ && magDist_.isDisturbed(); }
    double headingOffset() const { return delta_; }

    const Params& params() const { return p_; }

private:
    void updateGyr(const Vec3& gyr);
    // Returns false when acc carries no direction; accEarth receives the (pre-correction) unit vector.
    bool updateAcc(const Vec3& acc, Vec3& accEarth);
    void updateBias(const Vec3& accEarth, const Mat3& r);
    void updateMag(const Vec3& mag, const Mat3& r);

    Params p_;
    double ts_;
    // coefficients
    double biasP0_, biasV_, biasMotionW_, biasVerticalW_, biasRestW_, kMag_;
    // state
    Quat gyrQuat_, accQuat_;
    double delta_;
    Quat headingQuat_;  // rotation by delta_ about z, kept in step with it
    Vec3 bias_;
    Mat3 biasP_;
    LowPass2<3> accLp_;
    LowPass2<2> biasLp_;
    RestDetector rest_;
    MagDisturbance magDist_;
    double kMagInit_;
    double magRejectT_;
    bool hasMag_;
};

}  // namespace athlos::inertial
