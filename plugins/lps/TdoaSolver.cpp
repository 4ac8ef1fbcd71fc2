#include "plugins/lps/TdoaSolver.h"

#include <ceres/ceres.h>
#include <ceres/tiny_solver.h>

#include <Eigen/Dense>
#include <cmath>

namespace athlos::lps {

void FixInput::assign(const TdoaEpoch& epoch, const BeaconLayout& layout,
                      const std::vector<double>& referenceDistance) {
    t = epoch.t;
    const auto n = epoch.readings.size();
    beacons.resize(n);
    ranges.resize(n);
    weights.assign(n, 1.0);
    index.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const int i = epoch.readings[k].beacon;
        index[k] = i;
        beacons[k] = layout.positions[size_t(i)];
        ranges[k] = kSpeedOfLight * epoch.readings[k].dt + referenceDistance[size_t(i)];
    }
}

int FixInput::activeCount() const {
    int n = 0;
    for (double w : weights) n += w > 0.0;
    return n;
}

std::vector<double> referenceDistances(const BeaconLayout& layout) {
    std::vector<double> d(size_t(layout.size()));
    for (int i = 0; i < layout.size(); ++i) d[size_t(i)] = (layout.positions[size_t(i)] - layout.reference).norm();
    return d;
}

namespace {

// Residual vector √w_i·e_i and its Jacobian for TinySolver; x = [x y o] (planar) or [x y z o].
template <int P>
struct TdoaCost {
    using Scalar = double;
    enum { NUM_RESIDUALS = Eigen::Dynamic, NUM_PARAMETERS = P };

    const FixInput* input = nullptr;
    double height = 0.0;
    const double* sqrtW = nullptr;

    int NumResiduals() const { return input->size(); }
    bool operator()(const double* x, double* residuals, double* jacobian) const {
        const Vector3 m(x[0], x[1], P == 3 ? height : x[2]);
        const double o = x[P - 1];
        const int n = input->size();
        for (int i = 0; i < n; ++i) {
            const Vector3 d = m - input->beacons[size_t(i)];
            const double range = d.norm();
            const double s = sqrtW[i];
            residuals[i] = s * (range - input->ranges[size_t(i)] - o);
            if (jacobian) {
                // ∂e/∂m = (m − b)ᵀ/|m − b|, ∂e/∂o = −1 (column-major n × P)
                const double inv = range > 1e-9 ? s / range : 0.0;
                jacobian[i] = d.x() * inv;
                jacobian[i + n] = d.y() * inv;
                if constexpr (P == 4) jacobian[i + 2 * n] = d.z() * inv;
                jacobian[i + (P - 1) * n] = -s;
            }
        }
        return true;
    }
};

// One reading for a ceres::Problem (robust-loss backend), analytic derivatives.
template <int P>
class TdoaReadingCost final : public ceres::SizedCostFunction<1, P> {
public:
    TdoaReadingCost(const Vector3& beacon, double range, double sqrtW, double height)
        : beacon_(beacon), range_(range), sqrtW_(sqrtW), height_(height) {}
    bool Evaluate(const double* const* parameters, double* residuals, double** jacobians) const override {
        const double* x = parameters[0];
        const Vector3 d = Vector3(x[0], x[1], P == 3 ? height_ : x[2]) - beacon_;
        const double range = d.norm();
        residuals[0] = sqrtW_ * (range - range_ - x[P - 1]);
        if (jacobians && jacobians[0]) {
            const double inv = range > 1e-9 ? sqrtW_ / range : 0.0;
            jacobians[0][0] = d.x() * inv;
            jacobians[0][1] = d.y() * inv;
            if constexpr (P == 4) jacobians[0][2] = d.z() * inv;
            jacobians[0][P - 1] = -sqrtW_;
        }
        return true;
    }

private:
    Vector3 beacon_;
    double range_, sqrtW_, height_;
};

}  // namespace

struct TdoaSolver::Tiny {
    ceres::TinySolver<TdoaCost<3>> planar;
    ceres::TinySolver<TdoaCost<4>> spatial;
    std::vector<double> sqrtW;
};

