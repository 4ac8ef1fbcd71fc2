#pragma once
// What the read-out shows for one column: the value at the cursor (linear interpolation between
// the neighbouring samples) and mean, SD, min, max of the samples in the visible time range.
#include <cstddef>

namespace athlos {
struct StreamData;
}

namespace athlos::ui {

struct RangeStatistics {
    std::size_t count = 0;  // finite samples in the range
    double mean = 0, sd = 0, min = 0, max = 0;

    // Samples with t in [t0, t1]; NaN samples (gaps) are skipped.
    static RangeStatistics compute(const StreamData& data, int column, double t0, double t1);
    // NaN outside the samples' span.
    static double valueAt(const StreamData& data, int column, double t);
};

}  // namespace athlos::ui
