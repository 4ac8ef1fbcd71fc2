// properRotation (ProperRotation.h): the scaled Newton polar decomposition against the SVD (Kabsch)
// solution, computed here independently with Eigen's JacobiSVD, on random matrices of both determinant
// signs, near-singular ones (one or two singular values close to or exactly zero), reflections, extreme
// scales and the Kabsch problem of a rotated noisy point set.
#include "core/math/Angles.h"
#include "core/math/QuaternionOps.h"
#include "plugins/inertial/ProperRotation.h"

#include <gtest/gtest.h>

#include <random>

using namespace athlos;
using namespace athlos::inertial;
using Mat3 = Eigen::Matrix3d;

namespace {

// Kabsch / Wahba by SVD: R = U diag(1, 1, det(U Vᵀ)) Vᵀ maximises tr(Rᵀ m) over proper rotations.
Mat3 kabsch(const Mat3& m) {
    const Eigen::JacobiSVD<Mat3> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Mat3 u = svd.matrixU(), v = svd.matrixV();
    Mat3 d = Mat3::Identity();
    d(2, 2) = (u * v.transpose()).determinant() < 0.0 ? -1.0 : 1.0;
    return u * d * v.transpose();
}

Mat3 randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<double> normal;
    return math::Quat(normal(rng), normal(rng), normal(rng), normal(rng)).normalized().toRotationMatrix();
}

void expectProperRotation(const Mat3& r, const char* what) {
    EXPECT_LT((r.transpose() * r - Mat3::Identity()).norm(), 1e-12) << what;
    EXPECT_NEAR(r.determinant(), 1.0, 1e-12) << what;
}

// m = U diag(s) Vᵀ with random U, V and det(U Vᵀ) = sign.
Mat3 withSingularValues(std::mt19937_64& rng, const Eigen::Vector3d& s, double sign) {
    Mat3 u = randomRotation(rng);
    const Mat3 v = randomRotation(rng);
    if (sign < 0.0) u.col(2) = -u.col(2);
    return u * s.asDiagonal() * v.transpose();
}

}  // namespace

TEST(ProperRotation, EqualsTheSvdSolutionOnRandomMatrices) {
    std::mt19937_64 rng(11);
    std::normal_distribution<double> normal;
    int negative = 0;
    for (int i = 0; i < 2000; ++i) {
        Mat3 m;
        for (int k = 0; k < 9; ++k) m(k / 3, k % 3) = normal(rng);
        negative += m.determinant() < 0.0;
        const Mat3 r = properRotation(m), ref = kabsch(m);
        expectProperRotation(r, "random");
        EXPECT_LT((r - ref).norm(), 1e-9) << "matrix " << i << "\n" << m;
    }
    EXPECT_GT(negative, 500);  // both determinant signs were exercised
}

TEST(ProperRotation, ReflectionsGiveTheBestProperRotation) {
    std::mt19937_64 rng(12);
    for (int i = 0; i < 500; ++i) {
        // A rotation times a reflection (det m < 0): the polar factor is improper, the answer must not be.
        const Mat3 reflection = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
        const Mat3 m = randomRotation(rng) * reflection * withSingularValues(rng, {3.0, 2.0, 1.0}, 1.0);
        const Mat3 r = properRotation(m), ref = kabsch(m);
        expectProperRotation(r, "reflection");
        EXPECT_LT((r - ref).norm(), 1e-9) << "matrix " << i;
        EXPECT_NEAR((r.transpose() * m).trace(), (ref.transpose() * m).trace(), 1e-9);
    }
    // A pure reflection of a rotation: the nearest rotation turns the reflected axis by π.
    const Mat3 m = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
    const Mat3 r = properRotation(m);
    expectProperRotation(r, "diag(1, 1, -1)");
    EXPECT_NEAR((r.transpose() * m).trace(), 1.0, 1e-12);  // the best attainable: 1 + 1 − 1
}

TEST(ProperRotation, NearSingularAndSingularMatrices) {
    std::mt19937_64 rng(13);
    for (const double eps : {1e-2, 1e-4, 1e-8, 1e-12, 0.0})
        for (const double sign : {1.0, -1.0})
            for (int i = 0; i < 100; ++i) {
                // Rank two (one singular value ≈ 0): the solution is still unique.
                const Mat3 m = withSingularValues(rng, {2.0, 0.7, eps}, sign);
                const Mat3 r = properRotation(m), ref = kabsch(m);
                expectProperRotation(r, "rank two");
                EXPECT_LT((r - ref).norm(), 1e-7) << "eps " << eps << " sign " << sign;
                // Rank one (all vectors parallel, e.g. gravity only): the rotation about them is free, so
                // only the attained objective is unique.
                const Mat3 m1 = withSingularValues(rng, {1.5, eps, eps}, sign);
                const Mat3 r1 = properRotation(m1), ref1 = kabsch(m1);
                expectProperRotation(r1, "rank one");
                EXPECT_NEAR((r1.transpose() * m1).trace(), (ref1.transpose() * m1).trace(), 1e-9)
                    << "eps " << eps << " sign " << sign;
            }
    // The zero matrix: any rotation is optimal; the result must still be one.
    expectProperRotation(properRotation(Mat3::Zero()), "zero");
}

TEST(ProperRotation, ScaleInvariantAndExactOnRotations) {
    std::mt19937_64 rng(14);
    for (int i = 0; i < 200; ++i) {
        const Mat3 rot = randomRotation(rng);
        EXPECT_LT((properRotation(rot) - rot).norm(), 1e-12);
        const Mat3 m = withSingularValues(rng, {5.0, 1.0, 0.2}, i % 2 == 0 ? 1.0 : -1.0);
        const Mat3 ref = kabsch(m);
        for (const double scale : {1e-8, 1e-3, 1e3, 1e8}) EXPECT_LT((properRotation(scale * m) - ref).norm(), 1e-9);
    }
}

TEST(ProperRotation, SolvesKabschForARotatedNoisyPointSet) {
    std::mt19937_64 rng(15);
    std::normal_distribution<double> normal;
    const Mat3 truth = randomRotation(rng);
    Mat3 h = Mat3::Zero();  // Σ to fromᵀ
    for (int i = 0; i < 200; ++i) {
        const Eigen::Vector3d from(normal(rng), normal(rng), normal(rng));
        const Eigen::Vector3d to = truth * from + 0.01 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
        h += to * from.transpose();
    }
    const Mat3 r = properRotation(h);
    EXPECT_LT((r - kabsch(h)).norm(), 1e-9);
    EXPECT_LT(Eigen::AngleAxisd(r * truth.transpose()).angle(), 0.2 * math::kDeg);
}
