#pragma once
// Nelder–Mead downhill simplex minimiser (Lagarias, Reeds, Wright & Wright, "Convergence properties
// of the Nelder–Mead simplex method in low dimensions", SIAM J. Optim. 9(1), 1998 — the method behind
// MATLAB's fminsearch, which Fasel 2017 ch. 5 used for the sensor-to-joint vectors). Coefficients:
// reflection ρ = 1, expansion χ = 2, contraction γ = 1/2, shrink σ = 1/2. Derivative-free, for small
// problems (a handful of unknowns) with a cheap, possibly non-smooth cost such as a sum of norms.
#include <Eigen/Core>
#include <functional>

namespace athlos::inertial {

class NelderMead {
public:
    struct Params {
        double initialStep = 0.05;  // size of the initial simplex along each coordinate
        int maxEvaluations = 4000;
        double xTolerance = 1e-6;  // stop when every vertex is this close to the best (max norm) …
        double fTolerance = 1e-9;  // … and the values differ by less than this (relative to |f_best| + 1e-12)
    };
    struct Result {
        Eigen::VectorXd x;
        double value = 0.0;
        int evaluations = 0;
        bool converged = false;
    };
    using Cost = std::function<double(const Eigen::VectorXd&)>;

    static Result minimize(const Cost& cost, const Eigen::VectorXd& start, const Params& params);
};

}  // namespace athlos::inertial
