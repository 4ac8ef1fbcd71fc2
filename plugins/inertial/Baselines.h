#pragma once
// Baseline orientation filters, selectable with algorithm= for comparison with OrientationFilter.
// Each starts from the orientation of its first accelerometer (and magnetometer) sample and uses the
// same conventions (sensor→earth, ENU, body rates).
#include "plugins/inertial/OrientationTypes.h"

namespace athlos::inertial {

// Initial orientation from one sample: acc (+ mag).
Quat initialOrientation(const Vec3& acc, const Vec3* mag);

// What Strapdown, Madgwick and Mahony share: a quaternion that starts at the orientation of the
// first sample (unless the caller sets one), and no rest or magnetic-disturbance detection.
template <class Filter>
class QuaternionBaseline {
public:
    void updateBatch(const ImuBatch& in, OrientationTrack& out) { runBatch(static_cast<Filter&>(*this), in, out); }
    Quat quaternion() const { return q_; }
    bool restDetected() const { return false; }
    bool magDisturbed() const { return false; }
    void setQuaternion(const Quat& q) {
        q_ = q;
        initialised_ = true;
    }

protected:
    explicit QuaternionBaseline(double ts) : ts_(ts) {}
    // Called first in every update(): takes the orientation of the first sample.
    void initialiseFrom(const Vec3& acc, const Vec3* mag) {
        if (initialised_) return;
        q_ = initialOrientation(acc, mag);
        initialised_ = true;
    }

    double ts_;
    Quat q_ = Quat::Identity();

private:
    bool initialised_ = false;
};

// Plain strapdown integration of the gyroscope (Fasel, spec §2): q ← q ⊗ exp(ω dt / 2).
class Strapdown : public QuaternionBaseline<Strapdown> {
public:
    explicit Strapdown(double ts) : QuaternionBaseline(ts) {}
    void update(const Vec3& gyr, const Vec3& acc, const Vec3* mag);
    Vec3 bias() const { return Vec3::Zero(); }
};

// Madgwick, Harrison, Vaidyanathan, "Estimation of IMU and MARG orientation using a gradient descent
// algorithm", ICORR 2011. The gradient of f = Rᵀd − s is taken in the tangent space (rotation vector
// on the right), where it is Σ v_i × s_i with v_i = Rᵀd_i; this is the normalised quaternion
// gradient of the paper (eqs. 20–34) without its radial part, which normalisation removes anyway.
// Magnetic reference (eq. 45–46, ENU): b = (0, |h_xy|, h_z) with h = R m.
class Madgwick : public QuaternionBaseline<Madgwick> {
public:
    struct Params {
        double beta = 0.1;  // rad/s, gradient step (the paper's β = √(3/4) ω̃_β)
    };
    Madgwick(double ts, const Params& params) : QuaternionBaseline(ts), p_(params) {}
    void update(const Vec3& gyr, const Vec3& acc, const Vec3* mag);
    Vec3 bias() const { return Vec3::Zero(); }

private:
    Params p_;
};

// Mahony, Hamel, Pflimlin, "Nonlinear complementary filters on the special orthogonal group",
// IEEE TAC 53(5), 2008 (explicit complementary filter, eqs. 32–34): ω' = ω + Kp e + Ki ∫e with
// e = Σ s_i × v_i; the magnetometer contributes its horizontal direction only.
class Mahony : public QuaternionBaseline<Mahony> {
public:
    struct Params {
        double kp = 0.74;    // rad/s (BROAD paper's best single gain)
        double ki = 0.0012;  // rad/s²
    };
    Mahony(double ts, const Params& params) : QuaternionBaseline(ts), p_(params) {}
    void update(const Vec3& gyr, const Vec3& acc, const Vec3* mag);
    Vec3 bias() const { return -integral_; }

private:
    Params p_;
    Vec3 integral_ = Vec3::Zero();
};

// The attitude Kalman filter of Kim, Park, Yoon, Sensors 2023 (seed 004, eqs. 50–55): state q,
// prediction A = I + T_s/2 Ω(ω) (eq. 6), measurement z = q(roll, pitch from the accelerometer
// (eqs. 7–8), yaw) with H = I. In 6D the yaw of z is the filter's own yaw (heading is unobserved,
// as in the paper); in 9D it is the tilt-compensated magnetometer heading.
// Eqs. 7–8 are written for the paper's axes; in ENU with aerospace Z-Y-X angles, at rest
// f = Rᵀ(0,0,g) = g(−sin θ, cos θ sin φ, cos θ cos φ), so φ = atan2(a_y, a_z),
// θ = atan2(−a_x, √(a_y² + a_z²)).
class QuaternionKalman {
public:
    struct Params {
        double gyrNoise = 0.005;  // rad/s/√Hz: process noise Q = σ² T_s / 4 · I
        double angleNoise = 0.2;  // rad: measurement noise R = (σ/2)² · I
    };
    QuaternionKalman(double ts, const Params& params) : ts_(ts), p_(params) {}
    void update(const Vec3& gyr, const Vec3& acc, const Vec3* mag);
    void updateBatch(const ImuBatch& in, OrientationTrack& out) { runBatch(*this, in, out); }
    Quat quaternion() const { return math::quatFromWxyz(x_); }
    Vec3 bias() const { return Vec3::Zero(); }
    bool restDetected() const { return false; }
    bool magDisturbed() const { return false; }

private:
    double ts_;
    Params p_;
    Eigen::Vector4d x_ = Eigen::Vector4d(1, 0, 0, 0);  // (w, x, y, z)
    Eigen::Matrix4d P_ = Eigen::Matrix4d::Identity();
    bool initialised_ = false;
};

}  // namespace athlos::inertial
