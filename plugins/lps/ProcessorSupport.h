#pragma once
// Helpers the LPS processors share: reading beacon tables, TDoA streams and the track from the run
// context, parsing choices, and building output items.
#include "core/geometry/TrackGeometry.h"
#include "core/processing/Processor.h"
#include "plugins/lps/TdoaStream.h"

namespace athlos::lps {

Expected<BeaconLayout> loadBeacons(const RunContext& context, int input);
Expected<EpochSet> loadEpochs(const RunContext& context, int input, const BeaconLayout& layout);
// The track named by the `track` parameter: the project's geometry or a built-in.
Expected<TrackGeometry> loadTrack(const RunContext& context);

// The TdoaSimulator/TdoaPositioning output as a stream t, x, y, z (m) of the given kind.
Stream trajectoryStream(const std::vector<double>& t, const std::vector<Vector3>& positions, const QString& kind,
                        const QString& name);

// QCoreApplication::translate in the "athlos::lps" context.
QString tr(const char* text);

}  // namespace athlos::lps
