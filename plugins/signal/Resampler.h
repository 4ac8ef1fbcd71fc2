#pragma once
// Resampling of a stream onto a uniform time grid t_k = t0 + k/rate covering [t_begin, t_end].
//
// Ordinary columns: linear, nearest, or cubic. "cubic" is a local cubic Hermite spline whose
// slopes are the derivatives of the parabola through each sample and its two neighbours
// (Catmull-Rom on a uniform input grid; one-sided parabolas at the ends). It reproduces
// quadratics exactly on any input grid and, being local, a NaN only spoils the two intervals on
// either side of it — a natural spline would smear one NaN over the whole stream.
// Quaternion groups: SLERP along the shortest arc, renormalised (nearest sample for
// method=nearest, so that "nearest" never invents values). Flag columns: nearest neighbour.
// NaN in: an output sample whose interpolation uses a NaN input sample is NaN.
// max_gap > 0: output samples strictly inside an input interval longer than max_gap are NaN.
#include "plugins/signal/ColumnGroups.h"

#include "core/model/StreamData.h"
#include "core/util/Expected.h"

#include <QString>
#include <array>
#include <vector>

namespace athlos::signal {

class Resampler {
public:
    enum class Method { Linear, Nearest, Cubic };

    struct Params {
        double rate = 0.0;  // Hz, > 0
        Method method = Method::Linear;
        double maxGap = 0.0;  // s; 0 = off
        bool align = false;   // grid on integer multiples of 1/rate instead of starting at t_begin
    };

    // Largest output the resampler agrees to produce (rows), to turn a typo in rate into an error
    // instead of an out-of-memory crash.
    static constexpr long long kMaxOutputRows = 500'000'000;

    static Expected<Method> parseMethod(const QString& name);
    // Checks the parameters alone (rate, max_gap); errors name the parameter.
    static Status checkParams(const Params& params);
    // checkParams() plus the input times: enough samples, strictly increasing (naming the row), and
    // an output of sensible size.
    static Status check(const Params& params, const std::vector<double>& inputTimes);

    // Builds the output grid and, per output sample, the input interval it falls into.
    // inputTimes must pass check().
    Resampler(const Params& params, std::vector<double> inputTimes);

    const Params& params() const { return params_; }
    const std::vector<double>& times() const { return times_; }
    std::size_t size() const { return times_.size(); }
    // An output stream buffer of the right size (t filled in, values NaN).
    StreamData makeOutput(int columns) const;

    // Batch functions: read column(s) of in (sampled at the inputTimes given to the constructor)
    // and write the same column(s) of out (from makeOutput()).
    void resampleOrdinary(const StreamData& in, int column, StreamData& out) const;
    void resampleFlag(const StreamData& in, int column, StreamData& out) const;
    void resampleQuaternion(const StreamData& in, const std::array<int, 4>& columns, StreamData& out) const;
    // All columns by their group.
    StreamData resample(const StreamData& in, const ColumnGroups& groups) const;

private:
    void linear(const StreamData& in, int column, StreamData& out) const;
    void nearest(const StreamData& in, int column, StreamData& out) const;
    void cubic(const StreamData& in, int column, StreamData& out) const;

    Params params_;
    std::vector<double> tIn_;
    std::vector<double> times_;
    // Output sample k lies in [tIn_[index_[k]], tIn_[index_[k] + 1]] at fraction weight_[k] ∈ [0, 1];
    // weight_[k] is NaN when the sample falls inside a gap longer than max_gap.
    std::vector<long long> index_;
    std::vector<double> weight_;
};

}  // namespace athlos::signal
