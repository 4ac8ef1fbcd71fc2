#pragma once
// `body-model`: creates (or, re-run with new parameters, replaces) the athlete's body model table
// (BodyModel.h) from height, mass, sex, the anthropometric table, the sensors on the segments, equipment
// masses and an optional antenna position stream.
#include "core/processing/Processor.h"

namespace athlos::body {

class BodyModelProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("body-model"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::body
