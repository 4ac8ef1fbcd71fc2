#include "plugins/inertial/NelderMead.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace athlos::inertial {

NelderMead::Result NelderMead::minimize(const Cost& cost, const Eigen::VectorXd& start, const Params& params) {
    const auto n = static_cast<int>(start.size());
    std::vector<Eigen::VectorXd> x(static_cast<std::size_t>(n + 1), start);
    std::vector<double> f(static_cast<std::size_t>(n + 1));
    Result result;
    const auto eval = [&](const Eigen::VectorXd& p) {
        ++result.evaluations;
        const double v = cost(p);
        return std::isfinite(v) ? v : std::numeric_limits<double>::infinity();
    };
    for (int i = 0; i < n; ++i) x[static_cast<std::size_t>(i + 1)][i] += params.initialStep;
    for (std::size_t i = 0; i < x.size(); ++i) f[i] = eval(x[i]);
    std::vector<std::size_t> order(x.size());
    while (true) {
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return f[a] < f[b]; });
        const std::size_t best = order.front(), worst = order.back(), second = order[order.size() - 2];
        double spread = 0.0;
        for (std::size_t i = 0; i < x.size(); ++i) spread = std::max(spread, (x[i] - x[best]).cwiseAbs().maxCoeff());
        if (spread <= params.xTolerance &&
            std::abs(f[worst] - f[best]) <= params.fTolerance * (std::abs(f[best]) + 1e-12)) {
            result.converged = true;
            break;
        }
        if (result.evaluations >= params.maxEvaluations) break;
        Eigen::VectorXd centroid = Eigen::VectorXd::Zero(n);
        for (std::size_t i = 0; i < x.size(); ++i)
            if (i != worst) centroid += x[i];
        centroid /= n;
        const Eigen::VectorXd reflected = centroid + (centroid - x[worst]);
        const double fr = eval(reflected);
        if (fr < f[best]) {
            const Eigen::VectorXd expanded = centroid + 2.0 * (centroid - x[worst]);
            const double fe = eval(expanded);
            if (fe < fr) {
                x[worst] = expanded;
                f[worst] = fe;
            } else {
                x[worst] = reflected;
                f[worst] = fr;
            }
            continue;
        }
        if (fr < f[second]) {
            x[worst] = reflected;
            f[worst] = fr;
            continue;
        }
        // Contraction: outside when the reflection beat the worst vertex, inside otherwise.
        const bool outside = fr < f[worst];
        const Eigen::VectorXd contracted = outside ? Eigen::VectorXd(centroid + 0.5 * (reflected - centroid))
                                                   : Eigen::VectorXd(centroid + 0.5 * (x[worst] - centroid));
        const double fc = eval(contracted);
        if (fc < (outside ? fr : f[worst])) {
            x[worst] = contracted;
            f[worst] = fc;
            continue;
        }
        for (std::size_t i = 0; i < x.size(); ++i) {
            if (i == best) continue;
            x[i] = x[best] + 0.5 * (x[i] - x[best]);
            f[i] = eval(x[i]);
        }
    }
    const auto best = static_cast<std::size_t>(std::min_element(f.begin(), f.end()) - f.begin());
    result.x = x[best];
    result.value = f[best];
    return result;
}

}  // namespace athlos::inertial
