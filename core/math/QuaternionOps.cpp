#include "core/math/QuaternionOps.h"

#include <cmath>
#include <numbers>

namespace athlos::math {

Quat quatExp(const Vec3& v) {
    const double n = v.norm();
    if (n < 1e-12) return Quat(1.0, v.x(), v.y(), v.z()).normalized();  // first-order, stays unit
    const double s = std::sin(n) / n;
    return Quat(std::cos(n), s * v.x(), s * v.y(), s * v.z());
}

Vec3 quatLog(const Quat& q) {
    const Quat c = canonical(q.normalized());
    const Vec3 v = c.vec();
    const double n = v.norm();
    if (n < 1e-12) return v;
    return v * (std::atan2(n, c.w()) / n);
}

Quat quatFromRotationVector(const Vec3& r) { return quatExp(0.5 * r); }
Vec3 rotationVectorFromQuat(const Quat& q) { return 2.0 * quatLog(q); }

Quat quatFromAxisAngle(const Vec3& axis, double angle) { return quatFromRotationVector(axis.normalized() * angle); }

Quat integrateBodyRate(const Quat& q, const Vec3& omega, double dt) {
    return (q * quatExp(0.5 * dt * omega)).normalized();
}

Quat slerp(const Quat& a, const Quat& b, double t) {
    double d = a.dot(b);
    Quat bb = b;
    if (d < 0.0) {  // shorter arc: q and -q are the same rotation
        bb.coeffs() = -b.coeffs();
        d = -d;
    }
    if (d > 1.0 - 1e-12) {  // nearly identical: linear interpolation is exact to rounding
        Quat r;
        r.coeffs() = (1.0 - t) * a.coeffs() + t * bb.coeffs();
        return r.normalized();
    }
    const double theta = std::acos(d);
    const double s = std::sin(theta);
    Quat r;
    r.coeffs() = (std::sin((1.0 - t) * theta) / s) * a.coeffs() + (std::sin(t * theta) / s) * bb.coeffs();
    return r;
}

Quat canonical(const Quat& q) {
    if (q.w() >= 0.0) return q;
    Quat r;
    r.coeffs() = -q.coeffs();
    return r;
}

Quat headingRotation(double angle) { return Quat(std::cos(0.5 * angle), 0.0, 0.0, std::sin(0.5 * angle)); }

double headingAngle(const Quat& q) {
    const Vec3 x = q * Vec3::UnitX();
    return std::atan2(x.y(), x.x());
}

double twistHeadingAngle(const Quat& q) {
    const Quat c = canonical(q);  // w ≥ 0: the angle in (−π, π]
    return 2.0 * std::atan2(c.z(), c.w());
}

double inclinationAngle(const Quat& q) {
    const Vec3 z = q * Vec3::UnitZ();
    return std::acos(std::clamp(z.z(), -1.0, 1.0));
}

void splitHeadingInclination(const Quat& q, Quat& heading, Quat& inclination) {
    // Twist about earth z: project the (left) rotation axis on z. q = h ⊗ i with i having no
    // z component of its vector part in the earth frame: h = normalize(w, 0, 0, z).
    const double n = std::hypot(q.w(), q.z());
    heading = n < 1e-12 ? Quat::Identity() : Quat(q.w() / n, 0.0, 0.0, q.z() / n);
    inclination = heading.conjugate() * q;
}

Quat quatFromAccelerometer(const Vec3& acc) {
    const double n = acc.norm();
    if (n < 1e-12) return Quat::Identity();
    return Quat::FromTwoVectors(acc / n, Vec3::UnitZ());
}

Quat quatFromAccMag(const Vec3& acc, const Vec3& mag) {
    const double an = acc.norm();
    if (an < 1e-12) return Quat::Identity();
    const Vec3 up = acc / an;
    Vec3 east = mag.cross(up);
    const double en = east.norm();
    if (en < 1e-9 * std::max(1.0, mag.norm())) return quatFromAccelerometer(acc);
    east /= en;
    const Vec3 north = up.cross(east);
    Eigen::Matrix3d r;  // rows: earth axes in sensor coordinates → v_E = r v_S
    r.row(0) = east;
    r.row(1) = north;
    r.row(2) = up;
    return canonical(Quat(r)).normalized();
}

}  // namespace athlos::math
