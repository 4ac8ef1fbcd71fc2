#pragma once
// Magnetic disturbance detection (VQF, Laidig & Seel 2023, Sec. 3.5). The magnetometer sample is
// expressed in the heading-free earth frame; its norm and dip angle are compared with a reference
// field. A sample is undisturbed when the norm is within thNorm (relative) and the dip within thDip
// of the reference; after minUndisturbedTime of undisturbed samples the reference slowly tracks the
// field (τ = refTau). A new, consistent field (a candidate) replaces the reference after newTime of
// motion (newFirstTime when there is no reference yet) — so a changed but homogeneous environment is
// accepted, while a transient magnet near the sensor is not.
#include "core/math/Angles.h"
#include "plugins/inertial/LowPass2.h"
#include "plugins/inertial/OrientationTypes.h"

#include <cmath>

namespace athlos::inertial {

class MagDisturbance {
public:
    struct Params {
        double currentTau = 0.05;              // s, smoothing of norm and dip
        double refTau = 20.0;                  // s, tracking of the reference
        double thNorm = 0.1;                   // relative norm deviation
        double thDip = 10.0 * math::kDeg;      // rad
        double newTime = 20.0;                 // s
        double newFirstTime = 5.0;             // s
        double newMinGyr = 20.0 * math::kDeg;  // rad/s, motion needed to accept a new field
        double minUndisturbedTime = 0.5;       // s
    };

    MagDisturbance() = default;
    MagDisturbance(const Params& p, double ts) { setup(p, ts); }
    void setup(const Params& p, double ts) {
        p_ = p;
        ts_ = ts;
        kRef_ = gainFromTau(p.refTau, ts);
        lp_.setup(p.currentTau, ts);
        reset();
    }
    void reset() {
        lp_.reset();
        refNorm_ = refDip_ = 0.0;
        candNorm_ = candDip_ = -1.0;
        candTime_ = 0.0;
        undisturbedTime_ = 0.0;
        disturbed_ = true;  // no reference yet
    }

    // magEarth: the field in the heading-free earth frame; gyrLp: low-pass gyro (motion measure).
    void update(const Vec3& magEarth, const Vec3& gyrLp) {
        const double norm = magEarth.norm();
        Eigen::Vector2d nd(norm, norm > 0.0 ? -std::asin(std::clamp(magEarth.z() / norm, -1.0, 1.0)) : 0.0);
        if (p_.currentTau > 0.0) nd = lp_.step(nd);
        if (std::abs(nd[0] - refNorm_) < p_.thNorm * refNorm_ && std::abs(nd[1] - refDip_) < p_.thDip) {
            undisturbedTime_ += ts_;
            if (undisturbedTime_ >= p_.minUndisturbedTime) {
                disturbed_ = false;
                refNorm_ += kRef_ * (nd[0] - refNorm_);
                refDip_ += kRef_ * (nd[1] - refDip_);
            }
        } else {
            undisturbedTime_ = 0.0;
            disturbed_ = true;
        }
        if (std::abs(nd[0] - candNorm_) < p_.thNorm * candNorm_ && std::abs(nd[1] - candDip_) < p_.thDip) {
            if (gyrLp.norm() >= p_.newMinGyr) candTime_ += ts_;
            candNorm_ += kRef_ * (nd[0] - candNorm_);
            candDip_ += kRef_ * (nd[1] - candDip_);
            if (disturbed_ && (candTime_ >= p_.newTime || (refNorm_ == 0.0 && candTime_ >= p_.newFirstTime))) {
                refNorm_ = candNorm_;
                refDip_ = candDip_;
                disturbed_ = false;
                undisturbedTime_ = p_.minUndisturbedTime;
            }
        } else {
            candTime_ = 0.0;
            candNorm_ = nd[0];
            candDip_ = nd[1];
        }
    }

    bool isDisturbed() const { return disturbed_; }
    double referenceNorm() const { return refNorm_; }
    double referenceDip() const { return refDip_; }

private:
    Params p_;
    double ts_ = 0.01, kRef_ = 0.0;
    LowPass2<2> lp_;
    double refNorm_ = 0.0, refDip_ = 0.0, candNorm_ = -1.0, candDip_ = -1.0, candTime_ = 0.0;
    double undisturbedTime_ = 0.0;
    bool disturbed_ = true;
};

}  // namespace athlos::inertial
