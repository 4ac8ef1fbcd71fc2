#pragma once
// `lps-calibration`: beacon positions from a calibration walk and an initial beacon table
// (thesis §3.1, LpsCalibration.h). Inputs: TDoA stream of the walk, initial beacon table (any
// recording), optionally a surveyed reference table (then η of Eqns. 3.6–3.7 is reported).
// Outputs: the calibrated beacon table (same ids; the reference node stays where the initial table
// puts it) and, with suffix "report", a table per beacon (rms_residual, readings, shift) whose
// attributes hold nRMSR before/after, η, the walk height, the counts and the gauge: gauge (guess or
// track, the one used), gauge_reason, gauge_rotation (rad, applied on top of the guess-based
// rotation), gauge_fit_rms (m), gauge_fit_coverage, gauge_fit_inliers, gauge_lateral_offset (m).
#include "core/processing/Processor.h"

namespace athlos::lps {

class LpsCalibrationProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("lps-calibration"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::lps
