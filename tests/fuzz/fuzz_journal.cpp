// Fuzz target: the annotation journal (<project>.journal, one JSON edit per line): read, the
// digest check and the replay of its edits onto a small in-memory project.
#include "FuzzInput.h"
#include "core/model/AnnotationJournal.h"
#include "core/model/Project.h"

using namespace athlos;

namespace {

// The project the journal applies to: the base state of the seed journal (make_seeds.cpp), one
// recording "rec" without annotations and the class "tackle", so the seed's edits all apply.
// Never saved; only its path matters (the journal is <path>.journal).
std::unique_ptr<Project> makeProject(const QString& path) {
    auto project = Project::create(path, QStringLiteral("football"));
    project->ensureRecording(QStringLiteral("rec"));
    project->annotationClasses() << QStringLiteral("tackle");
    return project;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const QString projectPath = fuzz::scratchDir() + QStringLiteral("/p-%1.athlos").arg(fuzz::InputFile::nextNumber());
    const auto journal = fuzz::InputFile::at(AnnotationJournal::pathFor(projectPath), fuzz::bytes(data, size));
    auto project = makeProject(projectPath);
    (void)AnnotationJournal::read(journal.path());
    (void)AnnotationJournal::belongsTo(*project);
    if (AnnotationJournal::replay(*project)) (void)AnnotationJournal::stateDigest(*project);
    return 0;
}
