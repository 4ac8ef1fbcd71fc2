#include "plugins/lps/TrackGauge.h"

#include "plugins/lps/RobustStatistics.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace athlos::lps {

namespace {

constexpr double kCauchy = 2.385;   // 95 % efficiency at the normal distribution
constexpr double kMinScale = 0.02;  // m, floor of the robust scale (noise-free data)
constexpr double kInlierSigmas = 3.0;
constexpr double kMinInlierBand = 0.3;  // m
constexpr double kBin = 10.0;           // m of reference line per coverage bin

Eigen::Vector2d rotated(const Vector3& p, const Vector3& pivot, double c, double s) {
    const double x = p.x() - pivot.x(), y = p.y() - pivot.y();
    return {pivot.x() + c * x - s * y, pivot.y() + s * x + c * y};
}

}  // namespace

TrackGaugeFit fitTrackGauge(const std::vector<Vector3>& points, const Vector3& pivot, const TrackGeometry& track) {
    TrackGaugeFit fit;
    const std::size_t n = points.size();
    fit.points = int(n);
    if (n < 10) return fit;

    std::vector<double> e(n);
    std::vector<Eigen::Vector2d> jacobian(n);  // ∂e/∂(θ, d)
    std::vector<TrackQuery> queries(n);
    auto evaluate = [&](double theta, double d) {
        const double c = std::cos(theta), s = std::sin(theta);
        for (std::size_t k = 0; k < n; ++k) {
            const Eigen::Vector2d q = rotated(points[k], pivot, c, s);
            queries[k] = track.query(q);
            const double h = queries[k].heading;
            const Eigen::Vector2d right(std::sin(h), -std::cos(h));             // ∂d_track/∂q
            const Eigen::Vector2d dq(-(q.y() - pivot.y()), q.x() - pivot.x());  // ∂q/∂θ
            e[k] = queries[k].d - d;
            jacobian[k] = Eigen::Vector2d(right.dot(dq), -1.0);
        }
    };
    auto robustScale = [&]() { return std::max(kMinScale, 1.4826 * medianAbsoluteDeviation(e)); };

    double theta = 0.0, d = 0.0;
    evaluate(theta, 0.0);
    d = math::median(e);  // e = d_track here
    bool regular = true;
    for (int it = 0; it < 100; ++it) {
        evaluate(theta, d);
        const double scale = robustScale();
        Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
        Eigen::Vector2d b = Eigen::Vector2d::Zero();
        for (std::size_t k = 0; k < n; ++k) {
            const double u = e[k] / (kCauchy * scale);
            const double w = 1.0 / (1.0 + u * u);
            a += w * jacobian[k] * jacobian[k].transpose();
            b -= w * jacobian[k] * e[k];
        }
        if (a.determinant() <= 1e-12 * std::max(1.0, a.trace() * a.trace())) {
            regular = false;
            break;
        }
        const Eigen::Vector2d step = a.ldlt().solve(b);
        // Damped: θ steps beyond 0.1 rad are clipped (the fit starts from the guess-based gauge).
        const double factor = std::min(1.0, 0.1 / std::max(1e-300, std::abs(step.x())));
        theta += factor * step.x();
        d += factor * step.y();
        fit.iterations = it + 1;
        if (std::abs(step.x()) < 1e-10 && std::abs(step.y()) < 1e-8) break;
    }
    if (!regular) return fit;
    evaluate(theta, d);

    const double band = std::max(kMinInlierBand, kInlierSigmas * robustScale());
    const double length = track.referenceLength();
    const int bins = std::max(1, int(std::ceil(length / kBin)));
    std::vector<char> occupied(std::size_t(bins), 0);
    int bend1 = 0, bend2 = 0;
    double sumSq = 0.0;
    Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
    for (std::size_t k = 0; k < n; ++k) {
        if (std::abs(e[k]) > band) continue;
        ++fit.inliers;
        sumSq += e[k] * e[k];
        a += jacobian[k] * jacobian[k].transpose();
        const int bin = std::clamp(int(queries[k].s / length * bins), 0, bins - 1);
        occupied[std::size_t(bin)] = 1;
        if (queries[k].onBend) (queries[k].segment == 0 ? bend1 : bend2) += 1;
    }
    if (fit.inliers < 3 || std::abs(a.determinant()) < 1e-12) return fit;
    fit.rms = std::sqrt(sumSq / fit.inliers);
    fit.inlierShare = double(fit.inliers) / double(n);
    fit.coverage = double(std::count(occupied.begin(), occupied.end(), 1)) / bins;
    fit.bothBends = track.kind() != TrackGeometry::Kind::Oval || (bend1 >= 3 && bend2 >= 3);
    fit.rotation = theta;
    fit.lateralOffset = d;
    // Covariance of (θ, d): rms² (JᵀJ)⁻¹ over the inliers; at least 0.1 m of residual scale.
    const double sigma = std::max(fit.rms, 0.1);
    fit.sigmaRotation = sigma * std::sqrt(std::max(0.0, a.inverse()(0, 0)));
    fit.valid = std::isfinite(theta) && std::isfinite(d);
    return fit;
}

void rotateLayout(BeaconLayout& layout, double rotation) {
    const Eigen::Matrix3d r = Eigen::AngleAxisd(rotation, Vector3::UnitZ()).toRotationMatrix();
    for (auto& b : layout.positions) b = layout.reference + r * (b - layout.reference);
}

}  // namespace athlos::lps