TdoaSolver::TdoaSolver(const Params& params) : params_(params), tiny_(std::make_unique<Tiny>()) {
    // Tight tolerances: a noise-free fix must reproduce the position to well below a micrometre.
    auto configure = [&](auto& options) {
        options.max_num_iterations = params_.maxIterations;
        options.parameter_tolerance = 1e-12;
        options.function_tolerance = 1e-16;
        options.gradient_tolerance = 1e-14;
    };
    configure(tiny_->planar.options);
    configure(tiny_->spatial.options);
}

TdoaSolver::TdoaSolver() : TdoaSolver(Params()) {}
TdoaSolver::~TdoaSolver() = default;
TdoaSolver::TdoaSolver(TdoaSolver&&) noexcept = default;
TdoaSolver& TdoaSolver::operator=(TdoaSolver&&) noexcept = default;

void TdoaSolver::residuals(const FixInput& input, const Vector3& m, double offset, std::vector<double>& e) {
    e.resize(input.ranges.size());
    for (std::size_t i = 0; i < e.size(); ++i) e[i] = (m - input.beacons[i]).norm() - input.ranges[i] - offset;
}

double TdoaSolver::weightedRms(const FixInput& input, const std::vector<double>& e) {
    double sum = 0.0, weight = 0.0;
    for (std::size_t i = 0; i < e.size(); ++i) {
        sum += input.weights[i] * e[i] * e[i];
        weight += input.weights[i];
    }
    return weight > 0.0 ? std::sqrt(sum / weight) : std::numeric_limits<double>::quiet_NaN();
}

std::optional<TagFix> TdoaSolver::linearStart(const FixInput& input) const {
    const bool planar = params_.geometry == Geometry::Planar;
    const int p = unknowns();
    int k = -1;
    for (int i = 0; i < input.size() && k < 0; ++i)
        if (input.weights[size_t(i)] > 0.0) k = i;
    if (k < 0 || input.activeCount() < p + 1) return std::nullopt;
    // Normal equations of the differenced system, accumulated at fixed size (4×4 covers both modes).
    Eigen::Matrix4d ata = Eigen::Matrix4d::Zero();
    Eigen::Vector4d atb = Eigen::Vector4d::Zero();
    const Vector3& bk = input.beacons[size_t(k)];
    const double yk = input.ranges[size_t(k)];
    for (int i = 0; i < input.size(); ++i) {
        const double w = input.weights[size_t(i)];
        if (i == k || w <= 0.0) continue;
        const Vector3& bi = input.beacons[size_t(i)];
        const double yi = input.ranges[size_t(i)];
        const Vector3 db = bi - bk;
        Eigen::Vector4d row = Eigen::Vector4d::Zero();
        double rhs = yi * yi - yk * yk - bi.squaredNorm() + bk.squaredNorm();
        row(0) = -2.0 * db.x();
        row(1) = -2.0 * db.y();
        if (planar) {
            rhs += 2.0 * db.z() * params_.tagHeight;
            row(2) = -2.0 * (yi - yk);
        } else {
            row(2) = -2.0 * db.z();
            row(3) = -2.0 * (yi - yk);
        }
        ata += w * row * row.transpose();
        atb += w * rhs * row;
    }
    if (planar) ata(3, 3) = 1.0;  // unused unknown
    const Eigen::Vector4d x = ata.ldlt().solve(atb);
    if (!x.allFinite()) return std::nullopt;
    TagFix fix;
    fix.t = input.t;
    fix.position = planar ? Vector3(x(0), x(1), params_.tagHeight) : Vector3(x(0), x(1), x(2));
    fix.offset = planar ? x(2) : x(3);
    return fix;
}

TagFix TdoaSolver::finish(const FixInput& input, const Vector3& m, double offset) {
    TagFix fix;
    fix.t = input.t;
    fix.position = m;
    fix.offset = offset;
    residuals(input, m, offset, scratch_);
    fix.rmsResidual = weightedRms(input, scratch_);
    fix.beaconsUsed = input.activeCount();
    // Far outside any venue means the solver ran off (degenerate geometry or wrong branch).
    fix.valid = m.allFinite() && std::isfinite(offset) && std::isfinite(fix.rmsResidual) && plausible(input, m);
    return fix;
}

bool TdoaSolver::plausible(const FixInput& input, const Vector3& m) const {
    Vector2 centre = Vector2::Zero();
    for (const auto& b : input.beacons) centre += b.head<2>();
    centre /= double(input.beacons.size());
    double radius = 0.0;
    for (const auto& b : input.beacons) radius = std::max(radius, (b.head<2>() - centre).norm());
    return (m.head<2>() - centre).norm() <= params_.maxSpread * std::max(radius, 1.0);
}

