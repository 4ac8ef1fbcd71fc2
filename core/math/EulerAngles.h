#pragma once
// Euler/Cardan angle decompositions in any of the 12 axis sequences, intrinsic or extrinsic.
//
// A sequence is three letters naming the axes in the order the rotations are applied:
//   upper case ("ZYX", "XYZ", "ZXZ", ...) = intrinsic (rotating frame): q = R_Z(a0) ⊗ R_Y(a1) ⊗ R_X(a2);
//   lower case ("zyx", "xyz", "zxz", ...) = extrinsic (fixed frame):   q = R_x(a2) ⊗ R_y(a1) ⊗ R_z(a0)
//                                                                       for "zyx", i.e. first a0 about z.
// Intrinsic "ZYX" on a sensor→earth quaternion gives the aerospace yaw, pitch, roll.
// Cardan sequences (three different axes) have the middle angle in [-π/2, π/2], proper Euler
// sequences (first = last axis) in [0, π]; the others in (-π, π].
// Gimbal lock (middle angle at its limit): the two outer axes coincide, only their sum (or
// difference) is defined; the decomposition then sets the angle applied first to zero and puts all of
// it into the other outer angle, so composing the angles again reproduces the rotation exactly.
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"

#include <QString>
#include <array>

namespace athlos::math {

struct EulerSequence {
    std::array<int, 3> axes{2, 1, 0};  // 0 = x, 1 = y, 2 = z, in the order given by the name
    bool intrinsic = true;

    // "ZYX", "xyz", ... Errors name the text and say what is allowed.
    static Expected<EulerSequence> parse(const QString& name);
    QString name() const;
    bool isProper() const { return axes[0] == axes[2]; }
};

// Angles (rad) of q in the sequence, in the order of the sequence's name.
Vec3 eulerFromQuaternion(const Quat& q, const EulerSequence& sequence);
// The same decomposition in two steps, for batches whose atan2 calls are evaluated together
// (vectorised): the three atan2 arguments (y, x) of q, then the angles from the three atan2 values.
// eulerFromAtan2(s, {atan2(y[i], x[i])}) equals eulerFromQuaternion(q, s) exactly.
struct EulerAtan2Arguments {
    std::array<double, 3> y{}, x{};
};
EulerAtan2Arguments eulerAtan2Arguments(const Quat& q, const EulerSequence& sequence);
Vec3 eulerFromAtan2(const std::array<double, 3>& atan2Values, const EulerSequence& sequence);
// The quaternion composed from angles (rad) in the sequence.
Quat quaternionFromEuler(const Vec3& angles, const EulerSequence& sequence);

}  // namespace athlos::math
