#include "core/estimation/NoiseEstimator.h"

#include <opencv2/core/optim.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace athlos::estimation {

namespace {

double quantile(std::vector<double>& sorted, double q) {
    // Linear interpolation between order statistics (type 7, as numpy/R default).
    const double pos = q * double(sorted.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(pos));
    const std::size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (pos - double(lo)) * (sorted[hi] - sorted[lo]);
}

struct Cancelled {};

// Adapts the objective to OpenCV's solver: log-space parameters, bounds by clamping plus a
// quadratic penalty (keeps the simplex from wandering off along flat directions).
class LogSpaceFunction : public cv::MinProblemSolver::Function {
public:
    LogSpaceFunction(const std::vector<NoiseEstimator::Parameter>& parameters,
                     const NoiseEstimator::Objective& objective, const std::function<bool()>& tick)
        : parameters_(parameters), objective_(objective), tick_(tick) {}

    int getDims() const override { return static_cast<int>(parameters_.size()); }

    double calc(const double* z) const override {
        if (tick_ && !tick_()) throw Cancelled{};
        std::vector<double> values(parameters_.size());
        double penalty = 0.0;
        for (std::size_t i = 0; i < parameters_.size(); ++i) {
            const double lo = std::log(parameters_[i].lower), hi = std::log(parameters_[i].upper);
            const double c = std::clamp(z[i], lo, hi);
            penalty += 1e3 * (z[i] - c) * (z[i] - c);
            values[i] = std::exp(c);
        }
        const double f = objective_(values);
        return std::isfinite(f) ? f + penalty : std::numeric_limits<double>::max() / 4;
    }

private:
    const std::vector<NoiseEstimator::Parameter>& parameters_;
    const NoiseEstimator::Objective& objective_;
    const std::function<bool()>& tick_;
};

}  // namespace

double tukeyPenalty(std::vector<double> d2) {
    if (d2.empty()) return 0.0;
    std::sort(d2.begin(), d2.end());
    const double q1 = quantile(d2, 0.25), median = quantile(d2, 0.5), q3 = quantile(d2, 0.75);
    return median + 1.5 * (q3 - q1);  // eq. 4.12
}

double robustInnovationObjective(const std::vector<double>& d2, const std::vector<double>& logDetSigma, double alpha) {
    const double beta = tukeyPenalty(d2);
    double sum = 0.0;
    for (std::size_t k = 0; k < d2.size(); ++k) sum += logDetSigma[k] + (d2[k] <= alpha ? d2[k] : beta);  // 4.13/4.14
    return sum;
}

NoiseEstimator::NoiseEstimator(std::vector<Parameter> parameters, Params params)
    : parameters_(std::move(parameters)), params_(params) {}

NoiseEstimator::Result NoiseEstimator::minimize(const Objective& objective, const ProgressFn& progress) const {
    const int dims = static_cast<int>(parameters_.size());
    const int budget = params_.starts * params_.evaluationsPerStart + params_.polishEvaluations;
    Result best;
    best.objective = std::numeric_limits<double>::infinity();
    int evaluations = 0;
    std::function<bool()> tick = [&] {
        ++evaluations;
        return !progress || (evaluations % 16 != 0) || progress(std::min(1.0, double(evaluations) / budget));
    };
    LogSpaceFunction function(parameters_, objective, tick);
    std::mt19937_64 rng(params_.seed);

    std::vector<double> bestZ(dims);
    for (int i = 0; i < dims; ++i)
        bestZ[i] = std::log(std::clamp(parameters_[i].initial, parameters_[i].lower, parameters_[i].upper));
    double bestF = std::numeric_limits<double>::infinity();

    auto runFrom = [&](std::vector<double> z, int maxEvaluations, double step) {
        cv::Ptr<cv::DownhillSolver> solver = cv::DownhillSolver::create();
        solver->setFunction(cv::makePtr<LogSpaceFunction>(function));
        solver->setInitStep(cv::Mat(1, dims, CV_64F, cv::Scalar(step)));
        solver->setTermCriteria(
            cv::TermCriteria(cv::TermCriteria::MAX_ITER + cv::TermCriteria::EPS, maxEvaluations, params_.tolerance));
        cv::Mat x(1, dims, CV_64F, z.data());
        const double f = solver->minimize(x);
        if (f < bestF) {
            bestF = f;
            for (int i = 0; i < dims; ++i) bestZ[i] = x.at<double>(0, i);
        }
    };

    try {
        const std::vector<double> initial = bestZ;
        for (int s = 0; s < params_.starts; ++s) {
            std::vector<double> z = initial;
            if (s > 0)
                for (int i = 0; i < dims; ++i) {
                    std::uniform_real_distribution<double> u(std::log(parameters_[i].lower),
                                                             std::log(parameters_[i].upper));
                    // Half the starts near the initial guess (within e^±2), half anywhere in the bounds.
                    z[i] = s % 2 ? std::clamp(initial[i] + std::uniform_real_distribution<double>(-2, 2)(rng),
                                              std::log(parameters_[i].lower), std::log(parameters_[i].upper))
                                 : u(rng);
                }
            runFrom(z, params_.evaluationsPerStart, params_.initialStep);
        }
        if (params_.polishEvaluations > 0) runFrom(bestZ, params_.polishEvaluations, 0.3 * params_.initialStep);
    } catch (const Cancelled&) {
        best.cancelled = true;
    }
    best.values.resize(dims);
    for (int i = 0; i < dims; ++i)
        best.values[i] = std::exp(std::clamp(bestZ[i], std::log(parameters_[i].lower), std::log(parameters_[i].upper)));
    best.objective = bestF;
    best.evaluations = evaluations;
    return best;
}

}  // namespace athlos::estimation
