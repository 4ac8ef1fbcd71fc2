#include "ui/ProjectSession.h"

#include "core/io/Importer.h"
#include "core/model/AnnotationJournal.h"
#include "core/model/Project.h"
#include "ui/AnnotationEditor.h"
#include "ui/AnnotationLayer.h"
#include "ui/AnnotationPanel.h"
#include "ui/BackgroundTask.h"
#include "ui/MainWindow.h"
#include "ui/PanelLayout.h"
#include "ui/ProjectBrowser.h"
#include "ui/RecentProjects.h"

#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>
#include <memory>

namespace athlos::ui {

namespace {

const QString kProjectSuffix = QStringLiteral("athlos");

// Importer errors name file and line already; this only guarantees the file is named.
QString namingFile(const QString& file, const QString& message) {
    const QString name = QFileInfo(file).fileName();
    return message.contains(name) ? message : QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(file), message);
}

}  // namespace

ProjectSession::ProjectSession(MainWindow& window) : window_(window) {
    autosaveTimer_ = new QTimer(&window);
    autosaveTimer_->setSingleShot(true);
    autosaveTimer_->setInterval(QSettings().value(QStringLiteral("annotation/autosave_seconds"), 30).toInt() * 1000);
    QObject::connect(autosaveTimer_, &QTimer::timeout, &window, [this] { autosave(); });
    QObject::connect(window.annotationEditor(), &AnnotationEditor::annotationsChanged, autosaveTimer_, [this] {
        // Idle autosave: every edit postpones it.
        if (autosaveTimer_->interval() > 0) autosaveTimer_->start();
    });
}

bool ProjectSession::newProject(const QString& path) {
    if (!maybeSaveChanges()) return false;
    std::shared_ptr<Project> project = Project::create(path);
    if (Status locked = project->lockForChange(); !locked) {
        window_.showError(tr("Could not create the project"), locked.message());
        return false;
    }
    window_.setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        &window_, tr("Creating project…"), [project](const Progress& progress) { return project->save(progress); },
        window_.interactive_);
    window_.setBusy(false);
    if (!outcome.status) {
        window_.showError(tr("Could not create the project"), outcome.status.message());
        return false;
    }
    window_.setProject(project);
    RecentProjects::add(path);
    window_.statusBar()->showMessage(tr("Created %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

bool ProjectSession::openProject(const QString& path) {
    if (!maybeSaveChanges()) return false;
    // The GUI holds the project's write lock while it is open: a batch run on the same file is
    // refused instead of one overwriting the other's results.
    auto opened = Project::openForChange(path);
    if (!opened) {
        window_.showError(tr("Could not open the project"), opened.message());
        if (!QFileInfo::exists(path)) RecentProjects::remove(path);
        return false;
    }
    const QStringList notes = (*opened)->notes();
    window_.setProject(std::shared_ptr<Project>(std::move(opened).value()));
    // The data first: the first stream is selected and plotted, so an opened project never shows
    // an empty plot (a panel restored from the saved layout keeps its own stream).
    if (const QString first = window_.firstStream(); !first.isEmpty()) window_.selectItem(first);
    RecentProjects::add(path);
    window_.statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(path)), 5000);
    // Information, not an error: the project is as it was last saved.
    if (!notes.isEmpty()) {
        window_.statusBar()->showMessage(notes.join(QLatin1Char(' ')), 15000);
        if (window_.interactive_)
            QMessageBox::information(&window_, tr("Opened after an interrupted save"),
                                     notes.join(QStringLiteral("\n")));
    }
    recoverJournal();
    return true;
}

bool ProjectSession::saveProject() {
    std::shared_ptr<Project> project = window_.project_;
    if (!project) return false;
    if (!runSave([project](const Progress& progress) { return project->save(progress); },
                 tr("Saving cancelled; the file on disk is unchanged.")))
        return false;
    window_.updateTitle();
    window_.statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(project->path())), 5000);
    return true;
}

