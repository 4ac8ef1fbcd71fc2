#include "plugins/signal/ResampleProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"

#include <limits>

namespace athlos::signal {

namespace {
constexpr Translator tr{"athlos::signal", "ResampleProcessor"};
}  // namespace

QString ResampleProcessor::name() const { return tr("Resample"); }

QString ResampleProcessor::description() const {
    return tr(
        "Resamples a stream onto a uniform time grid: linear, nearest or cubic interpolation of ordinary "
        "columns, SLERP of quaternions (qw,qx,qy,qz, any prefix), nearest neighbour for flag columns; "
        "optionally NaN inside input gaps longer than max_gap.");
}

ParameterSpecs ResampleProcessor::parameters() const {
    const double inf = std::numeric_limits<double>::infinity();
    ParameterSpec rate = ParameterSpec::number(QStringLiteral("rate"), 0.0, 0.0, inf, QStringLiteral("Hz"),
                                               tr("Output sampling rate (> 0)."));
    rate.defaultValue = QVariant();  // required
    return {
        rate,
        ParameterSpec::choice(
            QStringLiteral("method"), {QStringLiteral("linear"), QStringLiteral("nearest"), QStringLiteral("cubic")},
            QStringLiteral("linear"),
            tr("Interpolation of ordinary columns. cubic = local cubic Hermite (Catmull-Rom style, exact for "
               "quadratics). Quaternions always use SLERP (nearest sample for nearest), flags nearest.")),
        ParameterSpec::number(QStringLiteral("max_gap"), 0.0, 0.0, inf, QStringLiteral("s"),
                              tr("Output samples inside an input gap longer than this become NaN; 0 = off.")),
        ParameterSpec::boolean(
            QStringLiteral("align"), false,
            tr("Put the grid on integer multiples of 1/rate instead of starting at the first sample.")),
    };
}

QList<InputSpec> ResampleProcessor::inputs() const {
    return {InputSpec{QStringLiteral("signal"), {}, false, false, tr("Stream of any kind, possibly non-uniform.")}};
}

QList<OutputSpec> ResampleProcessor::outputs() const {
    // Empty kind: the output has the kind of the input.
    return {OutputSpec{QString(), false, QString(), tr("Uniformly sampled stream: same kind, frame and columns.")}};
}

Expected<Resampler::Params> ResampleProcessor::readParams(const RunContext& context) const {
    if (!context.has(QStringLiteral("rate"))) return makeError(QStringLiteral("rate (Hz) is required"));
    Resampler::Params params;
    params.rate = context.number(QStringLiteral("rate"));
    auto method = Resampler::parseMethod(context.has(QStringLiteral("method")) ? context.text(QStringLiteral("method"))
                                                                               : QStringLiteral("linear"));
    if (!method) return method.error();
    params.method = *method;
    params.maxGap = context.number(QStringLiteral("max_gap"));  // absent → 0 = off
    params.align = context.flag(QStringLiteral("align"));
    return params;
}

Status ResampleProcessor::prepare(const RunContext& context) const {
    auto params = readParams(context);
    if (!params) return params.error();
    if (Status ok = Resampler::checkParams(*params); !ok) return ok;
    auto input = context.samples(0);
    if (!input) return input.error();
    if (Status ok = Resampler::check(*params, input->data->t); !ok) return input->error(ok.message());
    return {};
}

Expected<std::vector<ProcessorOutput>> ResampleProcessor::run(const RunContext& context) const {
    if (Status ok = prepare(context); !ok) return ok.error();
    const Resampler::Params params = *readParams(context);
    const InputSamples input = *context.samples(0);
    const StreamData& in = *input.data;
    const QStringList names = input.stream->info().columnNames();
    const ColumnGroups groups = ColumnGroups::detect(names);

    context.report(0.0, QStringLiteral("building the time grid"));
    const Resampler resampler(params, in.t);
    StreamData out = resampler.makeOutput(in.columns);

    // One unit of work per column group, each followed by a progress report and a cancel check.
    const auto units = static_cast<double>(groups.ordinary.size() + groups.flags.size() + groups.quaternions.size());
    double done = 0.0;
    auto step = [&](const QString& what) {
        done += 1.0;
        context.report(done / units, what);
        return !context.isCancelled();
    };
    if (context.isCancelled()) return cancelledError();
    for (int c : groups.ordinary) {
        resampler.resampleOrdinary(in, c, out);
        if (!step(names.value(c))) return cancelledError();
    }
    for (int c : groups.flags) {
        resampler.resampleFlag(in, c, out);
        if (!step(names.value(c))) return cancelledError();
    }
    for (const auto& q : groups.quaternions) {
        resampler.resampleQuaternion(in, q, out);
        if (!step(names.value(q[0]).chopped(2) + QStringLiteral("q"))) return cancelledError();
    }

    Stream result = derivedStream(*input.stream, std::move(out));
    result.info().attributes.insert(QStringLiteral("sampling_rate"), params.rate);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(result)});
    return outputs;
}

}  // namespace athlos::signal
