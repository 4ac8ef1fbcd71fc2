#pragma once
// Helpers the inertial processors share: loading inputs, locating IMU column triples, building
// output streams.
#include "core/processing/Processor.h"

#include <memory>

namespace athlos::inertial {

struct LoadedStream {
    const Stream* stream = nullptr;
    std::shared_ptr<const StreamData> data;
};

// Samples of input `index`, or an error naming the input path.
Expected<LoadedStream> loadInput(const RunContext& context, int index);

// Index of column <prefix>x whose <prefix>y and <prefix>z follow it, or -1.
int tripleIndex(const StreamInfo& info, const QString& prefix);

struct ImuColumns {
    int acc = -1, gyr = -1, mag = -1;  // first of each x, y, z triple; mag -1 when absent
};
// acc_x..z and gyr_x..z are required (named error otherwise); mag optional unless requireMag.
Expected<ImuColumns> imuColumns(const StreamInfo& info, const QString& path, bool requireMag);

// An in-memory output stream (no provenance: the runner attaches it).
Stream makeStream(const QString& kind, const QString& frame, const QStringList& names, const QStringList& units,
                  StreamData data, QJsonObject attributes = {});

// The nominal sampling interval (median) or an error naming the stream.
Expected<double> samplingInterval(const StreamData& data, const QString& path);

}  // namespace athlos::inertial
