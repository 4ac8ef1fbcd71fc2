#pragma once
// `simulate-imu-gnss`: no inputs; a simulated football session (ImuGnssSimulator): the IMU stream
// at <output>, GNSS at <output>-gnss and the truth at <output>-truth.
#include "core/processing/Processor.h"

namespace athlos::inertial {

class SimulateImuGnssProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-imu-gnss"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::inertial
