#pragma once
// Processor `alpine-turns`: a trunk or sacrum IMU during alpine skiing in, the turns between turn
// switches out (TurnSwitchDetector): predicted annotations "turn left" / "turn right" and a per-turn
// table (start, end, duration, side, peak yaw rate).
#include "core/processing/Processor.h"

namespace athlos::events {

class AlpineTurnsProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("alpine-turns"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::events
