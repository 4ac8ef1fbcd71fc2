#include "core/processing/OutputStreams.h"

namespace athlos {

Columns columnsOf(const QStringList& names, const QStringList& units) {
    Columns columns;
    columns.reserve(std::size_t(names.size()));
    for (int i = 0; i < names.size(); ++i) columns.push_back({names[i], units.value(i, QStringLiteral("1"))});
    return columns;
}

Stream derivedStream(const Stream& input, StreamData data) {
    StreamInfo info = input.info();
    info.provenance = {};
    info.contentHash.clear();
    return Stream(std::move(info), std::move(data));
}

Stream outputStream(const QString& kind, const QString& frame, Columns columns, StreamData data,
                    QJsonObject attributes) {
    StreamInfo info;
    info.kind = kind;
    info.frame = frame;
    info.columns = std::move(columns);
    info.attributes = std::move(attributes);
    return Stream(std::move(info), std::move(data));
}

StreamData samplesOnTimeAxis(const StreamData& input, int columns) {
    StreamData out(input.rows(), columns);
    out.t = input.t;
    return out;
}

}  // namespace athlos
