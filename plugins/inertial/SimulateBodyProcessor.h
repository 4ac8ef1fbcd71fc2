#pragma once
// `simulate-body`: eight IMUs on sacrum, sternum, thighs, shanks and feet with known mounts, a
// calibration block and walking or an alpine skiing run (BodySimulator.h), with the true segment
// orientations, joint angles, joint-centre positions and sensor-to-joint vectors — for validating
// `orientation` + `drift-reduction` + `joint-angles` (and later centre-of-mass estimates) end to end.
#include "core/processing/Processor.h"

namespace athlos::inertial {

class SimulateBodyProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-body"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::inertial
