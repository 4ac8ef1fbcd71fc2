#include "ui/ProcessorLauncher.h"

#include "core/model/AnnotationJournal.h"

#include "core/model/Project.h"
#include "core/processing/ProcessorRegistry.h"
#include "ui/AnnotationEditor.h"
#include "ui/BackgroundTask.h"
#include "ui/ItemDescription.h"
#include "ui/MainWindow.h"
#include "ui/PanelLayout.h"
#include "ui/ProcessorDialog.h"

#include <QMenu>
#include <QStatusBar>

#include <memory>
#include <optional>

namespace athlos::ui {

ProcessorLauncher::ProcessorLauncher(MainWindow& window) : window_(window) {}

Expected<RunOutcome> ProcessorLauncher::run(const RunRequest& request) {
    std::shared_ptr<Project> project = window_.project_;
    if (!project) return makeError(tr("Open a project first."));
    if (window_.busy_) return makeError(tr("Another job is still running."));
    const auto processor = ProcessorRegistry::instance().find(request.processorId);
    if (!processor) return makeError(tr("Unknown processor '%1'.").arg(request.processorId));

    // The runner reads the inputs and finally inserts the outputs on the worker. Panel loads
    // must not read concurrently, and a panel must not show a stream that is about to be
    // replaced in place (re-running into the same output).
    window_.panels_->waitForLoads();
    window_.panels_->releaseStreamsOf(request.output);

    // The annotation state before the run, for the journal entries of what the run changes.
    std::map<QString, Annotations> annotationsBefore;
    for (const auto& [name, recording] : project->recordings()) annotationsBefore.emplace(name, recording.annotations);
    const QByteArray digestBefore = AnnotationJournal::stateDigest(*project);

    auto result = std::make_shared<std::optional<Expected<RunOutcome>>>();
    window_.setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        &window_, tr("Running %1…").arg(processor->name()),
        [project, processor, request, result](const Progress& progress) -> Status {
            *result = athlos::runProcessor(*project, *processor, request, progress);
            if (!result->value()) return result->value().error();
            return {};
        },
        window_.interactive_);
    window_.setBusy(false);
    if (outcome.cancelled && !outcome.status) {
        window_.statusBar()->showMessage(tr("%1 cancelled; the project is unchanged.").arg(processor->name()), 5000);
        return makeError(tr("Cancelled; the project is unchanged."));
    }
    if (!result->has_value())
        return makeError(outcome.status ? tr("The processor did not run.") : outcome.status.message());
    Expected<RunOutcome> run = std::move(**result);
    if (!run) return run;
    project->setModified(true);
    window_.projectModified();
    if (!run->annotated.isEmpty()) {
        QStringList recordings;
        for (const QString& path : run->annotated) recordings << ItemPath::parse(path).recording;
        recordings.removeDuplicates();
        window_.annotationEditor()->annotationsReplaced(recordings, annotationsBefore, digestBefore);
    }
    if (!run->written.isEmpty()) window_.selectItem(run->written.front());
    window_.statusBar()->showMessage(tr("%1 wrote %2").arg(processor->name(), run->written.join(QStringLiteral(", "))),
                                     8000);
    return run;
}

RunRequest ProcessorLauncher::rerunRequest(const QString& path) const {
    const Project* project = window_.project_.get();
    if (!project) return {};
    const Provenance* provenance = nullptr;
    if (const Stream* stream = project->stream(path))
        provenance = &stream->info().provenance;
    else if (const Table* table = project->table(path))
        provenance = &table->provenance;
    if (!provenance || !ItemDescription::isResult(*provenance)) return {};
    RunRequest request;
    request.processorId = provenance->processorId;
    for (const ProvenanceInput& input : provenance->inputs) request.inputs << input.name;
    request.parameters = provenance->parameters.toVariantMap();
    request.output = path;
    return request;
}

void ProcessorLauncher::openDialog(const RunRequest& prefill) {
    if (!window_.project_ || window_.busy_) return;
    ProcessorDialog dialog(window_, &window_);
    if (!prefill.processorId.isEmpty() && !dialog.setRequest(prefill)) {
        window_.showError(
            tr("Re-run"),
            tr("The processor '%1' is not available (is its plugin installed?).").arg(prefill.processorId));
        return;
    }
    dialog.exec();
}

void ProcessorLauncher::showContextMenu(const QString& path, const QPoint& globalPos, QAction* runProcessor) {
    if (!window_.project_ || window_.busy_) return;
    QMenu menu(&window_);
    const RunRequest rerun = rerunRequest(path);
    if (!rerun.processorId.isEmpty()) {
        menu.addAction(tr("Re-run with Changed Parameters…"), &window_, [this, rerun] { openDialog(rerun); });
        menu.addSeparator();
    }
    menu.addAction(runProcessor);
    menu.exec(globalPos);
}

}  // namespace athlos::ui
