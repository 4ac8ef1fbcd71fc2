#pragma once
// Quaternion and rotation toolkit on Eigen.
//
// Conventions (ARCHITECTURE.md): quaternions are Hamilton, scalar-first when written as (w, x, y, z),
// and map sensor coordinates to earth coordinates, v_E = q ⊗ v_S ⊗ q* (Eigen: q * v, or
// q.toRotationMatrix() * v). The earth frame is East-North-Up. Angular rates are in the sensor frame,
// so strapdown integration multiplies on the right: q(t+dt) = q(t) ⊗ exp(ω dt / 2).
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace athlos::math {

using Quat = Eigen::Quaterniond;
using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;

// (w, x, y, z) ↔ quaternion.
inline Quat quatFromWxyz(double w, double x, double y, double z) { return Quat(w, x, y, z); }
inline Vec4 wxyz(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }
inline Quat quatFromWxyz(const Vec4& v) { return Quat(v[0], v[1], v[2], v[3]); }

// Exponential map of a pure quaternion (0, v): (cos|v|, sin|v| v/|v|). Exact for all |v|.
Quat quatExp(const Vec3& v);
// Logarithm of a unit quaternion: the vector part v with exp((0, v)) = q, |v| ≤ π/2 after sign choice (w ≥ 0).
Vec3 quatLog(const Quat& q);

// Rotation vector (axis · angle) ↔ unit quaternion: q = exp(r/2), the shortest rotation (angle ≤ π).
Quat quatFromRotationVector(const Vec3& r);
Vec3 rotationVectorFromQuat(const Quat& q);
Quat quatFromAxisAngle(const Vec3& axis, double angle);

// One strapdown step with a constant body rate ω (rad/s) over dt: q ⊗ exp(ω dt / 2). Exact for
// constant ω (Fasel eq. in spec §2 with the dt the source omits).
Quat integrateBodyRate(const Quat& q, const Vec3& omega, double dt);

// Spherical linear interpolation along the shorter arc: t = 0 → a, t = 1 → b (or -b).
Quat slerp(const Quat& a, const Quat& b, double t);

// The representative with w ≥ 0 (q and -q are the same rotation).
Quat canonical(const Quat& q);

// Rotation about the earth's vertical (z, Up) by angle (rad, counter-clockwise seen from above).
Quat headingRotation(double angle);
// Heading of a sensor→earth quaternion: the angle of the sensor's x axis projected on the
// horizontal plane, counter-clockwise from East (rad). Undefined (0) when x points straight up/down.
double headingAngle(const Quat& q);
// Heading as the twist of q about the earth's vertical (the heading factor of
// splitHeadingInclination below): 2·atan2(q_z, q_w) in (−π, π], counter-clockwise (rad); q = Rz(ψ)·q_i
// with q_i a rotation about a horizontal axis gives ψ. Applied to the rotation between two
// orientations, q1 ⊗ q0*, it is their heading change whatever the sensor's mounting (the mounting
// cancels; no sensor axis has to be horizontal).
double twistHeadingAngle(const Quat& q);
// Inclination: angle between the sensor's z axis and the earth's vertical (rad).
double inclinationAngle(const Quat& q);

// Splits q = q_heading ⊗ q_inclination, where q_heading rotates about earth z and q_inclination has
// no rotation about earth z (swing–twist decomposition about the vertical).
void splitHeadingInclination(const Quat& q, Quat& heading, Quat& inclination);

// Orientation whose earth-frame vertical matches the accelerometer (at rest it measures the specific
// force, which points up) with zero heading change relative to `headingOf` (identity by default):
// the smallest rotation taking the sensor's measured up direction to earth up.
Quat quatFromAccelerometer(const Vec3& acc);
// Full orientation from accelerometer and magnetometer (ENU: the horizontal magnetic field points
// north = +y). Falls back to quatFromAccelerometer when mag is (nearly) parallel to acc or zero.
Quat quatFromAccMag(const Vec3& acc, const Vec3& mag);

}  // namespace athlos::math
