#pragma once
// `simulate-gates`: a simulated giant-slalom run with magnets at the gates and its ground truth (see
// GateRunSimulator.h). No inputs. Outputs
//   <output>        imu:        acc_x..z (m/s²), gyr_x..z (rad/s), mag_x..z (µT), sacrum sensor frame;
//   <output>-truth  trajectory: x, y, z (m), vx, vy, vz, speed (m/s), ENU;
//   <output>-gates  gates table: id, east, north, up (m) — the surveyed magnet positions.
#include "core/processing/Processor.h"

namespace athlos::positioning {

class SimulateGatesProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-gates"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::positioning
