#include "ScaleProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"

namespace example {

namespace {
// Texts shown to users go through the family's translation context.
constexpr athlos::Translator tr{"athlos::example"};
}  // namespace

QString ScaleProcessor::name() const { return tr("Scale"); }

QString ScaleProcessor::description() const {
    return tr("Multiplies every column of a stream by a constant factor (an example plugin).");
}

athlos::ParameterSpecs ScaleProcessor::parameters() const {
    // The runner checks ranges and fills in defaults before run(); the CLI (--param factor=2)
    // and the GUI's dialog are built from this list.
    return {athlos::ParameterSpec::number(QStringLiteral("factor"), 1.0, -1e9, 1e9, QStringLiteral("1"),
                                          tr("Factor every value is multiplied by."))};
}

QList<athlos::InputSpec> ScaleProcessor::inputs() const {
    return {athlos::InputSpec{QStringLiteral("signal"), {}, false, false, tr("Any stream.")}};
}

QList<athlos::OutputSpec> ScaleProcessor::outputs() const {
    // Empty kind: the output has the kind of the input.
    return {athlos::OutputSpec{QString(), false, QString(), tr("The scaled stream: same kind, frame and columns.")}};
}

athlos::Expected<std::vector<athlos::ProcessorOutput>> ScaleProcessor::run(const athlos::RunContext& context) const {
    // Errors name the input ("input 'rec/imu' (signal): …"); the runner prefixes the processor id.
    auto input = context.samples(0);
    if (!input) return input.error();
    athlos::StreamData data = *input->data;
    data.matrix() *= context.number(QStringLiteral("factor"));
    context.report(1.0);
    // The runner stores the output under --output and attaches provenance; a processor never
    // writes into the project itself.
    std::vector<athlos::ProcessorOutput> outputs;
    outputs.push_back({QString(), athlos::derivedStream(*input->stream, std::move(data))});
    return outputs;
}

}  // namespace example
