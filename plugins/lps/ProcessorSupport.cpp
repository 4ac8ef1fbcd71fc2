#include "plugins/lps/ProcessorSupport.h"

#include "plugins/lps/BeaconTable.h"

#include <QCoreApplication>

namespace athlos::lps {

QString tr(const char* text) { return QCoreApplication::translate("athlos::lps", text); }

Expected<BeaconLayout> loadBeacons(const RunContext& context, int input) {
    const Table* table = context.table(input);
    if (!table) return makeError(QStringLiteral("beacon table '%1' is missing").arg(context.inputPath(input)));
    return layoutFromTable(*table, context.inputPath(input));
}

Expected<EpochSet> loadEpochs(const RunContext& context, int input, const BeaconLayout& layout) {
    const Stream* stream = context.stream(input);
    const QString path = context.inputPath(input);
    if (!stream) return makeError(QStringLiteral("TDoA stream '%1' is missing").arg(path));
    auto data = stream->data();
    if (!data) return makeError(QStringLiteral("cannot read TDoA stream '%1': %2").arg(path, data.message()));
    return epochsFromStream(*stream, **data, layout, path);
}

Expected<TrackGeometry> loadTrack(const RunContext& context) {
    auto track = TrackGeometry::resolve(context.project().geometry(), context.text(QStringLiteral("track")));
    if (!track) return makeError(QStringLiteral("track: %1").arg(track.message()));
    return track;
}

Stream trajectoryStream(const std::vector<double>& t, const std::vector<Vector3>& positions, const QString& kind,
                        const QString& name) {
    StreamInfo info;
    info.name = name;
    info.kind = kind;
    info.frame = QStringLiteral("lps");
    info.columns = {{QStringLiteral("x"), QStringLiteral("m")}, {QStringLiteral("y"), QStringLiteral("m")},
                    {QStringLiteral("z"), QStringLiteral("m")}};
    StreamData data(t.size(), 3);
    for (std::size_t k = 0; k < t.size(); ++k) {
        data.t[k] = t[k];
        for (int c = 0; c < 3; ++c) data.at(k, c) = positions[k](c);
    }
    return Stream(std::move(info), std::move(data));
}

}  // namespace athlos::lps
