#pragma once
// A min/max decimation pyramid over one column of a stream, so that a plot can show 10 million
// samples with ~2 points per pixel column without ever losing a peak.
//
// Lives in ui/ because only display code needs it: analysis always works on the raw samples.
#include "core/model/StreamData.h"

#include <QList>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace athlos::ui {

// The extremes of a run of samples. minFirst says whether the (first) minimum occurs no later
// than the (first) maximum, so a decimated line can visit them in time order. NaN samples are
// ignored; a run without finite samples is empty (min > max).
struct Extremes {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    bool minFirst = true;

    bool isEmpty() const { return min > max; }
    // Extremes of the concatenation "earlier, then later".
    static Extremes combine(const Extremes& earlier, const Extremes& later);
};

// The points to hand to a plot for one x range: for every pixel column its minimum and maximum
// in time order (or the raw samples when there are few enough), plus the nearest sample outside
// each end so the line runs to the plot edges.
struct DecimatedSeries {
    QList<double> keys;
    QList<double> values;
    bool raw = false;  // keys/values are the samples themselves
    Extremes visible;  // extremes of the samples inside [t0, t1] (for y auto-fit)
    long long visibleSamples = 0;
};

class MinMaxPyramid {
public:
    // Raw samples per bottom-level bucket and buckets merged per level above. Small enough that
    // a range query touches at most ~2·(16 + 4·levels) values; large enough that the pyramid
    // costs about 1/12 of a double per sample.
    static constexpr std::size_t kBaseBucket = 16;
    static constexpr std::size_t kFanout = 4;

    MinMaxPyramid() = default;
    // Builds the pyramid over data->column(column). Keeps data alive (the raw samples are read
    // at query time for the ragged ends of a range and for zoomed-in views).
    MinMaxPyramid(std::shared_ptr<const StreamData> data, int column);

    std::size_t size() const { return data_ ? data_->rows() : 0; }
    int column() const { return column_; }
    int levelCount() const { return static_cast<int>(levels_.size()); }
    const StreamData* data() const { return data_.get(); }
    double value(std::size_t row) const { return data_->values[row * stride_ + column_]; }

    // Extremes of samples [begin, end), in O(kBaseBucket + kFanout·levels).
    Extremes rangeExtremes(std::size_t begin, std::size_t end) const;

    // Points for a plot of the time range [t0, t1] that is `pixels` columns wide. Returns the raw
    // samples when at most rawLimit·pixels samples are visible, else per pixel column its
    // minimum and maximum (placed at 1/4 and 3/4 of the column, in the order they occur).
    DecimatedSeries decimate(double t0, double t1, int pixels, double rawLimit = 2.0) const;

private:
    struct Level {
        std::vector<double> min;
        std::vector<double> max;
        std::vector<std::uint8_t> minFirst;
        std::size_t size() const { return min.size(); }
        Extremes at(std::size_t i) const { return {min[i], max[i], minFirst[i] != 0}; }
    };

    Extremes sample(std::size_t row) const;

    std::shared_ptr<const StreamData> data_;
    int column_ = 0;
    std::size_t stride_ = 1;
    std::vector<Level> levels_;  // levels_[0]: buckets of kBaseBucket samples
};

}  // namespace athlos::ui
