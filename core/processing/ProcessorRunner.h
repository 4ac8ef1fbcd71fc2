#pragma once
// Runs a processor against a project the same way for the GUI, the CLI and pipelines:
// resolves and type-checks inputs, validates parameters, runs, refuses outputs that hold nothing
// (OutputChecks.h), attaches provenance and stores the outputs. On any error or cancellation the
// project is left unchanged.
#include "core/model/Project.h"
#include "core/processing/Processor.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QStringList>
#include <QVariantMap>

namespace athlos {

struct RunRequest {
    QString processorId;
    QStringList inputs;      // "rec/item" in the order of the processor's inputs()
    QString output;          // "rec/item" for the main output
    QVariantMap parameters;  // strings from the CLI or typed values from the GUI
};

struct RunOutcome {
    QStringList written;     // paths of the stored outputs (streams and tables)
    QStringList annotated;   // output paths whose annotations were replaced (see ProcessorOutput)
    QJsonObject parameters;  // validated parameters, as recorded in provenance
};

Expected<RunOutcome> runProcessor(Project& project, const Processor& processor, const RunRequest& request,
                                  const Progress& progress = {});

// runProcessor() in two steps, so that independent runs (e.g. one per athlete) can be computed on
// worker threads against the unchanged project and then stored one after the other on the owning
// thread. computeRun() only reads the project (thread-safe, samples load lazily under a lock) and
// returns the checked outputs with their provenance; storeRun() stores them as runProcessor() does.
struct ComputedRun {
    QString output;
    std::vector<ProcessorOutput> produced;
    Provenance provenance;
};
Expected<ComputedRun> computeRun(const Project& project, const Processor& processor, const RunRequest& request,
                                 const Progress& progress = {});
RunOutcome storeRun(Project& project, ComputedRun run);
// Looks the processor up in the registry first.
Expected<RunOutcome> runProcessor(Project& project, const RunRequest& request, const Progress& progress = {});

// A pipeline is a JSON document {"name": ..., "steps": [{"processor", "input" (string or array),
// "output", "params": {k: v}}, ...]}. Steps run in order; any failure leaves the project unchanged.
// The pipeline (with timestamps and outputs) is appended to the project's pipeline history.
Expected<QStringList> runPipeline(Project& project, const QJsonObject& pipeline, const Progress& progress = {});
// The run request of one pipeline step ({"processor", "input" (string or array), "output", "params"}).
RunRequest pipelineStepRequest(const QJsonObject& step);
// Where an output with the given suffix is stored: "<output>" or "<output>-<suffix>".
QString outputPathFor(const QString& output, const QString& suffix);
// The content hash recorded in provenance for a table input (SHA-256 over names and values, hex).
QByteArray tableHash(const Table& table);
// Parses a pipeline file, naming the file and the JSON error offset on failure.
Expected<QJsonObject> readPipelineFile(const QString& path);

}  // namespace athlos
