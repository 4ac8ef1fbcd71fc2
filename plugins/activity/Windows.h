#pragma once
// Sliding windows over a stream's time axis (seed 000 §5.2: fixed-length windows with overlap for
// continuous activities) and their labels from annotations.
#include "core/model/Annotation.h"
#include "core/model/StreamData.h"

#include <QStringList>
#include <vector>

namespace athlos::activity {

struct Window {
    double tStart = 0, tEnd = 0;     // s, [tStart, tStart + length)
    std::size_t begin = 0, end = 0;  // rows of the stream inside it
    double centre() const { return 0.5 * (tStart + tEnd); }
};

// Windows of `length` s every `step` s from the first sample; the last one ends at or before the last
// sample (a stream shorter than one window gives one window over all of it). Windows with fewer than
// minRows rows are left out.
std::vector<Window> slidingWindows(const StreamData& data, double length, double step, std::size_t minRows = 2);

// The label of a window: the label with the largest overlap among `annotations` (only labels listed in
// `classes` when it is not empty), or "" when that overlap is below minFraction of the window.
QString windowLabel(const Window& window, const Annotations& annotations, const QStringList& classes,
                    double minFraction);

}  // namespace athlos::activity
