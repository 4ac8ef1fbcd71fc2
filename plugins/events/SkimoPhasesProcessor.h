#pragma once
// Processor `skimo-phases`: a ski IMU during a ski-mountaineering ascent in, the motionless phases
// (local minima of the drifting speed, drift on their central 50 %, refined where the speed is below
// 0.1 m/s; Fasel 2017 ch. 4) and the cycles between them out: a per-cycle table (duration, speed,
// length, elevation, slope) with the elevation gain, and predicted annotations.
#include "core/processing/Processor.h"

namespace athlos::events {

class SkimoPhasesProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("skimo-phases"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::events
