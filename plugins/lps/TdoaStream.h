#pragma once
// The TDoA stream (kind "lps-tdoa") as the CSV importer produces it ↔ per-instant epochs.
//
// Stored form (core/io/TdoaLayout.h, written by the CSV importer from the long `t,beacon,dt` CSV):
// WIDE, one row per instant (strictly increasing t), one column "dt_<id>" (s) per beacon, NaN where
// that beacon did not receive the instant; attributes["beacon_ids"] lists the ids as text.
// The earlier long form (columns `beacon` and `dt`, t repeating, numeric ids or indices into
// "beacon_ids") is still accepted. Ids are matched to the beacon table by BeaconTable's rule.
#include "core/model/Stream.h"
#include "core/util/Expected.h"
#include "plugins/lps/Tdoa.h"

namespace athlos::lps {

struct EpochSet {
    std::vector<TdoaEpoch> epochs;
    long long readingsSkipped = 0;  // NaN dt
};

// Groups the rows into epochs and maps ids onto layout indices. Errors name the stream path and
// list ids missing from the beacon table.
Expected<EpochSet> epochsFromStream(const Stream& stream, const StreamData& data, const BeaconLayout& layout,
                                    const QString& path);

// The stream the CSV importer would produce from `t,beacon,dt` rows of these epochs (wide form,
// built by core's tdoaStreamFromSamples so that both stay identical).
Stream streamFromEpochs(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& layout,
                        const QString& name = QStringLiteral("tdoa"));

}  // namespace athlos::lps
