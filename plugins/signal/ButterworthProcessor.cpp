#include "plugins/signal/ButterworthProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/signal/ColumnGroups.h"

#include <cmath>

namespace athlos::signal {

namespace {
constexpr Translator tr{"athlos::signal", "ButterworthProcessor"};
}  // namespace

struct ButterworthProcessor::Plan {
    InputSamples input;
    Butterworth::Params params;
    bool zeroPhase = true;
    std::vector<int> columns;
};

QString ButterworthProcessor::name() const { return tr("Butterworth filter"); }

QString ButterworthProcessor::description() const {
    return tr(
        "Low-pass, high-pass, band-pass or band-stop Butterworth filter of selected columns, zero-phase "
        "(forward-backward) by default. Needs uniform sampling (run resample first). Quaternion and flag "
        "columns pass through unchanged; NaN-free runs are filtered separately.");
}

ParameterSpecs ButterworthProcessor::parameters() const {
    ParameterSpec cutoff = ParameterSpec::number(
        QStringLiteral("cutoff"), 0.0, 0.0, std::numeric_limits<double>::infinity(), QStringLiteral("Hz"),
        tr("Cut-off frequency (-3 dB of one pass); the lower edge for bandpass/bandstop. Must be below "
           "half the sampling rate."));
    cutoff.defaultValue = QVariant();  // required
    ParameterSpec cutoffHigh = ParameterSpec::number(
        QStringLiteral("cutoff_high"), 0.0, 0.0, std::numeric_limits<double>::infinity(), QStringLiteral("Hz"),
        tr("Upper edge for bandpass/bandstop (required there, not allowed otherwise)."));
    cutoffHigh.defaultValue = QVariant();
    cutoffHigh.optional = true;
    return {
        ParameterSpec::choice(QStringLiteral("type"),
                              {QStringLiteral("lowpass"), QStringLiteral("highpass"), QStringLiteral("bandpass"),
                               QStringLiteral("bandstop")},
                              QStringLiteral("lowpass"), tr("Filter type.")),
        ParameterSpec::integer(
            QStringLiteral("order"), 2, 1, Butterworth::kMaxOrder,
            tr("Filter order n (band types have 2n poles). Zero-phase filtering doubles the effective order.")),
        cutoff,
        cutoffHigh,
        ParameterSpec::boolean(
            QStringLiteral("zero_phase"), true,
            tr("Filter forwards and backwards (no phase shift, squared magnitude: -6 dB at the cut-off); "
               "false = causal single pass.")),
        ParameterSpec::text(QStringLiteral("columns"), QString(),
                            tr("Comma-separated columns to filter; empty = all columns except quaternions and flags.")),
    };
}

QList<InputSpec> ButterworthProcessor::inputs() const {
    return {InputSpec{QStringLiteral("signal"), {}, false, false, tr("Uniformly sampled stream of any kind.")}};
}

QList<OutputSpec> ButterworthProcessor::outputs() const {
    // Empty kind: the output has the kind of the input.
    return {OutputSpec{QString(), false, QString(), tr("Filtered stream: same kind, frame and columns.")}};
}

Expected<ButterworthProcessor::Plan> ButterworthProcessor::makePlan(const RunContext& context) const {
    Plan plan;
    auto type = Butterworth::parseType(context.has(QStringLiteral("type")) ? context.text(QStringLiteral("type"))
                                                                           : QStringLiteral("lowpass"));
    if (!type) return type.error();
    plan.params.type = *type;
    plan.params.order = context.has(QStringLiteral("order")) ? context.integer(QStringLiteral("order")) : 2;
    if (!context.has(QStringLiteral("cutoff"))) return makeError(QStringLiteral("cutoff (Hz) is required"));
    plan.params.cutoff = context.number(QStringLiteral("cutoff"));
    const bool hasHigh = context.has(QStringLiteral("cutoff_high"));
    if (Butterworth::isBand(plan.params.type) && !hasHigh)
        return makeError(
            QStringLiteral("cutoff_high (Hz) is required for type=%1").arg(context.text(QStringLiteral("type"))));
    if (!Butterworth::isBand(plan.params.type) && hasHigh)
        return makeError(
            QStringLiteral("cutoff_high applies only to type=bandpass or bandstop; remove it or change type"));
    plan.params.cutoffHigh = hasHigh ? context.number(QStringLiteral("cutoff_high")) : 0.0;
    plan.zeroPhase = !context.has(QStringLiteral("zero_phase")) || context.flag(QStringLiteral("zero_phase"));

    auto input = context.samples(0);
    if (!input) return input.error();
    plan.input = *input;
    const StreamData& data = *plan.input.data;
    const QString& path = plan.input.path;

    // The filter is designed for one sampling rate; with jitter its cut-off would wander.
    auto medianInterval = plan.input.samplingInterval();
    if (!medianInterval) return medianInterval.error();
    const double interval = *medianInterval;
    for (std::size_t i = 1; i < data.rows(); ++i) {
        const double dt = data.t[i] - data.t[i - 1];
        if (!(std::abs(dt - interval) <= kUniformTolerance * interval))
            return makeError(
                QStringLiteral("stream '%1' is not uniformly sampled: the interval before row %2 is %3 s, "
                               "the median is %4 s (more than 1 % apart); run the resample processor first")
                    .arg(path)
                    .arg(i)
                    .arg(dt, 0, 'g', 6)
                    .arg(interval, 0, 'g', 6));
    }
    plan.params.samplingRate = 1.0 / interval;
    if (Status ok = Butterworth::check(plan.params); !ok) return ok.error();

    const StreamInfo& info = plan.input.stream->info();
    const QStringList names = info.columnNames();
    const ColumnGroups groups = ColumnGroups::detect(names);
    const QStringList requested = splitList(context.text(QStringLiteral("columns")));
    if (requested.isEmpty()) {
        plan.columns = groups.ordinary;
    } else {
        for (const QString& name : requested) {
            const int c = info.columnIndex(name);
            if (c < 0)
                return makeError(QStringLiteral("columns: stream '%1' has no column '%2' (it has: %3)")
                                     .arg(path, name, names.join(QStringLiteral(", "))));
            if (groups.isQuaternionColumn(c))
                return makeError(
                    QStringLiteral("columns: '%1' is a quaternion component; quaternions cannot be filtered "
                                   "component-wise (leave it out: it passes through unchanged)")
                        .arg(name));
            if (groups.isFlagColumn(c))
                return makeError(
                    QStringLiteral("columns: '%1' is a flag column (categorical) and cannot be filtered").arg(name));
            plan.columns.push_back(c);
        }
    }
    if (plan.columns.empty())
        return makeError(QStringLiteral("stream '%1' has no column to filter (only quaternions and flags)").arg(path));

    if (plan.zeroPhase) {
        const int pad = Butterworth(plan.params).defaultPadLength();
        if (data.rows() <= static_cast<std::size_t>(pad))
            return makeError(
                QStringLiteral("stream '%1' has %2 rows; zero-phase filtering of order %3 needs at least %4 "
                               "rows (padding of %5); use a longer stream, a lower order or zero_phase=false")
                    .arg(path)
                    .arg(data.rows())
                    .arg(plan.params.order)
                    .arg(pad + 1)
                    .arg(pad));
    }
    return plan;
}

Status ButterworthProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> ButterworthProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    const Butterworth filter(plan->params);
    StreamData data = *plan->input.data;
    const QStringList names = plan->input.stream->info().columnNames();
    Eigen::VectorXd column(static_cast<Eigen::Index>(data.rows()));
    const auto count = static_cast<double>(plan->columns.size());
    for (std::size_t i = 0; i < plan->columns.size(); ++i) {
        if (context.isCancelled()) return cancelledError();
        const int c = plan->columns[i];
        context.report(static_cast<double>(i) / count, QStringLiteral("filtering %1").arg(names.value(c)));
        column = data.column(c);  // strided → contiguous for the recursive filter
        filter.filterSegments(column, plan->zeroPhase);
        data.column(c) = column;
    }
    context.report(1.0);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), derivedStream(*plan->input.stream, std::move(data))});
    return outputs;
}

}  // namespace athlos::signal
