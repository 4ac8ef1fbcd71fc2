#pragma once
// `velocity-reset`: velocity and position of one foot- or ski-mounted sensor in the earth frame,
// with the velocity reset to zero at every zero-velocity phase (the foot's stance, the ski's thrust)
// and the linear drift removed between them (VelocityReset.h; Fasel 2017 ch. 2–4). Inputs: the
// sensor's orientation (e.g. from `orientation`, or a drift-reduction output) and its IMU stream.
// Outputs: a trajectory stream (x, y, z, vx, vy, vz, zero_velocity) at --output and the
// zero-velocity phases as a table at <output>-zero-velocity. Run it only for the sensors that need
// it: drift-reduction itself does no velocity work (its speed target).
#include "core/processing/Processor.h"

namespace athlos::inertial {

class VelocityResetProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("velocity-reset"); }
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
