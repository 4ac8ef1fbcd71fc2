#include "plugins/positioning/NoiseProfileProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/positioning/NoiseProfile.h"

#include <QJsonArray>
#include <cmath>

namespace athlos::positioning {

namespace {
constexpr Translator tr{"athlos::positioning", "NoiseProfileProcessor"};

// position-filter parameters that do not change the estimate (output, smoothing, raw ranges) or
// are replaced by it (noise).
bool usedForProfile(const QString& name) {
    static const QStringList unused{QStringLiteral("noise"),         QStringLiteral("output_rate"),
                                    QStringLiteral("smoother"),      QStringLiteral("lag"),
                                    QStringLiteral("bridge_gap"),    QStringLiteral("r_range"),
                                    QStringLiteral("tag_height"),    QStringLiteral("range_offsets"),
                                    QStringLiteral("noise_spacing"), QStringLiteral("range_offset_sigma")};
    return !unused.contains(name);
}

}  // namespace

QString NoiseProfileProcessor::name() const { return tr("Noise profile"); }

QString NoiseProfileProcessor::description() const {
    return tr(
        "Estimates the position filter's process and measurement noise and outlier gate on up to eight training "
        "recordings of LPS fixes and stores them as a profile; position-filter applies it to new recordings with "
        "noise=profile:PATH.");
}

ParameterSpecs NoiseProfileProcessor::parameters() const {
    ParameterSpecs specs;
    for (const ParameterSpec& s : filter_.parameters())
        if (usedForProfile(s.name)) specs << s;
    return specs;
}

QList<InputSpec> NoiseProfileProcessor::inputs() const {
    QList<InputSpec> in;
    for (int i = 1; i <= kMaxTrainingInputs; ++i)
        in << InputSpec{QStringLiteral("training-%1").arg(i),
                        {QStringLiteral("lps-position")},
                        false,
                        i > 1,
                        tr("LPS fixes t, x, y (m) of one training recording from the system the profile is for.")};
    return in;
}

QList<OutputSpec> NoiseProfileProcessor::outputs() const {
    return {OutputSpec{kNoiseProfileKind, true, QString(),
                       tr("One row per noise parameter: parameter, value, unit; attribute model.")}};
}

Status NoiseProfileProcessor::prepare(const RunContext& context) const {
    auto params = filter_.readParams(context);
    if (!params) return params.error();
    for (int i = 0; i < context.inputCount(); ++i)
        if (context.stream(i))
            if (auto s = PositionFilterProcessor::positionSamples(context, i); !s) return s.error();
    return {};
}

Expected<std::vector<ProcessorOutput>> NoiseProfileProcessor::run(const RunContext& context) const {
    auto params = filter_.readParams(context);
    if (!params) return params.error();
    // Each recording contributes the same number of evenly spread chunks (PositionFilter::noiseChunks).
    std::vector<PositionSamples> chunks;
    QJsonArray training;
    for (int i = 0; i < context.inputCount(); ++i) {
        if (!context.stream(i)) continue;
        auto samples = PositionFilterProcessor::positionSamples(context, i);
        if (!samples) return samples.error();
        for (auto& c : PositionFilter::noiseChunks(*samples, context.number(QStringLiteral("noise_chunk")),
                                                   context.integer(QStringLiteral("noise_chunks"))))
            chunks.push_back(std::move(c));
        training.append(context.inputPath(i));
    }
    const Progress sub = context.progress().sub(0.0, 1.0);
    const auto estimate =
        PositionFilter::estimateNoise(*params, chunks, estimation::NoiseEstimator::Params{}, [&](double f) {
            sub.report(f, QStringLiteral("estimating noise"));
            return !context.isCancelled();
        });
    if (estimate.cancelled || context.isCancelled()) return cancelledError();
    if (!std::isfinite(estimate.objective))
        return makeError(
            QStringLiteral("the noise estimate did not converge on %1 (objective not finite); nothing "
                           "stored")
                .arg(training.size() == 1 ? training.first().toString() : QStringLiteral("the training recordings")));
    QJsonObject attributes{{QStringLiteral("training"), training},
                           {QStringLiteral("objective"), estimate.objective},
                           {QStringLiteral("evaluations"), estimate.evaluations},
                           {QStringLiteral("chunks"), static_cast<int>(chunks.size())}};
    ProcessorOutput out;
    out.item = noiseProfileTable(NoiseProfile{estimate.noise, params->model}, attributes);
    return std::vector<ProcessorOutput>{std::move(out)};
}

}  // namespace athlos::positioning
