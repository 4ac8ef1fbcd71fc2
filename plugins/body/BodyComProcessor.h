#pragma once
// `body-com`: joint centres and centre of mass relative to the lumbar joint centre through the kinematic
// chain (BodyCom.h), the fore-aft CoM position against the feet and, when the body model attaches a GNSS or
// LPS antenna to a segment, the absolute CoM (antenna position + chain offset, Fasel 2017 ch. 8) and its speed.
#include "core/processing/Processor.h"

namespace athlos::body {

class BodyComProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("body-com"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;
};

}  // namespace athlos::body
