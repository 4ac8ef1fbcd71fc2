#pragma once
// Average of rotations: Markley, Cheng, Crassidis, Oshman, "Averaging Quaternions", J. Guidance,
// Control, and Dynamics 30(4), 2007. The average maximises Σ w_i (q_i · q)², i.e. it is the
// eigenvector of M = Σ w_i q_i q_iᵀ with the largest eigenvalue (eq. 12); the sign ambiguity of
// quaternions (q ≡ -q) drops out because every q_i enters twice.
#include "core/math/QuaternionOps.h"

#include <span>

namespace athlos::math {

// Weights default to 1; returns identity for an empty set. Result has w ≥ 0.
Quat markleyAverage(std::span<const Quat> quaternions, std::span<const double> weights = {});

}  // namespace athlos::math
