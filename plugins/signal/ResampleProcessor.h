#pragma once
// `resample`: one stream of any kind onto a uniform grid at `rate` Hz (see Resampler.h for the
// interpolation of ordinary, quaternion and flag columns). The output keeps kind, frame and
// columns and records attributes.sampling_rate.
#include "core/processing/Processor.h"

#include "plugins/signal/Resampler.h"

namespace athlos::signal {

class ResampleProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("resample"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

private:
    Expected<Resampler::Params> readParams(const RunContext& context) const;
};

}  // namespace athlos::signal
