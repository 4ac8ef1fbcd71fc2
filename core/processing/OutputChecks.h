#pragma once
// The run contract's last check before anything is stored (issue #13, item 8: no silent wrong
// answers): a run whose stream or table output holds nothing useful fails with the reason instead
// of storing it. Refused: a stream with no rows, a stream in which every value is NaN or infinite
// (a solver that never converged), a table with no rows. Annotation outputs may be empty (no events
// found is an answer). The runner prefixes the processor id and stores nothing, so the project is
// left unchanged.
#include "core/processing/Processor.h"

namespace athlos {

// `path` is where the item would be stored ("rec/name[-suffix]"), named in the error.
Status checkOutputUseful(const ProcessorOutput& output, const QString& path);

}  // namespace athlos
