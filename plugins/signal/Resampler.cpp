#include "plugins/signal/Resampler.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace athlos::signal {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Grid points within this fraction of a period of t_begin/t_end still count as inside, so that
// rounding (0.3·10 = 3.0000000000000004) never drops the first or last sample.
constexpr double kGridTolerance = 1e-9;

struct Grid {
    double origin;  // t of k = 0 is origin + first/rate
    long long first;
    long long count;
    double at(long long k, double rate) const { return origin + static_cast<double>(first + k) / rate; }
};

Grid makeGrid(const Resampler::Params& p, double tBegin, double tEnd) {
    if (p.align) {
        // Multiples of 1/rate: t_k = k/rate exactly as the user would write them.
        const auto first = static_cast<long long>(std::ceil(tBegin * p.rate - kGridTolerance));
        const auto last = static_cast<long long>(std::floor(tEnd * p.rate + kGridTolerance));
        return {0.0, first, std::max(0LL, last - first + 1)};
    }
    const auto last = static_cast<long long>(std::floor((tEnd - tBegin) * p.rate + kGridTolerance));
    return {tBegin, 0, last + 1};
}

// Hermite slope at input sample j: derivative of the parabola through j and its neighbours.
double parabolaSlope(const std::vector<double>& t, const StreamData& in, int column, long long j) {
    const auto n = static_cast<long long>(t.size());
    auto y = [&](long long r) { return in.at(static_cast<std::size_t>(r), column); };
    auto h = [&](long long r) { return t[r + 1] - t[r]; };
    auto d = [&](long long r) { return (y(r + 1) - y(r)) / h(r); };
    if (n < 3) return d(0);
    if (j == 0) return ((2 * h(0) + h(1)) * d(0) - h(0) * d(1)) / (h(0) + h(1));
    if (j == n - 1) return ((2 * h(n - 2) + h(n - 3)) * d(n - 2) - h(n - 2) * d(n - 3)) / (h(n - 2) + h(n - 3));
    return (h(j) * d(j - 1) + h(j - 1) * d(j)) / (h(j - 1) + h(j));
}

Eigen::Quaterniond quaternionAt(const StreamData& in, std::size_t row, const std::array<int, 4>& c) {
    return Eigen::Quaterniond(in.at(row, c[0]), in.at(row, c[1]), in.at(row, c[2]), in.at(row, c[3])).normalized();
}

}  // namespace

Expected<Resampler::Method> Resampler::parseMethod(const QString& name) {
    if (name == QLatin1String("linear")) return Method::Linear;
    if (name == QLatin1String("nearest")) return Method::Nearest;
    if (name == QLatin1String("cubic")) return Method::Cubic;
    return makeError(QStringLiteral("method must be one of linear, nearest, cubic, got '%1'").arg(name));
}

Status Resampler::checkParams(const Params& params) {
    if (!(params.rate > 0.0) || !std::isfinite(params.rate))
        return makeError(QStringLiteral("rate must be a positive frequency in Hz, got %1").arg(params.rate));
    if (!(params.maxGap >= 0.0))
        return makeError(
            QStringLiteral("max_gap must be 0 (off) or a positive duration in s, got %1").arg(params.maxGap));
    return {};
}

Status Resampler::check(const Params& params, const std::vector<double>& t) {
    if (Status ok = checkParams(params); !ok) return ok;
    if (t.size() < 2)
        return makeError(QStringLiteral("the stream has %1 sample(s); resampling needs at least 2").arg(t.size()));
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!std::isfinite(t[i])) return makeError(QStringLiteral("time stamp of row %1 is not finite").arg(i));
        if (i > 0 && !(t[i] > t[i - 1]))
            return makeError(QStringLiteral("time stamps must increase strictly: row %1 (t = %2 s) is not after row %3")
                                 .arg(i)
                                 .arg(t[i], 0, 'g', 12)
                                 .arg(i - 1));
    }
    const Grid grid = makeGrid(params, t.front(), t.back());
    if (grid.count > kMaxOutputRows)
        return makeError(QStringLiteral("rate %1 Hz over %2 s would produce %3 rows (at most %4); lower rate")
                             .arg(params.rate)
                             .arg(t.back() - t.front())
                             .arg(grid.count)
                             .arg(kMaxOutputRows));
    if (grid.count == 0)
        return makeError(
            QStringLiteral("no multiple of 1/rate lies within [%1, %2] s; use align=false or a higher rate")
                .arg(t.front(), 0, 'g', 12)
                .arg(t.back(), 0, 'g', 12));
    return {};
}

