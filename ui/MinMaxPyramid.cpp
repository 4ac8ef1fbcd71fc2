#include "ui/MinMaxPyramid.h"

#include <algorithm>
#include <cmath>

namespace athlos::ui {

Extremes Extremes::combine(const Extremes& earlier, const Extremes& later) {
    if (earlier.isEmpty()) return later;
    if (later.isEmpty()) return earlier;
    // Ties go to the earlier run, so the result always describes the first occurrence.
    const bool minEarlier = earlier.min <= later.min;
    const bool maxEarlier = earlier.max >= later.max;
    Extremes r;
    r.min = minEarlier ? earlier.min : later.min;
    r.max = maxEarlier ? earlier.max : later.max;
    if (minEarlier == maxEarlier)
        r.minFirst = minEarlier ? earlier.minFirst : later.minFirst;
    else
        r.minFirst = minEarlier;
    return r;
}

MinMaxPyramid::MinMaxPyramid(std::shared_ptr<const StreamData> data, int column)
    : data_(std::move(data)), column_(column) {
    if (!data_ || column_ < 0 || column_ >= data_->columns) {
        data_.reset();
        return;
    }
    stride_ = static_cast<std::size_t>(data_->columns);
    const std::size_t n = data_->rows();
    if (n == 0) return;

    Level base;
    const std::size_t buckets = (n + kBaseBucket - 1) / kBaseBucket;
    base.min.resize(buckets);
    base.max.resize(buckets);
    base.minFirst.resize(buckets);
    for (std::size_t b = 0; b < buckets; ++b) {
        Extremes e;
        const std::size_t end = std::min(n, (b + 1) * kBaseBucket);
        for (std::size_t i = b * kBaseBucket; i < end; ++i) e = Extremes::combine(e, sample(i));
        base.min[b] = e.min;
        base.max[b] = e.max;
        base.minFirst[b] = e.minFirst;
    }
    levels_.push_back(std::move(base));

    while (levels_.back().size() > kFanout) {
        const Level& below = levels_.back();
        Level up;
        const std::size_t count = (below.size() + kFanout - 1) / kFanout;
        up.min.resize(count);
        up.max.resize(count);
        up.minFirst.resize(count);
        for (std::size_t b = 0; b < count; ++b) {
            Extremes e;
            const std::size_t end = std::min(below.size(), (b + 1) * kFanout);
            for (std::size_t i = b * kFanout; i < end; ++i) e = Extremes::combine(e, below.at(i));
            up.min[b] = e.min;
            up.max[b] = e.max;
            up.minFirst[b] = e.minFirst;
        }
        levels_.push_back(std::move(up));
    }
}

Extremes MinMaxPyramid::sample(std::size_t row) const {
    const double v = value(row);
    if (std::isnan(v)) return {};
    return {v, v, true};
}

Extremes MinMaxPyramid::rangeExtremes(std::size_t begin, std::size_t end) const {
    end = std::min(end, size());
    if (begin >= end) return {};

    // Short runs: raw samples are as cheap as the bookkeeping.
    if (end - begin < 2 * kBaseBucket) {
        Extremes e;
        for (std::size_t i = begin; i < end; ++i) e = Extremes::combine(e, sample(i));
        return e;
    }

    // Walk up the pyramid, peeling unaligned ends off at each level: `head` collects from the
    // left in time order, `tail` from the right (prepending), so combine() sees runs in order.
    Extremes head, tail;
    std::size_t lo = begin, hi = end;
    while (lo % kBaseBucket) head = Extremes::combine(head, sample(lo++));
    while (hi % kBaseBucket) tail = Extremes::combine(sample(--hi), tail);
    lo /= kBaseBucket;
    hi /= kBaseBucket;  // [lo, hi) are now complete buckets of level 0

    for (std::size_t level = 0; level < levels_.size() && lo < hi; ++level) {
        const Level& l = levels_[level];
        const bool top = level + 1 == levels_.size();
        if (top || hi - lo < 2 * kFanout) {
            for (std::size_t i = lo; i < hi; ++i) head = Extremes::combine(head, l.at(i));
            break;
        }
        while (lo % kFanout) head = Extremes::combine(head, l.at(lo++));
        while (hi % kFanout) tail = Extremes::combine(l.at(--hi), tail);
        lo /= kFanout;
        hi /= kFanout;
    }
    return Extremes::combine(head, tail);
}

DecimatedSeries MinMaxPyramid::decimate(double t0, double t1, int pixels, double rawLimit) const {
    DecimatedSeries out;
    const std::size_t n = size();
    if (n == 0 || !(t1 >= t0)) return out;
    pixels = std::max(pixels, 1);

    const double* t = data_->t.data();
    const std::size_t first = static_cast<std::size_t>(std::lower_bound(t, t + n, t0) - t);
    const std::size_t last = static_cast<std::size_t>(std::upper_bound(t, t + n, t1) - t);
    out.visibleSamples = static_cast<long long>(last - first);
    out.visible = rangeExtremes(first, last);

    // One neighbour outside each end, so the line leaves the plot instead of stopping short.
    const std::size_t before = first > 0 ? first - 1 : first;
    const std::size_t after = last < n ? last + 1 : last;

    if (static_cast<double>(last - first) <= rawLimit * pixels) {
        out.raw = true;
        out.keys.reserve(static_cast<qsizetype>(after - before));
        out.values.reserve(static_cast<qsizetype>(after - before));
        for (std::size_t i = before; i < after; ++i) {
            out.keys.append(t[i]);
            out.values.append(value(i));
        }
        return out;
    }

    out.keys.reserve(2 * pixels + 2);
    out.values.reserve(2 * pixels + 2);
    if (before < first) {
        out.keys.append(t[before]);
        out.values.append(value(before));
    }
    const double dt = (t1 - t0) / pixels;
    std::size_t b = first;
    for (int p = 0; p < pixels && b < last; ++p) {
        const double x0 = t0 + p * dt;
        const std::size_t next =
            p == pixels - 1 ? last : static_cast<std::size_t>(std::lower_bound(t + b, t + last, t0 + (p + 1) * dt) - t);
        const Extremes e = rangeExtremes(b, next);
        b = next;
        if (e.isEmpty()) continue;
        if (e.min == e.max) {
            out.keys.append(x0 + 0.5 * dt);
            out.values.append(e.min);
            continue;
        }
        out.keys.append(x0 + 0.25 * dt);
        out.values.append(e.minFirst ? e.min : e.max);
        out.keys.append(x0 + 0.75 * dt);
        out.values.append(e.minFirst ? e.max : e.min);
    }
    if (last < after) {
        out.keys.append(t[last]);
        out.values.append(value(last));
    }
    return out;
}

}  // namespace athlos::ui
