#pragma once
// Building a processor's output streams. Outputs carry no provenance and no stale content hash: the
// runner attaches provenance (processor, version, parameters, inputs) when it stores them.
#include "core/model/Stream.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace athlos {

// Columns from parallel lists of names and units ("1" where a unit is missing).
Columns columnsOf(const QStringList& names, const QStringList& units);

// A stream like `input` (kind, frame, columns, attributes) holding new samples, e.g. a filtered
// or resampled copy.
Stream derivedStream(const Stream& input, StreamData data);

// A stream of its own kind, frame and columns, e.g. orientations computed from an IMU stream.
Stream outputStream(const QString& kind, const QString& frame, Columns columns, StreamData data,
                    QJsonObject attributes = {});

// Samples on the time axis of `input` (same t) with `columns` columns, all zero: the usual start
// of an output that has one row per input row.
StreamData samplesOnTimeAxis(const StreamData& input, int columns);

}  // namespace athlos
