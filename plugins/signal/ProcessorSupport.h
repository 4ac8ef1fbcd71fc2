#pragma once
// Small helpers the signal processors share: reading the single input stream and building an
// output stream that keeps the input's kind, frame, columns and attributes.
#include "core/processing/Processor.h"

#include <memory>

namespace athlos::signal {

struct InputSamples {
    const Stream* stream = nullptr;
    std::shared_ptr<const StreamData> data;
};

// The samples of input 0, or an error naming the input path.
Expected<InputSamples> loadInput(const RunContext& context);

// A new in-memory stream like input (no provenance: the runner attaches it) holding data.
Stream derivedStream(const Stream& input, StreamData data);

// Splits a comma-separated list, trimming blanks and dropping empty entries.
QStringList splitList(const QString& text);

}  // namespace athlos::signal
