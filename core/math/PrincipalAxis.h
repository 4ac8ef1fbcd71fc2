#pragma once
// Principal axis of a set of 3-vectors about the origin (PCA without centring), from their second
// moment M = Σ v vᵀ: the eigenvector of M's largest eigenvalue λ₁ and its share λ₁ / (λ₁ + λ₂ + λ₃) of
// the energy. Used for rotation axes from angular velocity (a back-and-forth rotation has a near-zero
// mean, so the moment, not the covariance): segment and functional calibration, the foot's
// medio-lateral axis. The axis has no sign; a zero moment gives share 0 and the fallback axis.
#include <Eigen/Eigenvalues>

namespace athlos::math {

struct PrincipalAxis {
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    double share = 0.0;  // λ₁ / (λ₁ + λ₂ + λ₃), 0 when M = 0
};

inline PrincipalAxis principalAxisOfMoment(const Eigen::Matrix3d& moment,
                                           const Eigen::Vector3d& fallback = Eigen::Vector3d::UnitZ()) {
    PrincipalAxis p;
    p.axis = fallback;
    const double trace = moment.trace();
    if (!(trace > 0.0)) return p;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(moment);  // eigenvalues ascending
    p.axis = pca.eigenvectors().col(2);
    p.share = pca.eigenvalues()[2] / pca.eigenvalues().sum();
    return p;
}

}  // namespace athlos::math