TagFix TdoaSolver::solveTiny(const FixInput& input, const TagFix& start) {
    auto& sqrtW = tiny_->sqrtW;
    sqrtW.resize(input.weights.size());
    for (std::size_t i = 0; i < sqrtW.size(); ++i) sqrtW[i] = std::sqrt(std::max(0.0, input.weights[i]));
    if (params_.geometry == Geometry::Planar) {
        TdoaCost<3> cost{&input, params_.tagHeight, sqrtW.data()};
        Eigen::Vector3d x(start.position.x(), start.position.y(), start.offset);
        tiny_->planar.Solve(cost, &x);
        return finish(input, Vector3(x(0), x(1), params_.tagHeight), x(2));
    }
    TdoaCost<4> cost{&input, 0.0, sqrtW.data()};
    Eigen::Vector4d x(start.position.x(), start.position.y(), start.position.z(), start.offset);
    tiny_->spatial.Solve(cost, &x);
    return finish(input, Vector3(x(0), x(1), x(2)), x(3));
}

TagFix TdoaSolver::solveCeres(const FixInput& input, const TagFix& start) const {
    ceres::Problem::Options problemOptions;
    problemOptions.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problemOptions);
    std::unique_ptr<ceres::LossFunction> loss;
    if (params_.loss == Loss::Huber) loss = std::make_unique<ceres::HuberLoss>(params_.lossScale);
    if (params_.loss == Loss::Cauchy) loss = std::make_unique<ceres::CauchyLoss>(params_.lossScale);
    const bool planar = params_.geometry == Geometry::Planar;
    Eigen::Vector4d x(start.position.x(), start.position.y(), planar ? start.offset : start.position.z(), start.offset);
    for (int i = 0; i < input.size(); ++i) {
        const double w = input.weights[size_t(i)];
        if (w <= 0.0) continue;
        const double s = std::sqrt(w);
        ceres::CostFunction* cost =
            planar ? static_cast<ceres::CostFunction*>(new TdoaReadingCost<3>(
                         input.beacons[size_t(i)], input.ranges[size_t(i)], s, params_.tagHeight))
                   : new TdoaReadingCost<4>(input.beacons[size_t(i)], input.ranges[size_t(i)], s, 0.0);
        problem.AddResidualBlock(cost, loss.get(), x.data());
    }
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = params_.maxIterations;
    options.function_tolerance = 1e-12;
    options.parameter_tolerance = 1e-12;
    options.logging_type = ceres::SILENT;
    options.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    auto* self = const_cast<TdoaSolver*>(this);  // finish() only reuses scratch storage
    return planar ? self->finish(input, Vector3(x(0), x(1), params_.tagHeight), x(2))
                  : self->finish(input, Vector3(x(0), x(1), x(2)), x(3));
}

TagFix TdoaSolver::solve(const FixInput& input, const TagFix* start) {
    if (input.activeCount() < unknowns()) {
        TagFix fix;
        fix.t = input.t;
        fix.beaconsUsed = input.activeCount();
        return fix;
    }
    auto run = [&](const TagFix& s) { return params_.loss == Loss::None ? solveTiny(input, s) : solveCeres(input, s); };
    std::optional<TagFix> closedForm;
    TagFix initial;
    if (start && start->valid) {
        initial = *start;
        if (params_.geometry == Geometry::Planar) initial.position.z() = params_.tagHeight;
    } else {
        closedForm = linearStart(input);
        if (closedForm) {
            initial = *closedForm;
        } else {  // centroid of the beacons at tag height, offset from the mean residual
            Vector3 c = Vector3::Zero();
            for (const auto& b : input.beacons) c += b;
            initial.position = c / double(input.size());
            initial.position.z() = params_.tagHeight;
        }
    }
    TagFix fix = run(initial);
    if (start && start->valid && (!fix.valid || fix.rmsResidual > params_.retryResidual)) {
        if (auto s = linearStart(input)) {
            const TagFix second = run(*s);
            if (second.valid && (!fix.valid || second.rmsResidual < fix.rmsResidual)) fix = second;
        }
    }
    return fix;
}

}  // namespace athlos::lps
