#pragma once
// Sample intervals: a time range of a stream as the range of its rows.
#include <algorithm>
#include <cstddef>
#include <span>

namespace athlos {

// Rows [begin, end) of a stream.
struct RowRange {
    std::size_t begin = 0;
    std::size_t end = 0;

    std::size_t size() const { return end - begin; }
    bool empty() const { return end <= begin; }
};

// The rows whose time lies in [tBegin, tEnd] (both ends included) of the strictly increasing time
// stamps t; empty when the range misses the samples or tEnd < tBegin. O(log n).
inline RowRange rowsInTimeRange(std::span<const double> t, double tBegin, double tEnd) {
    const auto first = std::lower_bound(t.begin(), t.end(), tBegin);
    const auto last = std::upper_bound(first, t.end(), tEnd);
    return {std::size_t(first - t.begin()), std::size_t(last - t.begin())};
}

}  // namespace athlos
