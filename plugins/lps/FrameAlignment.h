#pragma once
// Rigid frame alignment (thesis §3.1.2 step 9 and the evaluation's Kabsch alignment [Kabs 76]).
//   Full: Kabsch — rotation R and translation t minimising Σ w_k |R p_k + t − q_k|² (≥ 3 marks,
//         not collinear).
//   Yaw:  rotation about the vertical axis only (the LPS frame stays levelled), translation in
//         x, y, z; two marks suffice. The venue case: "home straight along x, origin at the finish".
#include "core/util/Expected.h"
#include "plugins/lps/Tdoa.h"

#include <Eigen/Core>

namespace athlos::lps {

struct RigidTransform {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Vector3 translation = Vector3::Zero();

    Vector3 apply(const Vector3& p) const { return rotation * p + translation; }
};

enum class AlignMode { Yaw, Full };

// Least-squares transform mapping from[k] onto to[k]; weights optional (default equal).
Expected<RigidTransform> fitRigid(const std::vector<Vector3>& from, const std::vector<Vector3>& to, AlignMode mode,
                                  const std::vector<double>& weights = {});

// Rotation angle about the vertical axis through pivot that best maps from onto to (xy only).
double fitYawAboutPivot(const std::vector<Vector3>& from, const std::vector<Vector3>& to, const Vector3& pivot);

// Beacons and reference node moved by the transform.
BeaconLayout transformLayout(const BeaconLayout& layout, const RigidTransform& transform);

// RMS distance between matched point sets after a Full alignment of `estimate` onto `truth`.
double alignedRmse(const std::vector<Vector3>& estimate, const std::vector<Vector3>& truth);

}  // namespace athlos::lps
