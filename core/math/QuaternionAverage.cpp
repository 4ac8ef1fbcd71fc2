#include "core/math/QuaternionAverage.h"

#include <Eigen/Eigenvalues>

namespace athlos::math {

Quat markleyAverage(std::span<const Quat> quaternions, std::span<const double> weights) {
    if (quaternions.empty()) return Quat::Identity();
    Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
    for (std::size_t i = 0; i < quaternions.size(); ++i) {
        const Vec4 q = wxyz(quaternions[i].normalized());
        const double w = weights.empty() ? 1.0 : weights[i];
        m.noalias() += w * q * q.transpose();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(m);
    const Vec4 v = solver.eigenvectors().col(3);  // eigenvalues ascending: the last is the largest
    return canonical(quatFromWxyz(v).normalized());
}

}  // namespace athlos::math
