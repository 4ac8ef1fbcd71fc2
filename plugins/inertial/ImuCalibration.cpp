#include "plugins/inertial/ImuCalibration.h"

#include "plugins/inertial/RestDetector.h"

#include <ceres/ceres.h>
#include <Eigen/Eigenvalues>

namespace athlos::inertial {

namespace {

struct AccResidual {
    Vec3 m;
    double g;
    template <class T>
    bool operator()(const T* offset, const T* scale, T* r) const {
        T s2 = T(0);
        for (int i = 0; i < 3; ++i) {
            const T a = (T(m[i]) - offset[i]) / scale[i];
            s2 += a * a;
        }
        r[0] = ceres::sqrt(s2) - T(g);
        return true;
    }
};

// A is parametrised by its six upper-triangular entries (a00 a01 a02 a11 a12 a22).
struct MagResidual {
    Vec3 m;
    template <class T>
    bool operator()(const T* b, const T* a, T* r) const {
        const T d0 = T(m[0]) - b[0], d1 = T(m[1]) - b[1], d2 = T(m[2]) - b[2];
        const T x = a[0] * d0 + a[1] * d1 + a[2] * d2;
        const T y = a[1] * d0 + a[3] * d1 + a[4] * d2;
        const T z = a[2] * d0 + a[4] * d1 + a[5] * d2;
        r[0] = ceres::sqrt(x * x + y * y + z * z) - T(1);  // unit sphere; rescaled afterwards
        return true;
    }
};

ceres::Solver::Options solverOptions() {
    ceres::Solver::Options o;
    o.linear_solver_type = ceres::DENSE_QR;
    o.max_num_iterations = 100;
    o.logging_type = ceres::SILENT;
    return o;
}

}  // namespace

std::optional<AccCalibration> calibrateAccelerometer(const std::vector<Vec3>& means, double gravity) {
    if (means.size() < 6) return std::nullopt;
    for (int i = 0; i < 3; ++i) {  // each axis must have seen gravity in both directions
        bool up = false, down = false;
        for (const Vec3& m : means) {
            up = up || m[i] > 0.7 * gravity;
            down = down || m[i] < -0.7 * gravity;
        }
        if (!up || !down) return std::nullopt;
    }
    double offset[3] = {0, 0, 0}, scale[3] = {1, 1, 1};
    ceres::Problem problem;
    for (const Vec3& m : means)
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<AccResidual, 1, 3, 3>(new AccResidual{m, gravity}),
                                 nullptr, offset, scale);
    ceres::Solver::Summary summary;
    ceres::Solve(solverOptions(), &problem, &summary);
    if (!summary.IsSolutionUsable()) return std::nullopt;
    AccCalibration c;
    c.offset = Vec3(offset[0], offset[1], offset[2]);
    c.scale = Vec3(scale[0], scale[1], scale[2]);
    double s = 0;
    for (const Vec3& m : means) s += std::pow(c.apply(m).norm() - gravity, 2);
    c.rms = std::sqrt(s / static_cast<double>(means.size()));
    return c;
}

