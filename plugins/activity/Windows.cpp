#include "plugins/activity/Windows.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace athlos::activity {

std::vector<Window> slidingWindows(const StreamData& data, double length, double step, std::size_t minRows) {
    std::vector<Window> windows;
    if (data.rows() == 0 || !(length > 0) || !(step > 0)) return windows;
    const double first = data.t.front(), last = data.t.back();
    // A tolerance of a hundredth of a sample keeps the last full window despite rounding of t.
    const double tolerance = 0.01 * std::max(data.medianInterval(), 1e-9);
    const auto addWindow = [&](double start, double end) {
        Window w;
        w.tStart = start;
        w.tEnd = end;
        w.begin = std::size_t(std::lower_bound(data.t.begin(), data.t.end(), start - tolerance) - data.t.begin());
        w.end = std::size_t(std::lower_bound(data.t.begin(), data.t.end(), end - tolerance) - data.t.begin());
        if (end >= last - tolerance) w.end = data.rows();
        if (w.end - w.begin >= minRows) windows.push_back(w);
    };
    if (last - first < length) {
        addWindow(first, last);
        return windows;
    }
    const auto count = std::size_t(std::floor((last - first - length + tolerance) / step)) + 1;
    windows.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double start = first + double(i) * step;
        addWindow(start, start + length);
    }
    return windows;
}

QString windowLabel(const Window& window, const Annotations& annotations, const QStringList& classes,
                    double minFraction) {
    std::map<QString, double> overlap;
    for (const Annotation& a : annotations) {
        if (!classes.isEmpty() && !classes.contains(a.label)) continue;
        const double o = std::min(a.tEnd, window.tEnd) - std::max(a.tStart, window.tStart);
        if (o > 0) overlap[a.label] += o;
    }
    QString best;
    double bestOverlap = 0;
    for (const auto& [label, o] : overlap)
        if (o > bestOverlap) {
            best = label;
            bestOverlap = o;
        }
    const double length = window.tEnd - window.tStart;
    if (best.isEmpty() || bestOverlap < minFraction * length) return {};
    return best;
}

}  // namespace athlos::activity
