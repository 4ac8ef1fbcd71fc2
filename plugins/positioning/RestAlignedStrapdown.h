#pragma once
// Sacrum orientation for the anchor smoother when the orientation stream cannot be trusted in the
// turns: an accelerometer-aided filter takes the sustained centripetal acceleration of a giant-slalom
// turn (1–2 g) for gravity and tilts by several degrees, which integrates into metres of error.
// The thesis instead corrects the gyroscope offset "during a static phase before each run" (§9.2.1)
// and removes orientation drift with static phases (ch. 3–4: drift modelled as linear between two
// motionless instants). Here:
//   1. gyroscope bias = mean rate over the start rest;
//   2. the start orientation = the stream's at the end of the start rest, its tilt re-levelled with
//      the mean specific force of the rest (heading kept: the stream's magnetometer heading);
//   3. strapdown q_k = q_{k−1} ⊗ exp((ω_k − b) Δt / 2);
//   4. at the finish rest the tilt error δ (the rotation that levels the mean specific force) is
//      removed linearly in time from the end of the start rest to the start of the finish rest:
//      q_k ← exp(α_k δ / 2) ⊗ q_k, α_k ∈ [0, 1].
// Heading drift stays (the smoother's azimuth offset ψ takes the constant part).
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"

#include <vector>

namespace athlos::positioning {

struct RestAlignedStrapdown {
    // t (s), gyr (rad/s), acc (m/s², sensor frame), the stream's orientations, and the rest flags
    // (only the leading and trailing runs of 1 are used). Error when there is no start rest.
    static Expected<std::vector<math::Quat>> compute(const std::vector<double>& t, const std::vector<math::Vec3>& gyr,
                                                     const std::vector<math::Vec3>& acc,
                                                     const std::vector<math::Quat>& stream,
                                                     const std::vector<unsigned char>& startStill,
                                                     const std::vector<unsigned char>& finishStill);
};

}  // namespace athlos::positioning
