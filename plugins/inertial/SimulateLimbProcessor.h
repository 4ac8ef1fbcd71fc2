#pragma once
// `simulate-limb`: pelvis, thigh and shank IMUs with known mounts and reference hip and knee angles
// (LimbSimulator.h), for validating `orientation` + `joint-angles` end to end.
#include "core/processing/Processor.h"

namespace athlos::inertial {

class SimulateLimbProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-limb"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::inertial
