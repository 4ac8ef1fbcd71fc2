#pragma once
// Missing samples of a foot IMU (a cell left empty on export is NaN): the gait processors integrate
// every sample, and one NaN would spread through the whole smoothed trajectory. A sample is complete
// when all its columns are finite; a run of incomplete samples is bridged, column by column, by linear
// interpolation between the complete samples on either side when the interval between those is at most
// `maxGap` (at the start or end of the recording: the nearest complete sample is held). Values that are
// finite inside a run are kept. A longer run cannot be bridged by integration and is an error that
// names its times and rows.
#include "core/util/Expected.h"

#include <cstddef>
#include <vector>

namespace athlos::events {

struct GapFill {
    std::size_t runs = 0;     // runs of incomplete samples bridged
    std::size_t samples = 0;  // incomplete samples filled
    double longest = 0.0;     // s, longest interval bridged
};

// values: `columns` doubles per sample, row-major, one row per t. Filled in place; unchanged on error.
Expected<GapFill> fillShortGaps(std::vector<double>& values, std::size_t columns, const std::vector<double>& t,
                                double maxGap);

}  // namespace athlos::events
