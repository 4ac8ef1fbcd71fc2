#pragma once
// `butterworth`: low-/high-/band-pass or band-stop Butterworth filtering of selected columns of one
// uniformly sampled stream, zero-phase (forward-backward) by default.
//
// Column policy: by default every ordinary column is filtered. Quaternion groups (qw..qz with any
// prefix) and flag columns always pass through unchanged; naming one of them in `columns` is an
// error, because filtering a rotation component-wise or a categorical flag gives meaningless values.
// Columns not selected pass through unchanged.
// NaN policy: each NaN-free run of a column is filtered on its own (NaNs stay NaN), so streams
// resampled with max_gap can be filtered; short runs get correspondingly short padding.
// Sampling: rate = 1 / median interval; any interval more than 1 % off the median is refused
// (run `resample` first).
#include "core/processing/Processor.h"

#include "plugins/signal/Butterworth.h"

namespace athlos::signal {

class ButterworthProcessor : public Processor {
public:
    // Largest relative deviation of a sampling interval from the median that still counts as uniform.
    static constexpr double kUniformTolerance = 0.01;

    QString id() const override { return QStringLiteral("butterworth"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

private:
    struct Plan;
    Expected<Plan> makePlan(const RunContext& context) const;
};

}  // namespace athlos::signal
