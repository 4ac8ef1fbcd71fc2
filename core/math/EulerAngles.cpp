#include "core/math/EulerAngles.h"

#include "core/math/Angles.h"

#include <cmath>
#include <numbers>

namespace athlos::math {

namespace {

Quat elementary(int axis, double angle) {
    Vec3 a = Vec3::Zero();
    a[axis] = 1.0;
    return Quat(Eigen::AngleAxisd(angle, a));
}

// Extrinsic decomposition (first rotation about axes[0] in the fixed frame), after Bernardes &
// Viollet, "Quaternion to Euler angles conversion: a direct, general and computationally efficient
// method", PLoS ONE 17(11), 2022: the quaternion is permuted so that the sequence becomes a proper
// one about (i, j, k), the middle angle follows from |(c, d)| vs |(a, b)| and the outer angles from
// two half-angle sums — no trigonometric matrix elements, so no precision loss near the poles.
// Step 1: the arguments of the three atan2 (middle angle, half sum, half difference).
EulerAtan2Arguments extrinsicArguments(const Quat& quat, int i, int j, int k0) {
    const Vec4 q{quat.x(), quat.y(), quat.z(), quat.w()};  // components by axis index, w last
    const bool proper = (i == k0);
    const int k = proper ? 3 - i - j : k0;
    const double sign = static_cast<double>((i - j) * (j - k) * (k - i) / 2);  // ±1: axis order parity
    double a, b, c, d;
    if (proper) {
        a = q[3];
        b = q[i];
        c = q[j];
        d = q[k] * sign;
    } else {  // Eq. (8): rotate the frame by 45° about j to turn a Cardan into a proper sequence
        a = q[3] - q[j];
        b = q[i] + q[k] * sign;
        c = q[j] + q[3];
        d = q[k] * sign - q[i];
    }
    // a, b, c, d are sums of two unit-quaternion components (|·| ≤ 2): the plain square roots cannot
    // overflow or underflow, and are several times faster than std::hypot.
    EulerAtan2Arguments r;
    r.y = {std::sqrt(c * c + d * d), b, d};
    r.x = {std::sqrt(a * a + b * b), a, c};
    return r;
}

// Step 2: the angles from the three atan2 values.
Vec3 extrinsicFromAtan2(const std::array<double, 3>& atan2Values, int i, int j, int k0) {
    const bool proper = (i == k0);
    const int k = proper ? 3 - i - j : k0;
    const double sign = static_cast<double>((i - j) * (j - k) * (k - i) / 2);
    Vec3 angles;
    angles[1] = 2.0 * atan2Values[0];
    const double halfSum = atan2Values[1];
    const double halfDiff = atan2Values[2];
    constexpr double eps = 1e-9;
    if (std::abs(angles[1]) <= eps) {  // gimbal lock: only θ1 + θ3 is defined
        angles[0] = 2.0 * halfSum;
        angles[2] = 0.0;
    } else if (std::abs(angles[1] - std::numbers::pi) <= eps) {  // only θ1 - θ3 is defined
        angles[0] = -2.0 * halfDiff;
        angles[2] = 0.0;
    } else {
        angles[0] = halfSum - halfDiff;
        angles[2] = halfSum + halfDiff;
    }
    if (!proper) {
        angles[2] *= sign;
        angles[1] -= std::numbers::pi / 2.0;
    }
    for (int n = 0; n < 3; ++n) angles[n] = wrapAngle(angles[n]);
    return angles;
}

// The axes of the extrinsic decomposition that a sequence reduces to: intrinsic (A, B, C) with
// angles (a, b, c) is extrinsic (C, B, A) with angles (c, b, a).
std::array<int, 3> extrinsicAxes(const EulerSequence& s) {
    return s.intrinsic ? std::array<int, 3>{s.axes[2], s.axes[1], s.axes[0]} : s.axes;
}

}  // namespace

Expected<EulerSequence> EulerSequence::parse(const QString& name) {
    const auto fail = [&] {
        return makeError(QStringLiteral("invalid Euler sequence '%1': use three axis letters with no axis twice in a "
                                        "row, upper case for intrinsic (ZYX, XYZ, ZXZ, ...) or lower case for "
                                        "extrinsic (zyx, xyz, zxz, ...)")
                             .arg(name));
    };
    if (name.size() != 3) return fail();
    EulerSequence s;
    const bool upper = name.at(0).isUpper();
    for (int n = 0; n < 3; ++n) {
        const QChar ch = name.at(n);
        if (ch.isUpper() != upper) return fail();
        const int axis = ch.toLower().unicode() - 'x';
        if (axis < 0 || axis > 2) return fail();
        s.axes[n] = axis;
    }
    if (s.axes[0] == s.axes[1] || s.axes[1] == s.axes[2]) return fail();
    s.intrinsic = upper;
    return s;
}

QString EulerSequence::name() const {
    QString n;
    for (int a : axes) n += QChar((intrinsic ? 'X' : 'x') + a);
    return n;
}

Vec3 eulerFromQuaternion(const Quat& q, const EulerSequence& s) {
    const EulerAtan2Arguments a = eulerAtan2Arguments(q, s);
    return eulerFromAtan2({std::atan2(a.y[0], a.x[0]), std::atan2(a.y[1], a.x[1]), std::atan2(a.y[2], a.x[2])}, s);
}

EulerAtan2Arguments eulerAtan2Arguments(const Quat& q, const EulerSequence& s) {
    const Quat u(q.coeffs() * (1.0 / q.coeffs().norm()));  // normalised, one division
    const std::array<int, 3> e = extrinsicAxes(s);
    return extrinsicArguments(u, e[0], e[1], e[2]);
}

Vec3 eulerFromAtan2(const std::array<double, 3>& atan2Values, const EulerSequence& s) {
    const std::array<int, 3> e = extrinsicAxes(s);
    const Vec3 r = extrinsicFromAtan2(atan2Values, e[0], e[1], e[2]);
    return s.intrinsic ? Vec3(r[2], r[1], r[0]) : r;
}

Quat quaternionFromEuler(const Vec3& angles, const EulerSequence& s) {
    const Quat q0 = elementary(s.axes[0], angles[0]);
    const Quat q1 = elementary(s.axes[1], angles[1]);
    const Quat q2 = elementary(s.axes[2], angles[2]);
    return s.intrinsic ? (q0 * q1 * q2).normalized() : (q2 * q1 * q0).normalized();
}

}  // namespace athlos::math
