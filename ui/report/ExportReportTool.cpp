// File ▸ Export report…: the coach's PDF (SessionReport) from the GUI. Session metrics missing for
// an athlete are computed on a worker (both cores) behind a progress dialog with Cancel and stored
// in the project; the PDF is then drawn on the GUI thread (its plots are widgets), page by page
// behind the same kind of dialog. A cancelled or failed report changes neither the project nor an
// existing PDF.
#include "ui/BackgroundTask.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/report/SessionReport.h"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QMessageBox>

namespace athlos::ui {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("athlos::ui::ExportReportTool", text); }

void exportReport(Workspace& workspace) {
    Project* project = workspace.project();
    QWidget* parent = workspace.window();
    if (!project) {
        QMessageBox::information(parent, tr("Export report"), tr("Open a project first."));
        return;
    }
    // The recording: the one selected in the tree, else every recording with athletes.
    const QString recording = ItemPath::parse(workspace.currentItem() + QStringLiteral("/x")).recording;
    auto athletes = SessionReport::athletes(*project, project->recording(recording) ? recording : QString());
    if (!athletes) {
        QMessageBox::warning(parent, tr("Export report"), athletes.message());
        return;
    }
    const QString suggested = QFileInfo(project->path()).absolutePath() + QLatin1Char('/') +
                              QFileInfo(project->path()).completeBaseName() + QStringLiteral("-report.pdf");
    const QString path = QFileDialog::getSaveFileName(parent, tr("Export report"), suggested, tr("PDF (*.pdf)"));
    if (path.isEmpty()) return;

    // 1. Missing metrics computed on a worker (it only reads the project); stored here, on the GUI
    // thread, and only when all succeeded.
    std::vector<ComputedRun> runs;
    const Project* source = project;
    const QList<ReportAthlete> list = *athletes;
    const auto outcome = BackgroundTask::run(parent, tr("Computing session metrics…"), [&](const Progress& progress) {
        auto computed = SessionReport::computeMissingRuns(*source, list, {}, progress);
        if (!computed) return Status(computed.error());
        runs = std::move(*computed);
        return Status();
    });
    if (outcome.cancelled) return;
    if (!outcome.status) {
        QMessageBox::warning(parent, tr("Export report"), outcome.status.message());
        return;
    }
    for (auto& run : runs) storeRun(*project, std::move(run));
    if (!runs.empty()) workspace.projectModified();

    // 2. The PDF on the GUI thread, a page at a time.
    const auto written = BackgroundTask::runHere(parent, tr("Writing the report…"), [&](const Progress& progress) {
        return SessionReport::writePdf(*project, list, path, progress);
    });
    if (!written.status && !written.cancelled)
        QMessageBox::warning(parent, tr("Export report"), written.status.message());
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("export-report"), QT_TRANSLATE_NOOP("Tools", "Export report…"),
                      QT_TRANSLATE_NOOP("Tools", "File"), exportReport});

}  // namespace athlos::ui
