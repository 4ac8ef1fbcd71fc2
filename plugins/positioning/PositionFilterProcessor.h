#pragma once
// `position-filter`: robust Kalman filtering of an lps-position stream (t, x, y) with optional track
// constraints (thesis ch. 4, seed 001). Outputs
//   <output>           trajectory on the output grid: x, y (m), speed (m/s), heading (rad),
//                      turn_rate (rad/s), accel (m/s²), outlier (1 if an input sample flagged as an
//                      outlier falls in this output sample's interval [t − Δ/2, t + Δ/2), Δ = 1/output_rate;
//                      at the input times without output_rate: the sample's own flag);
//   <output>-outliers  per input sample: outlier (0/1), mahalanobis (d², dimensionless).
// noise=auto estimates Q, R and α from the input itself (eq. 4.13) and records them as attributes;
// noise=profile:PATH takes them from a noise-profile table (NoiseProfile.h).
// With raw two-way ranges (kind lps-range) and a beacon table as second input the filter is tightly
// coupled (RangeFilter.h): one update per range, per-measurement gating; the trajectory then also
// has sd_x, sd_y (m) and the outliers stream one row per range.
#include "core/processing/Processor.h"
#include "plugins/positioning/NoiseProfile.h"
#include "plugins/positioning/PositionFilter.h"

#include <optional>

namespace athlos::positioning {

class PositionFilterProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("position-filter"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.2"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

    // Shared with noise-profile: the parameters as filter settings, the valid fixes of input `index`,
    // and the profile named by noise=profile:PATH (nullopt for other noise settings; an error when the
    // table is missing, malformed or was estimated for another model).
    Expected<PositionFilter::Params> readParams(const RunContext& context) const;
    static Expected<PositionSamples> positionSamples(const RunContext& context, int index);
    static Expected<std::optional<NoiseProfile>> noiseProfile(const RunContext& context, ModelKind model);
};

}  // namespace athlos::positioning
