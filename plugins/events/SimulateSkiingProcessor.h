#pragma once
// `simulate-skiing`: IMU recordings with ground truth from SkiingSimulator.h — cross-country diagonal
// stride (ski IMU at <output>, pole IMU at <output>-pole), a ski-mountaineering ascent (ski IMU) or
// an alpine run (sacrum IMU) — and the true cycles or turns at <output>-truth, for validating
// xc-skiing-cycles, skimo-phases and alpine-turns end to end.
#include "core/processing/Processor.h"

namespace athlos::events {

class SimulateSkiingProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("simulate-skiing"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::events