bool ProjectSession::runSave(const std::function<Status(const Progress&)>& save, const QString& cancelledMessage) {
    window_.panels_->storeLayout();
    // The panels' workers may be reading lazy samples; saving rebinds the streams to the new file.
    window_.panels_->waitForLoads();
    window_.setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(&window_, tr("Saving…"), save, window_.interactive_);
    window_.setBusy(false);
    if (!outcome.status) {
        if (outcome.cancelled)
            window_.statusBar()->showMessage(cancelledMessage, 5000);
        else
            window_.showError(tr("Could not save the project"), outcome.status.message());
        return false;
    }
    window_.project_->setModified(false);
    afterSave();
    return true;
}

bool ProjectSession::saveProjectAs(const QString& path) {
    std::shared_ptr<Project> project = window_.project_;
    if (!project) return false;
    if (!runSave([project, path](const Progress& progress) { return project->saveAs(path, progress); },
                 tr("Saving cancelled; nothing was written.")))
        return false;
    RecentProjects::add(project->path());
    window_.updateTitle();
    window_.browser_->showProjectDetails();
    window_.statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(project->path())), 5000);
    return true;
}

bool ProjectSession::importFiles(const QStringList& files) {
    if (files.isEmpty()) return false;
    std::shared_ptr<Project> project = window_.project_;
    if (!project) {
        window_.showError(tr("Import"), tr("Create or open a project first, then import recordings into it."));
        return false;
    }
    auto merged = std::make_shared<ImportResult>();
    window_.setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        &window_, files.size() == 1 ? tr("Importing 1 file…") : tr("Importing %1 files…").arg(files.size()),
        [files, merged](const Progress& progress) -> Status {
            const int n = int(files.size());
            for (int i = 0; i < n; ++i) {
                ImportOptions options;
                options.format = QStringLiteral("auto");
                options.target = QFileInfo(files[i]).completeBaseName();
                auto result = importFile(files[i], options, progress.sub(double(i) / n, double(i + 1) / n));
                if (!result) return makeError(namingFile(files[i], result.message()));
                if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
                for (ImportedItem& item : result->items) merged->items.push_back(std::move(item));
                for (const QString& warning : result->warnings)
                    merged->warnings << QStringLiteral("%1: %2").arg(QFileInfo(files[i]).fileName(), warning);
            }
            return {};
        },
        window_.interactive_);
    window_.setBusy(false);
    if (outcome.cancelled) {
        window_.statusBar()->showMessage(tr("Import cancelled; the project is unchanged."), 5000);
        return false;
    }
    if (!outcome.status) {
        window_.showError(tr("Import failed"), tr("Nothing was imported.\n\n%1").arg(outcome.status.message()));
        return false;
    }

    QStringList paths;
    for (const ImportedItem& item : merged->items) paths << item.path;
    const QStringList warnings = merged->warnings;
    const Status applied = applyImport(*project, std::move(*merged), false);
    if (!applied) {
        window_.showError(tr("Import failed"), tr("Nothing was imported.\n\n%1").arg(applied.message()));
        return false;
    }
    project->setModified(true);
    window_.browser_->refresh();
    window_.updateTitle();
    if (!paths.isEmpty()) window_.selectItem(paths.front());
    window_.statusBar()->showMessage(tr("Imported %1").arg(paths.join(QStringLiteral(", "))), 8000);
    if (!warnings.isEmpty()) {
        if (window_.interactive_)
            QMessageBox::information(&window_, tr("Import warnings"), warnings.join(QLatin1Char('\n')));
        else
            emit window_.errorReported(warnings.join(QLatin1Char('\n')));
    }
    emit window_.projectChanged();
    return true;
}

