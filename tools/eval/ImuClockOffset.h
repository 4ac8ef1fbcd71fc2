#pragma once
// Clock offset between an IMU and an optical motion-capture system, measured from the accelerometer
// alone: the specific force rotated into the earth frame with the optical orientation, minus gravity,
// must equal the second derivative of the optical position (f_E = p̈ + g). Both are low-passed with
// the same zero-phase filter; the accelerometer is shifted by d samples and the offset is the d that
// minimises the RMS difference (parabolic interpolation between whole samples). The gyroscope is not
// involved, so a lag found here is one of the whole IMU against the optical clock, not a lag between
// the IMU's own sensors. Diagnostic for docs/validation/inertial.md §1b; not used by any estimator.
#include "core/math/QuaternionOps.h"

#include <vector>

namespace athlos::eval {

struct ClockOffset {
    double samples = 0.0;  // the accelerometer sample k + samples matches the optical sample k
    double rms = 0.0;      // m/s², RMS difference at the best whole-sample shift
};

// acc: accelerometer (sensor frame, m/s²); q: optical sensor→ENU orientation; pos: optical position (m);
// NaN optical samples are bridged linearly. ts: sampling interval (s).
ClockOffset imuClockOffset(const std::vector<math::Vec3>& acc, const std::vector<math::Quat>& q,
                           const std::vector<math::Vec3>& pos, double ts);

}  // namespace athlos::eval
