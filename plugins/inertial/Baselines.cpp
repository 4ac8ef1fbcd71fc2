#include "plugins/inertial/Baselines.h"

#include <Eigen/LU>
#include <cmath>

namespace athlos::inertial {

Quat initialOrientation(const Vec3& acc, const Vec3* mag) {
    return mag ? math::quatFromAccMag(acc, *mag) : math::quatFromAccelerometer(acc);
}

void Strapdown::update(const Vec3& gyr, const Vec3& acc, const Vec3* mag) {
    initialiseFrom(acc, mag);
    q_ = math::integrateBodyRate(q_, gyr, ts_);
}

namespace {
// Earth-frame reference of the magnetometer for the current estimate (Madgwick eq. 45–46 in ENU):
// the measured field's horizontal part is assumed to point north.
Vec3 magReference(const Quat& q, const Vec3& m) {
    const Vec3 h = q * m;
    return {0.0, std::hypot(h.x(), h.y()), h.z()};
}

// Σ v_i × s_i over the normalised measurements s_i (accelerometer; magnetometer when present) and
// their earth references as the estimate q expects them in the sensor frame, v_i = Rᵀd_i. This is
// Madgwick's tangent-space gradient; Mahony's error e = Σ s_i × v_i is its negative.
Vec3 referenceGradient(const Quat& q, const Vec3& accUnit, const Vec3* mag) {
    const Quat qc = q.conjugate();
    Vec3 g = (qc * Vec3::UnitZ()).cross(accUnit);
    if (mag && mag->norm() > 0.0) {
        const Vec3 m = mag->normalized();
        g += (qc * magReference(q, m)).cross(m);
    }
    return g;
}
}  // namespace

void Madgwick::update(const Vec3& gyr, const Vec3& acc, const Vec3* mag) {
    initialiseFrom(acc, mag);
    Vec3 w = gyr;
    const double an = acc.norm();
    if (an > 0.0) {
        const Vec3 g = referenceGradient(q_, acc / an, mag);
        const double gn = g.norm();
        if (gn > 1e-12) w -= 2.0 * p_.beta * g / gn;  // q̇ = ½ q⊗ω − β ∇f/|∇f|  (eq. 43)
    }
    q_ = math::integrateBodyRate(q_, w, ts_);
}

void Mahony::update(const Vec3& gyr, const Vec3& acc, const Vec3* mag) {
    initialiseFrom(acc, mag);
    const double an = acc.norm();
    Vec3 w = gyr;
    if (an > 0.0) {
        const Vec3 e = -referenceGradient(q_, acc / an, mag);
        if (p_.ki > 0.0) integral_ += p_.ki * e * ts_;
        w += p_.kp * e + integral_;
    }
    q_ = math::integrateBodyRate(q_, w, ts_);
}

void QuaternionKalman::update(const Vec3& gyr, const Vec3& acc, const Vec3* mag) {
    if (!initialised_) {
        x_ = math::wxyz(initialOrientation(acc, mag));
        P_ = Eigen::Matrix4d::Identity() * 1e-2;
        initialised_ = true;
    }
    // Prediction (eqs. 50–51): x = A x, A = I + T_s/2 Ω(p, q, r) (eq. 6).
    const double p = gyr.x(), q = gyr.y(), r = gyr.z();
    Eigen::Matrix4d omega;
    omega << 0, -p, -q, -r, p, 0, r, -q, q, -r, 0, p, r, q, -p, 0;
    const Eigen::Matrix4d a = Eigen::Matrix4d::Identity() + 0.5 * ts_ * omega;
    x_ = a * x_;
    x_.normalize();
    P_ = a * P_ * a.transpose();
    P_.diagonal().array() += p_.gyrNoise * p_.gyrNoise * ts_ / 4.0;
    const double an = acc.norm();
    if (an <= 0.0) return;
    // Measurement: roll and pitch from the accelerometer (eqs. 7–8 in ENU axes), yaw from the
    // state (6D) or the tilt-compensated magnetometer (9D), composed with eqs. 2–5.
    const double roll = std::atan2(acc.y(), acc.z());
    const double pitch = std::atan2(-acc.x(), std::hypot(acc.y(), acc.z()));
    const Quat rp = Quat(Eigen::AngleAxisd(pitch, Vec3::UnitY())) * Quat(Eigen::AngleAxisd(roll, Vec3::UnitX()));
    double yaw;
    if (mag && mag->norm() > 0.0) {
        const Vec3 mh = rp * *mag;
        yaw = std::atan2(mh.x(), mh.y());
    } else {
        const Quat qs = math::quatFromWxyz(x_);
        const Vec3 xAxis = qs * Vec3::UnitX();
        yaw = std::atan2(xAxis.y(), xAxis.x());  // the Z-Y-X yaw of the state is the heading of its x axis
    }
    Eigen::Vector4d z = math::wxyz(math::headingRotation(yaw) * rp);
    if (z.dot(x_) < 0.0) z = -z;  // q and -q are the same attitude: measure on the state's side
    // Update (eqs. 52–54) with H = I.
    const Eigen::Matrix4d s = P_ + Eigen::Matrix4d::Identity() * (0.25 * p_.angleNoise * p_.angleNoise);
    const Eigen::Matrix4d k = P_ * s.inverse();
    x_ += k * (z - x_);
    x_.normalize();
    P_ = (Eigen::Matrix4d::Identity() - k) * P_;
}

}  // namespace athlos::inertial