bool ProjectSession::maybeSaveChanges() {
    const Project* project = window_.project_.get();
    if (!project || !project->isModified() || !window_.interactive_) return true;
    const auto answer = QMessageBox::warning(
        &window_, tr("Unsaved changes"),
        tr("The project %1 has unsaved changes. Save them?").arg(QFileInfo(project->path()).completeBaseName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return saveProject();
    // Discarded on purpose: the journal must not offer the edits again.
    if (answer == QMessageBox::Discard) window_.annotationEditor()->journal().discard();
    return answer == QMessageBox::Discard;
}

void ProjectSession::setAutosaveDelay(int milliseconds) {
    autosaveTimer_->stop();
    autosaveTimer_->setInterval(std::max(0, milliseconds));
}

bool ProjectSession::autosave() {
    std::shared_ptr<Project> project = window_.project_;
    if (!project || window_.busy_ || !project->isModified()) return false;
    window_.panels_->waitForLoads();
    AnnotationEditor* editor = window_.annotationEditor();
    // Not setBusy(): the window stays usable; only commands that change the project wait.
    window_.busy_ = true;
    editor->setLocked(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        &window_, tr("Saving…"), [project](const Progress& progress) { return project->save(progress); }, false);
    window_.busy_ = false;
    editor->setLocked(false);
    if (!outcome.status) {
        window_.statusBar()->showMessage(
            tr("Autosave failed: %1 (the journal keeps your edits)").arg(outcome.status.message()), 8000);
        return false;
    }
    project->setModified(false);
    afterSave();
    window_.updateTitle();
    window_.statusBar()->showMessage(tr("Autosaved"), 3000);
    return true;
}

void ProjectSession::afterSave() {
    // The file now has every edit; a new journal starts (at the new path after Save As).
    AnnotationJournal& journal = window_.annotationEditor()->journal();
    journal.discard();
    journal.setProjectPath(window_.project_->path());
}

void ProjectSession::recoverJournal() {
    Project* project = window_.project_.get();
    if (!project || !AnnotationJournal::hasPendingEdits(project->path())) return;
    AnnotationEditor* editor = window_.annotationEditor();
    if (!AnnotationJournal::belongsTo(*project)) {
        // The file was saved after the journal began (the program ended between the save and the
        // journal's removal): its edits are in the file already.
        editor->journal().discard();
        return;
    }
    if (window_.interactive_) {
        const auto answer = QMessageBox::question(
            &window_, tr("Recover annotations"),
            tr("%1 has annotation edits that were not saved (the program ended unexpectedly). Recover them?")
                .arg(QFileInfo(project->path()).fileName()),
            QMessageBox::Yes | QMessageBox::Discard, QMessageBox::Yes);
        if (answer != QMessageBox::Yes) {
            editor->journal().discard();
            return;
        }
    }
    auto replayed = AnnotationJournal::replay(*project);
    if (!replayed) {
        window_.showError(tr("Could not recover annotations"), replayed.message());
        return;
    }
    // The journal stays until the next save: the file still lacks these edits.
    editor->setProject(project);
    window_.annotationLayer()->rebuild();
    window_.annotationPanel()->refresh();
    window_.updateTitle();
    window_.statusBar()->showMessage(tr("Annotation edits recovered from the journal: %1").arg(*replayed), 8000);
}

// --- dialogs ----------------------------------------------------------------------------------

void ProjectSession::newProjectDialog() {
    QString path = QFileDialog::getSaveFileName(&window_, tr("New Project"), {}, tr("Athlos projects (*.athlos)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QLatin1Char('.') + kProjectSuffix;
    newProject(path);
}

void ProjectSession::openProjectDialog() {
    const QString path =
        QFileDialog::getOpenFileName(&window_, tr("Open Project"), {}, tr("Athlos projects (*.athlos);;All files (*)"));
    if (!path.isEmpty()) openProject(path);
}

void ProjectSession::saveAsDialog() {
    const Project* project = window_.project_.get();
    if (!project) return;
    QString path = QFileDialog::getSaveFileName(&window_, tr("Save Project As"), project->path(),
                                                tr("Athlos projects (*.athlos)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QLatin1Char('.') + kProjectSuffix;
    saveProjectAs(path);
}

void ProjectSession::importDialog() {
    QStringList patterns;
    for (const auto& importer : importers())
        for (const QString& ext : importer->extensions()) {
            const QString pattern = QStringLiteral("*.") + ext;
            if (!patterns.contains(pattern)) patterns << pattern;
        }
    QString filter = patterns.isEmpty()
                         ? QString()
                         : tr("Recordings (%1)").arg(patterns.join(QLatin1Char(' '))) + QStringLiteral(";;");
    filter += tr("All files (*)");
    const QStringList files = QFileDialog::getOpenFileNames(&window_, tr("Import Recordings"), {}, filter);
    if (!files.isEmpty()) importFiles(files);
}

}  // namespace athlos::ui
