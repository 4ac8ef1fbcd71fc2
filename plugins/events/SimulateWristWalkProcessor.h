#pragma once
// `simulate-wrist-walk`: a wrist IMU and barometer during walking bouts and pauses, with the truth
// (WristWalkSimulator). No inputs. Outputs
//   <output>            imu:       acc_x..z (m/s²), gyr_x..z (rad/s);
//   <output>-barometer  barometer: pressure (Pa);
//   <output>-truth      reference: cadence (steps/min), speed (m/s), grade (1), altitude (m), walking (1).
#include "core/processing/Processor.h"

namespace athlos::events {

class SimulateWristWalkProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-wrist-walk"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::events