Resampler::Resampler(const Params& params, std::vector<double> inputTimes)
    : params_(params), tIn_(std::move(inputTimes)) {
    const Grid grid = makeGrid(params_, tIn_.front(), tIn_.back());
    const auto n = static_cast<long long>(tIn_.size());
    times_.resize(static_cast<std::size_t>(grid.count));
    index_.resize(times_.size());
    weight_.resize(times_.size());
    long long i = 0;  // both time axes increase, so one forward walk brackets every output sample
    for (long long k = 0; k < grid.count; ++k) {
        const double t = grid.at(k, params_.rate);
        times_[k] = t;
        const double tc = std::clamp(t, tIn_.front(), tIn_.back());  // grid tolerance may overshoot by an ulp
        while (i + 2 < n && tIn_[i + 1] <= tc) ++i;
        const double span = tIn_[i + 1] - tIn_[i];
        double w = (tc - tIn_[i]) / span;
        if (params_.maxGap > 0.0 && span > params_.maxGap && w > 0.0 && w < 1.0) w = kNaN;
        index_[k] = i;
        weight_[k] = w;
    }
}

StreamData Resampler::makeOutput(int columns) const {
    StreamData out(times_.size(), columns);
    out.t = times_;
    std::fill(out.values.begin(), out.values.end(), kNaN);
    return out;
}

void Resampler::resampleOrdinary(const StreamData& in, int column, StreamData& out) const {
    switch (params_.method) {
        case Method::Linear:
            linear(in, column, out);
            break;
        case Method::Nearest:
            nearest(in, column, out);
            break;
        case Method::Cubic:
            cubic(in, column, out);
            break;
    }
}

void Resampler::resampleFlag(const StreamData& in, int column, StreamData& out) const { nearest(in, column, out); }

void Resampler::linear(const StreamData& in, int column, StreamData& out) const {
    for (std::size_t k = 0; k < times_.size(); ++k) {
        const auto i = static_cast<std::size_t>(index_[k]);
        const double w = weight_[k];
        const double a = in.at(i, column);
        const double b = in.at(i + 1, column);
        // Exact hits return the sample itself, even next to a NaN neighbour (0·NaN would be NaN).
        out.at(k, column) = w == 0.0 ? a : w == 1.0 ? b : a + w * (b - a);
    }
}

void Resampler::nearest(const StreamData& in, int column, StreamData& out) const {
    for (std::size_t k = 0; k < times_.size(); ++k) {
        const double w = weight_[k];
        const auto i = static_cast<std::size_t>(index_[k]);
        out.at(k, column) = std::isnan(w) ? kNaN : in.at(w < 0.5 ? i : i + 1, column);
    }
}

void Resampler::cubic(const StreamData& in, int column, StreamData& out) const {
    long long slopesAt = -1;  // interval whose end slopes are cached
    double m0 = 0.0, m1 = 0.0;
    for (std::size_t k = 0; k < times_.size(); ++k) {
        const long long i = index_[k];
        const double s = weight_[k];
        const auto row = static_cast<std::size_t>(i);
        const double y0 = in.at(row, column);
        const double y1 = in.at(row + 1, column);
        if (s == 0.0 || s == 1.0 || std::isnan(s)) {
            out.at(k, column) = s == 0.0 ? y0 : s == 1.0 ? y1 : kNaN;
            continue;
        }
        if (slopesAt != i) {
            m0 = parabolaSlope(tIn_, in, column, i);
            m1 = parabolaSlope(tIn_, in, column, i + 1);
            slopesAt = i;
        }
        // Cubic Hermite basis on [t_i, t_i+1] with s ∈ (0, 1) and h = t_i+1 − t_i.
        const double h = tIn_[row + 1] - tIn_[row];
        const double s2 = s * s, s3 = s2 * s;
        out.at(k, column) =
            (2 * s3 - 3 * s2 + 1) * y0 + (s3 - 2 * s2 + s) * h * m0 + (-2 * s3 + 3 * s2) * y1 + (s3 - s2) * h * m1;
    }
}

void Resampler::resampleQuaternion(const StreamData& in, const std::array<int, 4>& c, StreamData& out) const {
    for (std::size_t k = 0; k < times_.size(); ++k) {
        const double w = weight_[k];
        const auto i = static_cast<std::size_t>(index_[k]);
        Eigen::Quaterniond q(kNaN, kNaN, kNaN, kNaN);
        if (!std::isnan(w)) {
            if (params_.method == Method::Nearest || w == 0.0 || w == 1.0) {
                q = quaternionAt(in, w < 0.5 ? i : i + 1, c);
            } else {
                // Eigen's slerp takes the shortest arc (it flips the sign for a negative dot product).
                q = quaternionAt(in, i, c).slerp(w, quaternionAt(in, i + 1, c)).normalized();
            }
        }
        out.at(k, c[0]) = q.w();
        out.at(k, c[1]) = q.x();
        out.at(k, c[2]) = q.y();
        out.at(k, c[3]) = q.z();
    }
}

StreamData Resampler::resample(const StreamData& in, const ColumnGroups& groups) const {
    StreamData out = makeOutput(in.columns);
    for (int c : groups.ordinary) resampleOrdinary(in, c, out);
    for (int c : groups.flags) resampleFlag(in, c, out);
    for (const auto& q : groups.quaternions) resampleQuaternion(in, q, out);
    return out;
}

}  // namespace athlos::signal
