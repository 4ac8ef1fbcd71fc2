#pragma once
// `anchor-smoother`: sacrum trajectory from an IMU with magnetometer, its orientation stream and the
// gates table (Fasel thesis ch. 9; AnchorPipeline → GateDetector + AnchorSmoother). Inputs: imu
// (acc, gyr, mag), orientation (one row per imu sample), gates table (id, east, north, up). Outputs
//   <output>            trajectory: x, y, z (m), vx, vy, vz, speed (m/s) in the gates' frame;
//   <output>-crossings  table: one row per detected gate crossing (time, matched gate, distance
//                       from the field, side, residual, and the pass-0 gate estimate for averaging).
#include "core/processing/Processor.h"

namespace athlos::positioning {

class AnchorSmootherProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("anchor-smoother"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::positioning
