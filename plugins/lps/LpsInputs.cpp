#include "plugins/lps/LpsInputs.h"

#include "plugins/lps/BeaconTable.h"

namespace athlos::lps {

Expected<BeaconLayout> loadBeacons(const RunContext& context, int input) {
    auto table = context.requireTable(input);
    if (!table) return table.error();
    return layoutFromTable(**table, context.inputPath(input));
}

Expected<EpochSet> loadEpochs(const RunContext& context, int input, const BeaconLayout& layout) {
    auto tdoa = context.samples(input);
    if (!tdoa) return tdoa.error();
    return epochsFromStream(*tdoa->stream, *tdoa->data, layout, tdoa->path);
}

Expected<TrackGeometry> loadTrack(const RunContext& context) {
    auto track = TrackGeometry::resolve(context.project().geometry(), context.text(QStringLiteral("track")));
    if (!track) return makeError(QStringLiteral("track: %1").arg(track.message()));
    return track;
}

}  // namespace athlos::lps
