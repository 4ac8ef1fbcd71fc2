#pragma once
// `orientation`: sensor→earth (ENU) orientation from an IMU stream, one row per input sample, with
// the gyroscope bias estimate and rest / magnetic-disturbance flags. The default algorithm is the
// VQF-class OrientationFilter; strapdown, madgwick, mahony and kalman (seed 004) are baselines.
#include "core/processing/Processor.h"

namespace athlos::inertial {

class OrientationProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("orientation"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::inertial
