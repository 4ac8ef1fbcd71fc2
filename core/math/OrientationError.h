#pragma once
// Orientation error metrics of the BROAD benchmark (Laidig et al., Data 2021; shared/data/README.md):
// error quaternion in the earth frame e = q_est ⊗ q_ref*, split into
//   total       = 2·acos(clip(|e_w|, 0, 1))
//   heading     = 2·atan(|e_z / e_w|)
//   inclination = 2·acos(clip(sqrt(e_w² + e_z²), 0, 1)).
// A 9D estimate is judged on total, a 6D one (arbitrary heading) on inclination.
#include "core/math/QuaternionOps.h"

#include <span>

namespace athlos::math {

struct OrientationErrors {
    double total = 0.0;        // rad
    double heading = 0.0;      // rad
    double inclination = 0.0;  // rad
};

OrientationErrors orientationError(const Quat& estimate, const Quat& reference);

struct ErrorRms {
    double total = 0.0;  // deg, RMS over the counted samples
    double heading = 0.0;
    double inclination = 0.0;
    long long count = 0;  // samples counted (mask true, both quaternions finite)
};

// RMS in degrees over samples where mask is true (empty mask = all); samples with a non-finite
// quaternion on either side (optical dropouts) are skipped.
ErrorRms orientationErrorRms(std::span<const Quat> estimate, std::span<const Quat> reference,
                             std::span<const bool> mask = {});

}  // namespace athlos::math
