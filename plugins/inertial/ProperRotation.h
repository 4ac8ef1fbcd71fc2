#pragma once
// The proper rotation nearest to a 3×3 matrix in the sense of Wahba's and Kabsch's problems: R
// maximising tr(Rᵀ m) over rotations (det R = +1). DriftReduction solves one per window and, in the
// sensor-to-joint fit, one per block and cost evaluation, hence the fast Newton polar decomposition
// with the SVD as reference and fallback. Header-only so that the hot loop can inline it.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>

namespace athlos::inertial {

// The rotation R maximising tr(Rᵀ m), i.e. U diag(1, 1, det UVᵀ) Vᵀ for m = U S Vᵀ (the solution of
// Wahba's problem and of Kabsch's, Markley 1988), by SVD.
inline Eigen::Matrix3d properRotationSvd(const Eigen::Matrix3d& m) {
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d fix = Eigen::Matrix3d::Identity();
    fix(2, 2) = svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0 ? -1.0 : 1.0;
    return svd.matrixU() * fix * svd.matrixV().transpose();
}

// The same rotation as the orthogonal polar factor of m by the scaled Newton iteration
// X ← ½(γX + γ⁻¹X⁻ᵀ) (Higham 1986, "Computing the polar decomposition — with applications", SIAM J.
// Sci. Stat. Comput. 7(4), Frobenius-norm scaling γ), several times faster than a 3×3 Jacobi SVD and
// equal to it up to rounding. With det m ≤ 0 (the polar factor is then improper) or no convergence the
// SVD is used.
inline Eigen::Matrix3d properRotation(const Eigen::Matrix3d& m) {
    Eigen::Matrix3d x = m;
    const double scale2 = x.squaredNorm();
    bool scaled = true, last = false;
    for (int it = 0; it < 30; ++it) {
        // X⁻ᵀ = cof(X) / det X; the cofactor columns are cross products of X's columns.
        Eigen::Matrix3d inverseT;
        inverseT.col(0) = x.col(1).cross(x.col(2));
        inverseT.col(1) = x.col(2).cross(x.col(0));
        inverseT.col(2) = x.col(0).cross(x.col(1));
        const double det = x.col(0).dot(inverseT.col(0));
        if (it == 0 ? !(det * det > 1e-24 * scale2 * scale2 * scale2) : !(det > 0.0)) break;
        inverseT *= 1.0 / det;
        // γ = (‖X⁻¹‖_F / ‖X‖_F)^½; 1 near convergence, where the plain iteration is quadratic.
        const double gamma = scaled ? std::sqrt(std::sqrt(inverseT.squaredNorm() / x.squaredNorm())) : 1.0;
        const Eigen::Matrix3d next = 0.5 * (gamma * x + (1.0 / gamma) * inverseT);
        if (last) return next;
        const double change2 = (next - x).squaredNorm();
        x = next;
        if (it == 0 && det < 0.0) break;  // improper polar factor: the SVD handles the reflection
        if (change2 < 1e-6) scaled = false;
        // The error after a plain step is about half the square of the change before it.
        if (!scaled && change2 < 1e-16) last = true;
    }
    return properRotationSvd(m);
}

}  // namespace athlos::inertial
