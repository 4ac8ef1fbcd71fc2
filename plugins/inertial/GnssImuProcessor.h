#pragma once
// `gnss-imu`: loosely-coupled GNSS/IMU fusion (seed 004) in a local ENU frame from the first fix,
// output at the IMU rate with speed and distance. GNSS may be geodetic (lat, lon, alt[, vn, ve, vd])
// or local (x, y, z[, vx, vy, vz]).
#include "core/processing/Processor.h"

namespace athlos::inertial {

class GnssImuProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("gnss-imu"); }
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
