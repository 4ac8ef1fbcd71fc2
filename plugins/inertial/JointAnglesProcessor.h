#pragma once
// `joint-angles`: knee, hip, ankle or trunk angles (ISB / Grood & Suntay, JointAngles.h) from the
// orientation streams of the proximal and distal sensors, with the sensors' mounts on their segments
// (parameters, or a segment-calibration table), one row per proximal sample (the distal stream is
// SLERPed onto the proximal's time stamps).
#include "core/processing/Processor.h"

namespace athlos::inertial {

class JointAnglesProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("joint-angles"); }
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