std::optional<MagCalibration> calibrateMagnetometer(const std::vector<Vec3>& samples) {
    if (samples.size() < 20) return std::nullopt;
    Vec3 mean = Vec3::Zero();
    for (const Vec3& m : samples) mean += m;
    mean /= static_cast<double>(samples.size());
    double radius0 = 0;
    for (const Vec3& m : samples) radius0 += (m - mean).norm();
    radius0 /= static_cast<double>(samples.size());
    if (!(radius0 > 0)) return std::nullopt;
    // Coverage: the directions around the centre must span 3D (a ring from turning about one axis only
    // makes the ellipsoid degenerate): smallest eigenvalue of their scatter, 1/3 for a full sphere.
    Mat3 scatter = Mat3::Zero();
    for (const Vec3& m : samples) {
        const Vec3 u = (m - mean).normalized();
        scatter += u * u.transpose();
    }
    scatter /= static_cast<double>(samples.size());
    if (Eigen::SelfAdjointEigenSolver<Mat3>(scatter).eigenvalues()[0] < 0.05) return std::nullopt;
    double b[3] = {mean.x(), mean.y(), mean.z()};
    double a[6] = {1 / radius0, 0, 0, 1 / radius0, 0, 1 / radius0};
    ceres::Problem problem;
    for (const Vec3& m : samples)
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<MagResidual, 1, 3, 6>(new MagResidual{m}), nullptr, b,
                                 a);
    ceres::Solver::Summary summary;
    ceres::Solve(solverOptions(), &problem, &summary);
    if (!summary.IsSolutionUsable()) return std::nullopt;
    Mat3 A;
    A << a[0], a[1], a[2], a[1], a[3], a[4], a[2], a[4], a[5];
    const double det = A.determinant();
    if (!(det > 0)) return std::nullopt;
    MagCalibration c;
    c.hardIron = Vec3(b[0], b[1], b[2]);
    c.radius = std::cbrt(1.0 / det);  // geometric-mean radius of the fitted ellipsoid
    c.softIron = A * c.radius;
    double s = 0;
    for (const Vec3& m : samples) s += std::pow(c.apply(m).norm() - c.radius, 2);
    c.rms = std::sqrt(s / static_cast<double>(samples.size()));
    if (c.rms > 0.1 * c.radius) return std::nullopt;  // not an ellipsoid: disturbed or moving field
    return c;
}

std::vector<StaticSegment> findStaticSegments(const ImuBatch& imu, double ts, double minDuration) {
    RestDetector::Params p;
    p.minTime = minDuration;
    RestDetector rest(p, ts);
    std::vector<StaticSegment> segments;
    const auto minRows = static_cast<std::size_t>(std::ceil(minDuration / ts));
    std::size_t still = 0;  // samples in a row without a rest break
    bool open = false;
    StaticSegment current;
    auto close = [&](std::size_t end) {
        if (!open) return;
        current.end = end;
        const double n = static_cast<double>(current.end - current.begin);
        current.acc /= n;
        current.gyr /= n;
        segments.push_back(current);
        open = false;
    };
    for (std::size_t r = 0; r < imu.rows; ++r) {
        const std::size_t o = r * imu.stride;
        const Vec3 g(imu.gyr[o], imu.gyr[o + 1], imu.gyr[o + 2]), a(imu.acc[o], imu.acc[o + 1], imu.acc[o + 2]);
        rest.updateGyr(g);
        rest.updateAcc(a);
        if (!rest.isRest()) {
            close(r);
            still = 0;
            continue;
        }
        ++still;
        if (!open) {  // the detector confirms rest after minTime: the segment started then
            open = true;
            current = StaticSegment{r + 1 - std::min(still, minRows), 0, Vec3::Zero(), Vec3::Zero()};
            for (std::size_t q = current.begin; q < r; ++q) {
                const std::size_t oq = q * imu.stride;
                current.acc += Vec3(imu.acc[oq], imu.acc[oq + 1], imu.acc[oq + 2]);
                current.gyr += Vec3(imu.gyr[oq], imu.gyr[oq + 1], imu.gyr[oq + 2]);
            }
        }
        current.acc += a;
        current.gyr += g;
    }
    close(imu.rows);
    return segments;
}

Eigen::Vector3i countSaturated(const double* values, std::size_t rows, std::size_t stride, double range) {
    Eigen::Vector3i count = Eigen::Vector3i::Zero();
    for (int i = 0; i < 3; ++i) {
        double extreme = 0.0;
        if (range <= 0.0)
            for (std::size_t r = 0; r < rows; ++r) extreme = std::max(extreme, std::abs(values[r * stride + i]));
        int run = 0, flagged = 0;
        for (std::size_t r = 0; r < rows; ++r) {
            const double v = std::abs(values[r * stride + i]);
            if (range > 0.0) {
                if (v >= 0.995 * range) ++count[i];
                continue;
            }
            run = (v == extreme && extreme > 0.0) ? run + 1 : 0;
            if (run >= 3) flagged += (run == 3) ? 3 : 1;
        }
        if (range <= 0.0) count[i] = flagged;
    }
    return count;
}

}  // namespace athlos::inertial
