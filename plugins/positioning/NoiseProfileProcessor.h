#pragma once
// `noise-profile`: estimates the position filter's noise parameters Θ = (Q, R, α) once on up to
// eight training recordings of LPS fixes (one likelihood, eq. 4.13, summed over chunks of all of
// them) and stores them as a noise-profile table (NoiseProfile.h), which `position-filter
// --param noise=profile:<output>` applies to new recordings of the same system, as the thesis deploys
// its filter (§4.4). Parameters as position-filter's (the model and track the profile is for);
// the attributes record the training inputs, the objective and the number of evaluations.
#include "core/processing/Processor.h"
#include "plugins/positioning/PositionFilterProcessor.h"

namespace athlos::positioning {

class NoiseProfileProcessor : public Processor {
public:
    static constexpr int kMaxTrainingInputs = 8;

    QString id() const override { return QStringLiteral("noise-profile"); }
    QString name() const override;
    QString description() const override;
    QString version() const override { return QStringLiteral("1.0"); }
    ParameterSpecs parameters() const override;
    QList<InputSpec> inputs() const override;
    QList<OutputSpec> outputs() const override;
    Status prepare(const RunContext& context) const override;
    Expected<std::vector<ProcessorOutput>> run(const RunContext& context) const override;

private:
    PositionFilterProcessor filter_;
};

}  // namespace athlos::positioning
