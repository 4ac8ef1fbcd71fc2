#pragma once
// Order statistics shared by the families: the median (and the upper median some estimators were
// tuned with). Both are NaN for an empty set: callers decide what an empty window means.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace athlos::math {

// The upper median: the middle value of an odd-sized set, the higher of the two middle values of
// an even-sized one (always a member of the set). NaN for an empty set. O(n).
inline double upperMedian(std::vector<double> values) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto mid = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    return *mid;
}

// The median: the middle value of an odd-sized set, the mean of the two middle values of an
// even-sized one. NaN for an empty set. NaN entries are not filtered out (pass finite values). O(n).
inline double median(std::vector<double> values) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto mid = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), mid, values.end());
    if (values.size() % 2) return *mid;
    return 0.5 * (*mid + *std::max_element(values.begin(), mid));
}

}  // namespace athlos::math
