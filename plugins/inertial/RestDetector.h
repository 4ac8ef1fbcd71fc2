#pragma once
// Rest detection (VQF, Laidig & Seel 2023, Sec. 3.4): the sensor is at rest when, for at least
// restMinT, every gyroscope sample stays within thGyr of its low-pass filtered value (τ = filterTau),
// the low-pass gyro stays below biasClip (a large constant rate is motion, not bias), and every
// accelerometer sample stays within thAcc of its low-pass value. The low-pass gyro at rest is the
// bias measurement.
#include "core/math/Angles.h"
#include "plugins/inertial/LowPass2.h"
#include "plugins/inertial/OrientationTypes.h"

namespace athlos::inertial {

class RestDetector {
public:
    struct Params {
        double minTime = 1.5;                // s
        double filterTau = 0.5;              // s
        double thGyr = 2.0 * math::kDeg;     // rad/s
        double thAcc = 0.5;                  // m/s²
        double biasClip = 2.0 * math::kDeg;  // rad/s
    };

    RestDetector() = default;
    RestDetector(const Params& p, double ts) { setup(p, ts); }
    void setup(const Params& p, double ts) {
        p_ = p;
        ts_ = ts;
        gyrLp_.setup(p.filterTau, ts);
        accLp_.setup(p.filterTau, ts);
        reset();
    }
    void reset() {
        gyrLp_.reset();
        accLp_.reset();
        restTime_ = 0.0;
        rest_ = false;
        lastGyrLp_.setZero();
    }

    void updateGyr(const Vec3& gyr) {
        lastGyrLp_ = gyrLp_.step(gyr);
        if ((gyr - lastGyrLp_).squaredNorm() >= p_.thGyr * p_.thGyr || lastGyrLp_.cwiseAbs().maxCoeff() > p_.biasClip)
            moved();
    }
    void updateAcc(const Vec3& acc) {
        const Vec3 lp = accLp_.step(acc);
        if ((acc - lp).squaredNorm() >= p_.thAcc * p_.thAcc) {
            moved();
        } else {
            restTime_ += ts_;
            if (restTime_ >= p_.minTime) rest_ = true;
        }
    }

    bool isRest() const { return rest_; }
    const Vec3& gyrLowPass() const { return lastGyrLp_; }

private:
    void moved() {
        restTime_ = 0.0;
        rest_ = false;
    }
    Params p_;
    double ts_ = 0.01;
    LowPass2<3> gyrLp_, accLp_;
    double restTime_ = 0.0;
    bool rest_ = false;
    Vec3 lastGyrLp_ = Vec3::Zero();
};

}  // namespace athlos::inertial
