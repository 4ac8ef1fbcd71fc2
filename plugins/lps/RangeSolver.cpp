#include "plugins/lps/RangeSolver.h"

#include "core/math/Statistics.h"

#include <ceres/tiny_solver.h>

#include <Eigen/Dense>
#include <cmath>

namespace athlos::lps {

void RangeFixInput::assign(const TdoaEpoch& epoch, const BeaconLayout& layout) {
    t = epoch.t;
    const auto n = epoch.readings.size();
    beacons.resize(n);
    ranges.resize(n);
    weights.assign(n, 1.0);
    index.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        index[k] = epoch.readings[k].beacon;
        beacons[k] = layout.positions[std::size_t(index[k])];
        ranges[k] = epoch.readings[k].dt;
    }
}

namespace {

// √w_i (|m − b_i| − d_i) and its Jacobian; x = [x y] (planar, z = height) or [x y z].
template <int P>
struct RangeCost {
    using Scalar = double;
    enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = P };
    const RangeFixInput* input = nullptr;
    double height = 0.0;

    int NumResiduals() const { return input->size(); }
    bool operator()(const double* x, double* residuals, double* jacobian) const {
        const Vector3 m(x[0], x[1], P == 2 ? height : x[2]);
        const int n = input->size();
        for (int i = 0; i < n; ++i) {
            const Vector3 d = m - input->beacons[std::size_t(i)];
            const double range = d.norm();
            const double s = std::sqrt(input->weights[std::size_t(i)]);
            residuals[i] = s * (range - input->ranges[std::size_t(i)]);
            if (jacobian) {
                const double inv = range > 1e-9 ? s / range : 0.0;
                jacobian[i] = d.x() * inv;
                jacobian[i + n] = d.y() * inv;
                if constexpr (P == 3) jacobian[i + 2 * n] = d.z() * inv;
            }
        }
        return true;
    }
};

}  // namespace

struct RangeSolver::Tiny {
    ceres::TinySolver<RangeCost<2>> planar;
    ceres::TinySolver<RangeCost<3>> spatial;
};

RangeSolver::RangeSolver(const Params& params) : params_(params), tiny_(std::make_unique<Tiny>()) {
    auto configure = [&](auto& options) {
        options.max_num_iterations = params_.maxIterations;
        options.parameter_tolerance = 1e-12;
        options.function_tolerance = 1e-16;
        options.gradient_tolerance = 1e-14;
    };
    configure(tiny_->planar.options);
    configure(tiny_->spatial.options);
}
RangeSolver::RangeSolver() : RangeSolver(Params()) {}
RangeSolver::~RangeSolver() = default;
RangeSolver::RangeSolver(RangeSolver&&) noexcept = default;
RangeSolver& RangeSolver::operator=(RangeSolver&&) noexcept = default;

std::optional<Vector3> RangeSolver::linearStart(const RangeFixInput& input) const {
    // 2 (b_i − b_0)ᵀ m = |b_i|² − |b_0|² − d_i² + d_0²; planar: z fixed, its terms move to the right.
    const bool planar = params_.geometry == Geometry::Planar;
    const int n = input.size(), p = planar ? 2 : 3;
    if (n < p + 1) return std::nullopt;
    Eigen::MatrixXd A(n - 1, p);
    Eigen::VectorXd b(n - 1);
    const Vector3& b0 = input.beacons[0];
    for (int i = 1; i < n; ++i) {
        const Vector3& bi = input.beacons[std::size_t(i)];
        const Vector3 g = 2.0 * (bi - b0);
        double rhs = bi.squaredNorm() - b0.squaredNorm() - input.ranges[std::size_t(i)] * input.ranges[std::size_t(i)] +
                     input.ranges[0] * input.ranges[0];
        if (planar) rhs -= g.z() * params_.tagHeight;
        A.row(i - 1) = g.head(p).transpose();
        b(i - 1) = rhs;
    }
    const Eigen::VectorXd m = A.completeOrthogonalDecomposition().solve(b);
    if (!m.allFinite()) return std::nullopt;
    return Vector3(m(0), m(1), planar ? params_.tagHeight : m(2));
}

TagFix RangeSolver::solveWeighted(const RangeFixInput& input, const Vector3& start) {
    TagFix fix;
    fix.t = input.t;
    if (params_.geometry == Geometry::Planar) {
        RangeCost<2> cost{&input, params_.tagHeight};
        Eigen::Vector2d x = start.head<2>();
        tiny_->planar.Solve(cost, &x);
        fix.position = Vector3(x.x(), x.y(), params_.tagHeight);
    } else {
        RangeCost<3> cost{&input, 0.0};
        Eigen::Vector3d x = start;
        tiny_->spatial.Solve(cost, &x);
        fix.position = x;
    }
    double sum = 0.0, weight = 0.0;
    for (int i = 0; i < input.size(); ++i) {
        const double e = (fix.position - input.beacons[std::size_t(i)]).norm() - input.ranges[std::size_t(i)];
        sum += input.weights[std::size_t(i)] * e * e;
        weight += input.weights[std::size_t(i)];
    }
    fix.rmsResidual = weight > 0 ? std::sqrt(sum / weight) : 0.0;
    fix.valid = fix.position.allFinite();
    return fix;
}

TagFix RangeSolver::solve(RangeFixInput input, const TagFix* start) {
    TagFix invalid;
    invalid.t = input.t;
    if (input.size() < unknowns() + 1) return invalid;
    std::optional<Vector3> initial;
    if (start && start->valid) initial = start->position;
    if (!initial) initial = linearStart(input);
    if (!initial) return invalid;
    input.weights.assign(std::size_t(input.size()), 1.0);
    TagFix fix = solveWeighted(input, *initial);
    // A warm start can sit in the mirror minimum of a compact anchor group: retry from the closed form.
    if (start && fix.rmsResidual > params_.maxResidual)
        if (auto linear = linearStart(input)) {
            const TagFix again = solveWeighted(input, *linear);
            if (again.valid && again.rmsResidual < fix.rmsResidual) fix = again;
        }
    if (params_.selection == Selection::Irls) {
        // Tukey's bisquare, ψ(u) = u (1 − u²)², w = (1 − u²)² for |u| < 1, u = e / (k·1.4826·MAD).
        for (int iteration = 0; iteration < params_.irlsIterations && fix.valid; ++iteration) {
            std::vector<double> e(std::size_t(input.size())), absE;
            for (int i = 0; i < input.size(); ++i) {
                e[std::size_t(i)] =
                    (fix.position - input.beacons[std::size_t(i)]).norm() - input.ranges[std::size_t(i)];
                absE.push_back(std::abs(e[std::size_t(i)]));
            }
            const double scale = std::max(1.4826 * math::median(absE), params_.irlsMinScale) * params_.irlsK;
            int active = 0;
            for (int i = 0; i < input.size(); ++i) {
                const double u = e[std::size_t(i)] / scale;
                input.weights[std::size_t(i)] = std::abs(u) < 1.0 ? std::pow(1.0 - u * u, 2) : 0.0;
                active += input.weights[std::size_t(i)] > 0.0;
            }
            if (active < unknowns() + 1) break;
            fix = solveWeighted(input, fix.position);
        }
    }
    fix.beaconsUsed = 0;
    for (double w : input.weights) fix.beaconsUsed += w >= 0.5;
    fix.offset = 0.0;
    if (!fix.valid || fix.rmsResidual > params_.maxResidual) fix.valid = false;
    return fix;
}

}  // namespace athlos::lps
