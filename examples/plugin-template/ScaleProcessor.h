#pragma once
// `example-scale`: multiplies every column of a stream by a factor. A minimal processor to start
// from: one parameter, one input, one output of the input's kind.
#include "core/processing/Processor.h"

namespace example {

class ScaleProcessor : public athlos::Processor {
public:
    QString id() const override { return QStringLiteral("example-scale"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }  // bump when results change
    athlos::ParameterSpecs parameters() const override;
    QList<athlos::InputSpec> inputs() const override;
    QList<athlos::OutputSpec> outputs() const override;
    athlos::Expected<std::vector<athlos::ProcessorOutput>> run(const athlos::RunContext& context) const override;
};

}  // namespace example
