#include "plugins/activity/EventDetectors.h"

#include "plugins/signal/Butterworth.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::activity {

namespace {
using signal::Butterworth;

Expected<double> samplingRate(const StreamData& data) {
    const double dt = data.medianInterval();
    if (data.rows() < 8 || !(dt > 0)) return makeError(QStringLiteral("the stream is too short to detect events"));
    return 1.0 / dt;
}

// Zero-phase Butterworth (order 2) of one column.
Expected<Eigen::VectorXd> filtered(const StreamData& data, int column, Butterworth::Type type, double cutoff,
                                   double rate, const char* what) {
    Butterworth::Params p;
    p.type = type;
    p.order = 2;
    p.cutoff = cutoff;
    p.samplingRate = rate;
    if (Status s = Butterworth::check(p); !s)
        return makeError(
            QStringLiteral("%1 at %2 Hz: %3").arg(QLatin1String(what)).arg(rate, 0, 'g', 4).arg(s.message()));
    Eigen::VectorXd x(Eigen::Index(data.rows()));
    for (std::size_t i = 0; i < data.rows(); ++i) x[Eigen::Index(i)] = data.at(i, column);
    Butterworth(p).filterSegments(x, true);
    return x;
}
}  // namespace

Expected<std::vector<int>> accelerometerColumns(const StreamInfo& info) {
    std::vector<int> columns;
    for (const char* name : {"acc_x", "acc_y", "acc_z"}) {
        const int i = info.columnIndex(QLatin1String(name));
        if (i < 0) return makeError(QStringLiteral("the event detectors need column %1").arg(QLatin1String(name)));
        columns.push_back(i);
    }
    return columns;
}

std::vector<DetectedEvent> peaksAfterCrossings(const StreamData& data, const std::vector<double>& signal,
                                               double threshold, double minSeparation) {
    std::vector<DetectedEvent> events;
    const std::size_t n = std::min(signal.size(), data.rows());
    double last = -std::numeric_limits<double>::infinity();
    bool armed = n > 0 && !(signal[0] >= threshold);  // a stream starting above the threshold waits for a fall
    for (std::size_t i = 1; i < n; ++i) {
        if (!(signal[i] >= threshold)) {
            armed = true;
            continue;
        }
        if (!armed || data.t[i] - last < minSeparation) continue;
        // Upward crossing at i: climb to the next local maximum.
        std::size_t k = i;
        while (k + 1 < n && signal[k + 1] >= signal[k]) ++k;
        DetectedEvent e;
        e.t = data.t[k];
        e.row = k;
        e.impact = signal[k];
        events.push_back(e);
        last = e.t;
        armed = false;
        i = k;
    }
    return events;
}

Expected<std::vector<double>> ImpactDetector::signal(const StreamInfo& info, const StreamData& data,
                                                     const Params& params) {
    auto columns = accelerometerColumns(info);
    if (!columns) return columns.error();
    auto rate = samplingRate(data);
    if (!rate) return rate.error();
    Eigen::VectorXd l1 = Eigen::VectorXd::Zero(Eigen::Index(data.rows()));
    for (int c : *columns) {
        auto hp = filtered(data, c, Butterworth::Type::HighPass, params.highPass, *rate, "impact high-pass");
        if (!hp) return hp.error();
        l1 += hp->cwiseAbs();
    }
    Butterworth::Params lp;
    lp.cutoff = params.lowPass;
    lp.samplingRate = *rate;
    if (Status s = Butterworth::check(lp); !s) return makeError(QStringLiteral("impact low-pass: ") + s.message());
    Butterworth(lp).filterSegments(l1, true);
    return std::vector<double>(l1.data(), l1.data() + l1.size());
}

