#pragma once
// Processor `gait-summary`: the stride tables of gait-parameters (one foot, or both) in; one table
// with a row per foot (and "both" for two feet): the strides used, and per parameter the steady-state
// mean, standard deviation, coefficient of variation and, in the "both" row, the symmetry index
// (GaitSummary.h).
#include "core/processing/Processor.h"

namespace athlos::events {

class GaitSummaryProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("gait-summary"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::events
