#pragma once
// The inputs only LPS processors read: the beacon table, the TDoA stream (as epochs against that
// table) and the track named by the `track` parameter. Errors name the input (RunContext).
#include "core/geometry/TrackGeometry.h"
#include "core/processing/Processor.h"
#include "plugins/lps/TdoaStream.h"

namespace athlos::lps {

Expected<BeaconLayout> loadBeacons(const RunContext& context, int input);
Expected<EpochSet> loadEpochs(const RunContext& context, int input, const BeaconLayout& layout);
// The track named by the `track` parameter: the project's geometry or a built-in.
Expected<TrackGeometry> loadTrack(const RunContext& context);

}  // namespace athlos::lps
