// File ▸ Export gait report…: the gait report (GaitReport) of the current recording's stride tables.
// The dialog picks the tables (one per foot) and the steady-state parameters; the summary is computed
// in memory (the project is not changed) and the PDF drawn on the GUI thread behind a progress dialog
// with Cancel, which leaves an existing PDF as it was.
#include "ui/BackgroundTask.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/report/GaitReport.h"
#include "ui/report/GaitReportDialog.h"

#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>

namespace athlos::ui {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("athlos::ui::ExportGaitReportTool", text); }

void exportGaitReport(Workspace& workspace) {
    Project* project = workspace.project();
    QWidget* parent = workspace.window();
    if (!project) {
        QMessageBox::information(parent, tr("Export gait report"), tr("Open a project first."));
        return;
    }
    // The recording selected in the tree when it has stride tables, else the only one that has any
    // (several: the user selects one). Two tables of one foot are no error here: the dialog chooses.
    const QString current = workspace.currentItem();
    const QString selected = ItemPath::parse(current + QStringLiteral("/x")).recording;
    const QString recording = GaitReport::defaultRecording(*project, selected);
    auto found = GaitReport::strideTables(*project, recording);
    GaitReportInput start{recording, {}};
    if (found) start = *found;
    if (start.recording.isEmpty()) {
        QMessageBox::warning(parent, tr("Export gait report"), found.message());
        return;
    }
    if (const Table* t = project->table(current); t && GaitReport::isStrideTable(*t))
        start.strides << current;  // chosen last: its foot's combo shows it
    GaitReportDialog dialog(*project, start, parent);
    if (dialog.exec() != QDialog::Accepted) return;
    const GaitReportInput input = dialog.input();
    if (input.strides.isEmpty()) {
        QMessageBox::warning(parent, tr("Export gait report"), tr("Choose a stride table."));
        return;
    }
    auto checked = GaitReport::strideTables(*project, {}, input.strides);
    if (!checked) {
        QMessageBox::warning(parent, tr("Export gait report"), checked.message());
        return;
    }
    auto summary = GaitReport::summary(*project, *checked, dialog.parameters());
    if (!summary) {
        QMessageBox::warning(parent, tr("Export gait report"), summary.message());
        return;
    }
    const QString suggested = QFileInfo(project->path()).absolutePath() + QLatin1Char('/') +
                              QFileInfo(project->path()).completeBaseName() + QLatin1Char('-') + checked->recording +
                              QStringLiteral("-gait.pdf");
    const QString path = QFileDialog::getSaveFileName(parent, tr("Export gait report"), suggested, tr("PDF (*.pdf)"));
    if (path.isEmpty()) return;
    const auto written = BackgroundTask::runHere(parent, tr("Writing the gait report…"), [&](const Progress& progress) {
        return GaitReport::writePdf(*project, *checked, *summary, path, progress);
    });
    if (!written.status && !written.cancelled)
        QMessageBox::warning(parent, tr("Export gait report"), written.status.message());
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("export-gait-report"), QT_TRANSLATE_NOOP("Tools", "Export gait report…"),
                      QT_TRANSLATE_NOOP("Tools", "File"), exportGaitReport});

}  // namespace athlos::ui
