#pragma once
// Where an IMU stream keeps its axes: the adjacent column triples acc_x..z, gyr_x..z and mag_x..z;
// and the quaternions (qw, qx, qy, qz, sensor → earth) of an orientation stream.
#include "core/math/QuaternionOps.h"
#include "core/processing/Processor.h"

#include <vector>

namespace athlos::inertial {

// Index of column <prefix>x whose <prefix>y and <prefix>z follow it, or -1.
int tripleIndex(const StreamInfo& info, const QString& prefix);

struct ImuColumns {
    int acc = -1, gyr = -1, mag = -1;  // first of each x, y, z triple; mag -1 when absent
};
// acc_x..z and gyr_x..z are required (an error naming the input otherwise); mag optional unless
// requireMag.
Expected<ImuColumns> imuColumns(const InputSamples& input, bool requireMag);

// The orientation stream's rows as unit quaternions (columns qw, qx, qy, qz); an error naming the
// input for a missing column or a row without a finite, non-zero quaternion.
Expected<std::vector<math::Quat>> orientationQuaternions(const InputSamples& s);

}  // namespace athlos::inertial
