#pragma once
// Whether a project already holds what a pipeline would compute, judged from the provenance the
// runner stores with every output (ProcessorRunner.h): each step's outputs carry the step's
// processor id and version, the same validated parameters (defaults filled in) and inputs whose
// content hashes are those of the inputs as they are now. `athlos batch` skips such projects.
#include "core/model/Project.h"
#include "core/util/Expected.h"

#include <QJsonObject>
#include <QString>

namespace athlos {

struct PipelineCheck {
    bool done = false;
    QString reason;  // when not done: the first step that would change something, and why
};

// Errors for a malformed pipeline (no steps, unknown processor, invalid parameters).
Expected<PipelineCheck> checkPipelineDone(const Project& project, const QJsonObject& pipeline);

}  // namespace athlos
