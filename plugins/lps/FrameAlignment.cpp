#include "plugins/lps/FrameAlignment.h"

#include <Eigen/Dense>
#include <Eigen/SVD>
#include <cmath>

namespace athlos::lps {

Expected<RigidTransform> fitRigid(const std::vector<Vector3>& from, const std::vector<Vector3>& to, AlignMode mode,
                                  const std::vector<double>& weights) {
    const std::size_t n = from.size();
    if (n != to.size())
        return makeError(QStringLiteral("alignment: %1 source points but %2 targets").arg(n).arg(to.size()));
    const std::size_t minimum = mode == AlignMode::Full ? 3 : 2;
    if (n < minimum)
        return makeError(QStringLiteral("alignment needs at least %1 marks for %2 (got %3)")
                             .arg(minimum)
                             .arg(mode == AlignMode::Full ? "a full rotation" : "a yaw rotation")
                             .arg(n));
    auto w = [&](std::size_t k) { return weights.empty() ? 1.0 : weights[k]; };
    double total = 0.0;
    Vector3 cf = Vector3::Zero(), ct = Vector3::Zero();
    for (std::size_t k = 0; k < n; ++k) {
        cf += w(k) * from[k];
        ct += w(k) * to[k];
        total += w(k);
    }
    cf /= total;
    ct /= total;
    RigidTransform transform;
    if (mode == AlignMode::Full) {
        Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
        for (std::size_t k = 0; k < n; ++k) h += w(k) * (from[k] - cf) * (to[k] - ct).transpose();
        Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
        if (svd.singularValues()(1) < 1e-9 * std::max(1.0, svd.singularValues()(0)))
            return makeError(
                QStringLiteral("alignment: the marks are collinear; a full rotation is undetermined "
                               "(use the yaw mode or a non-collinear mark)"));
        // Kabsch: R = V diag(1, 1, det(VUᵀ)) Uᵀ excludes reflections.
        Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
        d(2, 2) = (svd.matrixV() * svd.matrixU().transpose()).determinant() < 0 ? -1.0 : 1.0;
        transform.rotation = svd.matrixV() * d * svd.matrixU().transpose();
    } else {
        double s = 0.0, c = 0.0;  // 2D Procrustes: θ = atan2(Σ p × q, Σ p · q)
        for (std::size_t k = 0; k < n; ++k) {
            const Vector3 p = from[k] - cf, q = to[k] - ct;
            s += w(k) * (p.x() * q.y() - p.y() * q.x());
            c += w(k) * (p.x() * q.x() + p.y() * q.y());
        }
        if (std::hypot(s, c) < 1e-12)
            return makeError(
                QStringLiteral("alignment: the marks coincide horizontally; the rotation is undetermined"));
        transform.rotation = Eigen::AngleAxisd(std::atan2(s, c), Vector3::UnitZ()).toRotationMatrix();
    }
    transform.translation = ct - transform.rotation * cf;
    return transform;
}

double fitYawAboutPivot(const std::vector<Vector3>& from, const std::vector<Vector3>& to, const Vector3& pivot) {
    double s = 0.0, c = 0.0;
    for (std::size_t k = 0; k < from.size() && k < to.size(); ++k) {
        const Vector3 p = from[k] - pivot, q = to[k] - pivot;
        s += p.x() * q.y() - p.y() * q.x();
        c += p.x() * q.x() + p.y() * q.y();
    }
    return std::atan2(s, c);
}

BeaconLayout transformLayout(const BeaconLayout& layout, const RigidTransform& transform) {
    BeaconLayout moved = layout;
    for (auto& p : moved.positions) p = transform.apply(p);
    moved.reference = transform.apply(layout.reference);
    return moved;
}

double alignedRmse(const std::vector<Vector3>& estimate, const std::vector<Vector3>& truth) {
    auto transform = fitRigid(estimate, truth, AlignMode::Full);
    if (!transform) return std::numeric_limits<double>::quiet_NaN();
    double sum = 0.0;
    for (std::size_t k = 0; k < estimate.size(); ++k) sum += (transform->apply(estimate[k]) - truth[k]).squaredNorm();
    return std::sqrt(sum / double(estimate.size()));
}

}  // namespace athlos::lps
