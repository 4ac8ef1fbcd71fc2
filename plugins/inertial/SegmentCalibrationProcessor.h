#pragma once
// `segment-calibration`: functional sensor-to-segment calibration (SegmentCalibration.h) of up to
// three IMUs from a static upright window and a squat window; writes a segment-calibration table
// (segment, qw..qz) that joint-angles reads.
#include "core/processing/Processor.h"

namespace athlos::inertial {

class SegmentCalibrationProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("segment-calibration"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::inertial
