#include "plugins/activity/FeatureExtractor.h"

#include "plugins/activity/FeatureMath.h"

#include <algorithm>
#include <cmath>

namespace athlos::activity {

namespace {
// Per-channel statistics, in the order of Table 5.1 of the thesis.
// Then percentiles and the share of the spectral energy in four bands (0.3–1, 1–3, 3–6, 6–12 Hz: posture
// drift, gait, running and impacts): shape and rhythm independent of a person's movement amplitude.
const char* const kStatistics[] = {"median", "mean", "sd",     "skewness",   "kurtosis", "dom_freq", "dom_amp",
                                   "max",    "min",  "argmax", "argmin",     "energy",   "p10",      "p25",
                                   "p75",    "p90",  "iqr",    "band_0.3_1", "band_1_3", "band_3_6", "band_6_12"};
constexpr int kStatisticCount = 21;
constexpr double kBandEdges[] = {0.3, 1.0, 3.0, 6.0, 12.0};
constexpr int kBands = 4;

// Channels of a sensor beyond x, y, z, norm.
int extraChannels(const QString& sensor) {
    if (sensor == QLatin1String("acc")) return 2;  // vert, horiz
    if (sensor == QLatin1String("gyr")) return 1;  // vert
    return 0;
}
}  // namespace

Expected<FeatureExtractor> FeatureExtractor::create(const StreamInfo& info, const QStringList& sensors) {
    FeatureExtractor f;
    if (!sensors.contains(QStringLiteral("acc")))
        return makeError(QStringLiteral("sensors: 'acc' is required (gravity features come from it)"));
    for (const QString& s : {QStringLiteral("acc"), QStringLiteral("gyr"), QStringLiteral("mag")}) {
        if (!sensors.contains(s)) continue;
        const int x = info.columnIndex(s + QStringLiteral("_x"));
        if (x < 0 || info.columnIndex(s + QStringLiteral("_y")) != x + 1 ||
            info.columnIndex(s + QStringLiteral("_z")) != x + 2)
            return makeError(QStringLiteral("needs adjacent columns %1_x, %1_y, %1_z (it has: %2)")
                                 .arg(s, info.columnNames().join(QStringLiteral(", "))));
        f.sensors_ << s;
        f.columns_.push_back({s, x});
    }
    for (const QString& s : sensors)
        if (!f.sensors_.contains(s))
            return makeError(QStringLiteral("sensors: unknown sensor '%1' (use acc, gyr, mag)").arg(s));
    f.addNames();
    return f;
}

QStringList FeatureExtractor::inputColumns() const {
    QStringList columns;
    for (const Sensor& s : columns_)
        for (const char* axis : {"_x", "_y", "_z"}) columns << s.name + QLatin1String(axis);
    return columns;
}

void FeatureExtractor::addNames() {
    names_.clear();
    for (const Sensor& s : columns_) {
        QStringList channels{s.name + QStringLiteral("_x"), s.name + QStringLiteral("_y"),
                             s.name + QStringLiteral("_z"), s.name + QStringLiteral("_norm")};
        if (extraChannels(s.name) >= 1) channels << s.name + QStringLiteral("_vert");
        if (extraChannels(s.name) >= 2) channels << s.name + QStringLiteral("_horiz");
        for (const QString& c : channels)
            for (const char* stat : kStatistics) names_ << c + QLatin1Char('.') + QLatin1String(stat);
        for (const char* pair : {"xy", "xz", "yz"}) names_ << s.name + QStringLiteral(".corr_") + QLatin1String(pair);
    }
    for (const char* g : {"gravity_x", "gravity_y", "gravity_z", "pitch", "roll"})
        names_ << QStringLiteral("acc.") + QLatin1String(g);
}

void FeatureExtractor::compute(const StreamData& data, std::size_t begin, std::size_t end, float* out) {
    const std::size_t n = end > begin ? end - begin : 0;
    std::fill(out, out + names_.size(), 0.0f);
    if (n < 2) return;
    const double duration = data.t[end - 1] - data.t[begin];
    const double rate = duration > 0 ? double(n - 1) / duration : 1.0;

    // Gravity direction: the mean of the accelerometer over the window.
    const int acc = columns_.front().column;
    double g[3] = {0, 0, 0};
    for (std::size_t r = begin; r < end; ++r)
        for (int k = 0; k < 3; ++k)
            if (const double v = data.at(r, acc + k); std::isfinite(v)) g[k] += v;
    const double gNorm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    double u[3] = {0, 0, 1};
    if (gNorm > 0)
        for (int k = 0; k < 3; ++k) u[k] = g[k] / gNorm;

    int channelCount = 0;
    for (const Sensor& s : columns_) channelCount += 4 + extraChannels(s.name);
    channels_.resize(std::size_t(channelCount) * n);
    scratch_.resize(n);

    int channel = 0;
    for (const Sensor& s : columns_) {
        const int extra = extraChannels(s.name);
        double* x = channels_.data() + std::size_t(channel) * n;
        double* y = x + n;
        double* z = y + n;
        double* norm = z + n;
        double* vert = extra >= 1 ? norm + n : nullptr;
        double* horiz = extra >= 2 ? vert + n : nullptr;
        // Missing samples (NaN cells of an import) take the last finite value of the sensor.
        double held[3] = {0, 0, 0};
        for (std::size_t i = 0; i < n; ++i) {
            const double* raw = data.values.data() + (begin + i) * std::size_t(data.columns) + s.column;
            if (std::isfinite(raw[0]) && std::isfinite(raw[1]) && std::isfinite(raw[2])) {
                held[0] = raw[0];
                held[1] = raw[1];
                held[2] = raw[2];
                break;
            }
        }
        for (std::size_t i = 0; i < n; ++i) {
            const double* raw = data.values.data() + (begin + i) * std::size_t(data.columns) + s.column;
            if (std::isfinite(raw[0]) && std::isfinite(raw[1]) && std::isfinite(raw[2])) {
                held[0] = raw[0];
                held[1] = raw[1];
                held[2] = raw[2];
            }
            const double* row = held;
            x[i] = row[0];
            y[i] = row[1];
            z[i] = row[2];
            const double squares = row[0] * row[0] + row[1] * row[1] + row[2] * row[2];
            norm[i] = std::sqrt(squares);
            if (vert) {
                const double along = row[0] * u[0] + row[1] * u[1] + row[2] * u[2];
                vert[i] = along;
                if (horiz) horiz[i] = std::sqrt(std::max(0.0, squares - along * along));
            }
        }
        channel += 4 + extra;
    }

    // One DFT of all channels (rows), mean removed, zero-padded to an efficient length.
    const int length = cv::getOptimalDFTSize(int(n));
    if (padded_.rows != channelCount || padded_.cols != length) padded_.create(channelCount, length, CV_64F);
    for (int c = 0; c < channelCount; ++c) {
        const double* x = channels_.data() + std::size_t(c) * n;
        double mean = 0;
        for (std::size_t i = 0; i < n; ++i) mean += x[i];
        mean /= double(n);
        double* row = padded_.ptr<double>(c);
        for (std::size_t i = 0; i < n; ++i) row[i] = x[i] - mean;
        std::fill(row + n, row + length, 0.0);
    }
    cv::dft(padded_, spectrum_, cv::DFT_ROWS | cv::DFT_COMPLEX_OUTPUT);
    const std::size_t bins = std::size_t(length / 2 + 1);
    magnitude_.resize(bins);

    float* o = out;
    channel = 0;
    for (const Sensor& s : columns_) {
        const int count = 4 + extraChannels(s.name);
        for (int c = 0; c < count; ++c, ++channel) {
            const double* x = channels_.data() + std::size_t(channel) * n;
            const Moments m = moments(x, n);
            const Extremes e = extremes(x, n);
            const cv::Vec2d* bin = spectrum_.ptr<cv::Vec2d>(channel);
            for (std::size_t k = 0; k < bins; ++k) magnitude_[k] = std::hypot(bin[k][0], bin[k][1]);
            const Dominant d = dominantFromSpectrum(magnitude_.data(), bins, std::size_t(length), n, rate);
            const Quantiles q = quantiles(x, n, scratch_.data());
            double shares[kBands];
            bandShares(magnitude_.data(), bins, std::size_t(length), rate, kBandEdges, kBands, shares);
            const double values[kStatisticCount] = {
                q.p50, m.mean, m.sd,          m.skewness, m.kurtosis, d.frequency, d.amplitude,
                e.max, e.min,  e.argmax,      e.argmin,   m.energy,   q.p10,       q.p25,
                q.p75, q.p90,  q.p75 - q.p25, shares[0],  shares[1],  shares[2],   shares[3]};
            for (double v : values) *o++ = std::isfinite(v) ? float(v) : 0.0f;
        }
        const double* base = channels_.data() + std::size_t(channel - count) * n;
        *o++ = float(correlation(base, base + n, n));
        *o++ = float(correlation(base, base + 2 * n, n));
        *o++ = float(correlation(base + n, base + 2 * n, n));
    }
    // Pitch and roll of the sensor from gravity (x forward: pitch = atan2(−g_x, √(g_y²+g_z²)),
    // roll = atan2(g_y, g_z); the torso-pitch construction of the digest §8 applied to the wrist).
    *o++ = float(u[0]);
    *o++ = float(u[1]);
    *o++ = float(u[2]);
    *o++ = float(std::atan2(-u[0], std::hypot(u[1], u[2])));
    *o++ = float(std::atan2(u[1], u[2]));
}

}  // namespace athlos::activity
