// Fuzz target: the project reader. The input is written to a temporary .athlos file and opened
// with Project::open (structure and metadata); then every stream's samples are loaded and the
// annotation digest is computed, as the GUI does on open.
//
// libhdf5 itself may crash on some damaged files (e.g. in H5HG_read for variable-length string
// attributes); Project::open is meant to refuse those without crashing (issue #11).
#include "FuzzInput.h"
#include "core/model/AnnotationJournal.h"
#include "core/model/Project.h"

using namespace athlos;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const fuzz::InputFile input(data, size, QStringLiteral(".athlos"));
    auto project = Project::open(input.path());
    if (!project) return 0;
    for (const QString& path : (*project)->streamPaths()) {
        const Stream* stream = (*project)->stream(path);
        if (!stream) continue;
        (void)stream->info().columnNames();
        (void)stream->data();
    }
    for (const QString& path : (*project)->tablePaths())
        if (const Table* table = (*project)->table(path)) (void)table->rows();
    (void)AnnotationJournal::stateDigest(**project);
    return 0;
}
