#include "plugins/lps/RobustStatistics.h"

#include <algorithm>
#include <cmath>

namespace athlos::lps {

double medianAbsoluteDeviation(const std::vector<double>& values) {
    const double m = math::median(values);
    std::vector<double> dev(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) dev[i] = std::abs(values[i] - m);
    return math::median(std::move(dev));
}

double normalQuantile(double p) {
    // Acklam's rational approximation (relative error < 1.2e-9) of Φ⁻¹(p).
    static const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                               1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
    static const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                               6.680131188771972e+01, -1.328068155288572e+01};
    static const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                               -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
    static const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                               3.754408661907416e+00};
    const double low = 0.02425;
    if (p < low) {
        const double q = std::sqrt(-2 * std::log(p));
        return (((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
               ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1);
    }
    if (p > 1 - low) return -normalQuantile(1 - p);
    const double q = p - 0.5, r = q * q;
    return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
           (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1);
}

double studentTQuantile(double p, double v) {
    const double z = normalQuantile(1.0 - p);  // upper quantile
    const double z2 = z * z, z3 = z2 * z, z5 = z3 * z2, z7 = z5 * z2, z9 = z7 * z2;
    return z + (z3 + z) / (4 * v) + (5 * z5 + 16 * z3 + 3 * z) / (96 * v * v) +
           (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * v * v * v) +
           (79 * z9 + 776 * z7 + 1482 * z5 - 1920 * z3 - 945 * z) / (92160 * v * v * v * v);
}

std::vector<bool> grubbsOutliers(const std::vector<double>& values, double alpha, int maxRemovals) {
    std::vector<bool> outlier(values.size(), false);
    std::vector<std::size_t> alive;
    for (std::size_t i = 0; i < values.size(); ++i)
        if (std::isfinite(values[i])) alive.push_back(i);
    // Running sums make each round O(N) for the arg-max only.
    double sum = 0.0, sumSq = 0.0;
    for (auto i : alive) {
        sum += values[i];
        sumSq += values[i] * values[i];
    }
    for (int removed = 0; removed < maxRemovals && alive.size() >= 7; ++removed) {
        const double n = double(alive.size());
        const double mean = sum / n;
        const double sd = std::sqrt(std::max(0.0, (sumSq - n * mean * mean) / (n - 1)));
        if (!(sd > 0.0)) break;
        std::size_t worst = 0;
        for (std::size_t k = 1; k < alive.size(); ++k)
            if (std::abs(values[alive[k]] - mean) > std::abs(values[alive[worst]] - mean)) worst = k;
        const double g = std::abs(values[alive[worst]] - mean) / sd;
        const double t = studentTQuantile(alpha / (2 * n), n - 2);
        const double critical = (n - 1) / std::sqrt(n) * std::sqrt(t * t / (n - 2 + t * t));
        if (g <= critical) break;
        const std::size_t i = alive[worst];
        outlier[i] = true;
        sum -= values[i];
        sumSq -= values[i] * values[i];
        alive.erase(alive.begin() + long(worst));
    }
    return outlier;
}

}  // namespace athlos::lps
