#pragma once
// Median absolute deviation and the Grubbs outlier test (thesis §3.1.2 step 4, [Grub 69]); the median
// itself is math::median (core/math/Statistics.h).
#include "core/math/Statistics.h"

#include <vector>

namespace athlos::lps {

// Unscaled MAD = median |x − median(x)|; multiply by 1.4826 for a Gaussian σ estimate.
double medianAbsoluteDeviation(const std::vector<double>& values);

// Upper quantile of Student's t with ν degrees of freedom (Cornish–Fisher expansion around the
// normal quantile; accurate to ~1e-3 for ν ≥ 10, which the residual sets here always exceed).
double studentTQuantile(double p, double dof);
double normalQuantile(double p);

// Iterative two-sided Grubbs test at significance alpha: removes the most extreme value while
// G = max|x − x̄|/s exceeds G_crit = (N−1)/√N · √(t²/(N−2+t²)), t = t_{α/(2N), N−2}.
// Returns a flag per value (true = outlier). Stops after maxRemovals or below 7 remaining values.
std::vector<bool> grubbsOutliers(const std::vector<double>& values, double alpha, int maxRemovals);

}  // namespace athlos::lps
