#pragma once
// Processor `classify-actions`: an IMU stream in, predicted activity annotations out, from a model
// trained with `athlos train` and stored in the project (/models/<name>).
#include "core/processing/Processor.h"

namespace athlos::activity {

class ClassifyActionsProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("classify-actions"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::activity