Expected<std::vector<DetectedEvent>> ImpactDetector::detect(const StreamInfo& info, const StreamData& data,
                                                            const Params& params) {
    auto s = signal(info, data, params);
    if (!s) return s.error();
    // One hump per impact: a separation of a tenth of a second only guards against ripples.
    std::vector<DetectedEvent> events = peaksAfterCrossings(data, *s, params.threshold, 0.1);
    const std::vector<int> columns = *accelerometerColumns(info);
    for (DetectedEvent& e : events) {
        double sum = 0;
        int count = 0;
        for (std::size_t i = e.row; i-- > 0 && data.t[i] >= e.t - params.swingWindow;) {
            double norm = 0;
            for (int c : columns) norm += data.at(i, c) * data.at(i, c);
            sum += std::sqrt(norm);
            ++count;
        }
        e.swing = count ? sum / count : 0.0;
    }
    return events;
}

Expected<std::vector<double>> TackleDetector::signal(const StreamInfo& info, const StreamData& data,
                                                     const Params& params) {
    auto columns = accelerometerColumns(info);
    if (!columns) return columns.error();
    auto rate = samplingRate(data);
    if (!rate) return rate.error();
    Eigen::VectorXd sq = Eigen::VectorXd::Zero(Eigen::Index(data.rows()));
    for (int c : *columns) {
        auto lp = filtered(data, c, Butterworth::Type::LowPass, params.lowPass, *rate, "tackle low-pass");
        if (!lp) return lp.error();
        sq += lp->cwiseAbs2();
    }
    std::vector<double> out(data.rows());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::sqrt(sq[Eigen::Index(i)]);
    return out;
}

Expected<std::vector<DetectedEvent>> TackleDetector::detect(const StreamInfo& info, const StreamData& data,
                                                            const Params& params) {
    if (!(params.threshold > 0))
        return makeError(
            QStringLiteral("the tackle detector's threshold is not fitted (train with annotated tackles)"));
    auto s = signal(info, data, params);
    if (!s) return s.error();
    return peaksAfterCrossings(data, *s, params.threshold, params.minSeparation);
}

std::vector<double> TackleDetector::annotationPeaks(const StreamData& data, const std::vector<double>& signal,
                                                    const Annotations& annotations) {
    std::vector<double> peaks;
    for (const Annotation& a : annotations) {
        const auto begin = std::size_t(std::lower_bound(data.t.begin(), data.t.end(), a.tStart) - data.t.begin());
        const auto end = std::size_t(std::upper_bound(data.t.begin(), data.t.end(), a.tEnd) - data.t.begin());
        double peak = std::numeric_limits<double>::quiet_NaN();
        for (std::size_t i = begin; i < end && i < signal.size(); ++i)
            if (!(signal[i] <= peak)) peak = signal[i];
        peaks.push_back(peak);
    }
    return peaks;
}

Expected<double> TackleDetector::fitThreshold(std::vector<double> peaks, const Params& params) {
    std::erase_if(peaks, [](double v) { return !std::isfinite(v); });
    if (peaks.empty()) return makeError(QStringLiteral("no annotated event to fit the tackle detector's threshold on"));
    if (!(params.targetRecall > 0 && params.targetRecall <= 1))
        return makeError(
            QStringLiteral("--tackle-recall %1: expected a share above 0, at most 1").arg(params.targetRecall));
    std::sort(peaks.begin(), peaks.end());
    // Keep the ceil(recall · n) strongest events: the threshold sits below the weakest of them.
    const auto keep = std::size_t(std::ceil(params.targetRecall * double(peaks.size()) - 1e-9));
    const double weakest = peaks[peaks.size() - std::max<std::size_t>(keep, 1)];
    return params.margin * weakest;
}

double eventRecall(const std::vector<DetectedEvent>& events, const Annotations& annotations, double tolerance) {
    if (annotations.empty()) return 1.0;
    std::size_t found = 0;
    for (const Annotation& a : annotations) {
        const auto it = std::lower_bound(events.begin(), events.end(), a.tStart - tolerance,
                                         [](const DetectedEvent& e, double t) { return e.t < t; });
        found += it != events.end() && it->t <= a.tEnd + tolerance;
    }
    return double(found) / double(annotations.size());
}

}  // namespace athlos::activity
