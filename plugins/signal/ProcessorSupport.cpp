#include "plugins/signal/ProcessorSupport.h"

namespace athlos::signal {

Expected<InputSamples> loadInput(const RunContext& context) {
    const QString path = context.inputCount() > 0 ? context.inputPath(0) : QString();
    const Stream* stream = context.stream(0);
    if (!stream) return makeError(QStringLiteral("input stream '%1' is missing").arg(path));
    auto data = stream->data();
    if (!data) return makeError(QStringLiteral("cannot read input stream '%1': %2").arg(path, data.message()));
    return InputSamples{stream, std::move(data).value()};
}

Stream derivedStream(const Stream& input, StreamData data) {
    StreamInfo info = input.info();
    info.provenance = {};
    info.contentHash.clear();
    return Stream(std::move(info), std::move(data));
}

QStringList splitList(const QString& text) {
    QStringList items;
    for (const QString& item : text.split(QLatin1Char(','))) {
        const QString trimmed = item.trimmed();
        if (!trimmed.isEmpty()) items << trimmed;
    }
    return items;
}

}  // namespace athlos::signal
