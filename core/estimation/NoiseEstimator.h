#pragma once
// Parameter estimation without ground truth (thesis §4.1.2): the noise parameters Θ = (Q, R, α)
// minimise the robust innovation negative log-likelihood
//   J(Θ) = Σ_{k∈M} [ log det Σ_k + g_k ],  g_k = d_k² if d_k² ≤ α, else β(Θ)            (4.13, 4.14)
//   β(Θ) = median(d²) + 1.5 · (q3(d²) − q1(d²))                                         (4.12)
// The thesis used a genetic algorithm because SQP got stuck; here a multi-start Nelder–Mead
// (OpenCV's cv::DownhillSolver) searches log-parameter space within bounds: derivative-free, robust
// to the piecewise-constant dependence on α, and deterministic for a given seed.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace athlos::estimation {

// J(Θ) of eq. 4.13 for one run: d² and log det Σ of every evaluated observation, and α.
double robustInnovationObjective(const std::vector<double>& mahalanobis2, const std::vector<double>& logDetSigma,
                                 double alpha);
// β of eq. 4.12.
double tukeyPenalty(std::vector<double> mahalanobis2);

class NoiseEstimator {
public:
    // One positive parameter (a variance or the gate α), searched as log(value) within bounds.
    struct Parameter {
        std::string name;
        double initial = 1.0;
        double lower = 1e-6;
        double upper = 1e6;
    };

    struct Params {
        int starts = 4;  // first from the initial values, the others log-uniform in the bounds
        int evaluationsPerStart = 300;
        int polishEvaluations = 300;  // a final restart from the best point (restarts help Nelder–Mead)
        double initialStep = 1.0;     // simplex size in log space (≈ factor e)
        double tolerance = 1e-4;      // relative change of the objective that stops a start
        std::uint64_t seed = 1;
    };

    struct Result {
        std::vector<double> values;  // linear scale, in the order of the parameters
        double objective = 0.0;
        int evaluations = 0;
        bool cancelled = false;
    };

    using Objective = std::function<double(const std::vector<double>& values)>;
    // Called between evaluations with the fraction done; returning false cancels.
    using ProgressFn = std::function<bool(double)>;

    NoiseEstimator(std::vector<Parameter> parameters, Params params);
    Result minimize(const Objective& objective, const ProgressFn& progress = {}) const;

private:
    std::vector<Parameter> parameters_;
    Params params_;
};

}  // namespace athlos::estimation
