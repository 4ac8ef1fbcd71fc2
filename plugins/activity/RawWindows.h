#pragma once
// Raw windows for the 1D CNN (seed 000 §5.2: the DCNN reads the raw 3 × 157 window): the window's
// input columns resampled linearly onto `length` equally spaced times from tStart to tEnd, channel
// major (C × L floats), so recordings at 50 and 52 Hz give windows of one shape. Also the .npy
// writer of `athlos train --export-windows` (NumPy format 1.0, little-endian, C order).
#include "core/model/StreamData.h"
#include "core/util/Expected.h"

#include <QString>
#include <vector>

namespace athlos::activity {

// out: columns.size() × length floats. Times outside the stream take its first or last sample.
void rawWindow(const StreamData& data, const std::vector<int>& columns, double tStart, double tEnd, int length,
               float* out);

// Writes an array of float32 (dtype "<f4") or int32 ("<i4") with the given shape as a .npy file.
Status writeNpy(const QString& path, const std::vector<long long>& shape, const float* values);
Status writeNpy(const QString& path, const std::vector<long long>& shape, const int* values);

}  // namespace athlos::activity
