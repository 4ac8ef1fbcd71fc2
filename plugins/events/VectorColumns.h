#pragma once
// The input columns of the events family's IMU processors (gait-events, gait-parameters,
// wrist-cadence): a vector is three adjacent columns <prefix>x, <prefix>y, <prefix>z.
#include "core/processing/Processor.h"

namespace athlos::events {

// Index of <prefix>x of input `input`, followed by <prefix>y and <prefix>z, each without a unit or in
// `unit`; otherwise an error naming the input and its columns, or the column, its unit and what
// `processor` expects.
Expected<int> vectorColumns(const RunContext& c, int input, const QString& prefix, const QString& unit,
                            const QString& processor);

}  // namespace athlos::events
