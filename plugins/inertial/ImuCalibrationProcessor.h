#pragma once
// `imu-calibration`: estimates (or, given a calibration table, re-applies) gyroscope offset,
// accelerometer offset/scale (static positions), magnetometer hard/soft iron (ellipsoid fit), checks
// saturation, and writes the calibrated stream plus the calibration table (<output>-calibration,
// with provenance from the runner).
#include "core/processing/Processor.h"

namespace athlos::inertial {

class ImuCalibrationProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("imu-calibration"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.1"); }  // 1.1: plausibility checks
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::inertial
