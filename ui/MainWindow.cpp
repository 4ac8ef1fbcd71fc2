#include "ui/MainWindow.h"

#include "core/io/Importer.h"
#include "core/model/Project.h"
#include "core/processing/ProcessorRegistry.h"
#include "core/util/Version.h"
#include "core/model/AnnotationJournal.h"
#include "ui/AnnotationEditor.h"
#include "ui/AnnotationLayer.h"
#include "ui/AnnotationPanel.h"
#include "ui/BackgroundTask.h"
#include "ui/ItemDescription.h"
#include "ui/PlotExporter.h"
#include "ui/ProcessorDialog.h"
#include "ui/ProjectTreeModel.h"
#include "ui/RecentProjects.h"
#include "ui/TimeController.h"
#include "ui/TimeSeriesPanel.h"
#include "ui/ToolRegistry.h"
#include "ui/TrajectoryPanel.h"
#include "ui/UiEntry.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QHeaderView>
#include <QInputDialog>
#include <QSettings>
#include <QUndoStack>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>
#include <QTabWidget>
#include <QTextBrowser>
#include <QTimer>
#include <QTreeView>
#include <QJsonArray>
#include <qcustomplot.h>

#include <algorithm>
#include <limits>
#include <optional>

namespace athlos::ui {

namespace {

const QString kProjectSuffix = QStringLiteral("athlos");

QStringList localFiles(const QMimeData* mime)
{
    QStringList files;
    if (!mime || !mime->hasUrls()) return files;
    for (const QUrl& url : mime->urls())
        if (url.isLocalFile() && QFileInfo(url.toLocalFile()).isFile()) files << url.toLocalFile();
    return files;
}

// Importer errors name file and line already; this only guarantees the file is named.
QString namingFile(const QString& file, const QString& message)
{
    const QString name = QFileInfo(file).fileName();
    return message.contains(name) ? message : QStringLiteral("%1: %2").arg(QDir::toNativeSeparators(file), message);
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent)
{
    setWindowIcon(QIcon(QStringLiteral(":/athlos/icons/athlos.svg")));
    setAcceptDrops(true);

    timeController_ = new TimeController(this);
    timeSeries_ = new TimeSeriesPanel(this);
    timeSeries_->setTimeController(timeController_);
    addExportMenu(timeSeries_->plot());
    connect(timeSeries_, &TimeSeriesPanel::loaded, this, &MainWindow::updateTimeBounds);
    trajectory_ = new TrajectoryPanel(this);
    trajectory_->setTimeController(timeController_);
    addExportMenu(trajectory_->plot());
    tabs_ = new QTabWidget(this);
    tabs_->setDocumentMode(true);
    tabs_->addTab(timeSeries_, tr("Time series"));
    tabs_->addTab(trajectory_, tr("Trajectory"));
    setCentralWidget(tabs_);

    createAnnotationTool();
    createActions();
    createDocks();
    createMenus();
    statusBar()->showMessage(tr("Open a project, or drop recordings onto the window to import them."));
    resize(1280, 800);
    updateTitle();
    updateActions();
}

MainWindow::~MainWindow()
{
    // Panels may hold pointers into the project; drop them before the project goes.
    removeExtraPanels();
    timeSeries_->clear();
    trajectory_->clear();
    treeModel_->setProject(nullptr);
}

void MainWindow::createActions()
{
    newAction_ = new QAction(QIcon::fromTheme(QStringLiteral("document-new"), QIcon(QStringLiteral(":/athlos/icons/new.svg"))),
                             tr("&New Project…"), this);
    newAction_->setShortcut(QKeySequence::New);
    newAction_->setStatusTip(tr("Create an empty project file"));
    connect(newAction_, &QAction::triggered, this, &MainWindow::newProjectDialog);

    openAction_ = new QAction(QIcon::fromTheme(QStringLiteral("document-open"), QIcon(QStringLiteral(":/athlos/icons/open.svg"))),
                              tr("&Open Project…"), this);
    openAction_->setShortcut(QKeySequence::Open);
    openAction_->setStatusTip(tr("Open an existing project file"));
    connect(openAction_, &QAction::triggered, this, &MainWindow::openProjectDialog);

    saveAction_ = new QAction(QIcon::fromTheme(QStringLiteral("document-save"), QIcon(QStringLiteral(":/athlos/icons/save.svg"))),
                              tr("&Save"), this);
    saveAction_->setShortcut(QKeySequence::Save);
    saveAction_->setStatusTip(tr("Save the project (the file is replaced atomically)"));
    connect(saveAction_, &QAction::triggered, this, [this] { saveProject(); });

    saveAsAction_ = new QAction(tr("Save &As…"), this);
    saveAsAction_->setShortcut(QKeySequence::SaveAs);
    saveAsAction_->setStatusTip(tr("Save the project under a new name"));
    connect(saveAsAction_, &QAction::triggered, this, &MainWindow::saveAsDialog);

    importAction_ = new QAction(QIcon(QStringLiteral(":/athlos/icons/import.svg")), tr("&Import…"), this);
    importAction_->setShortcut(Qt::CTRL | Qt::Key_I);
    importAction_->setStatusTip(tr("Import recordings (CSV, BROAD, gaitmap, …) into the project"));
    connect(importAction_, &QAction::triggered, this, &MainWindow::importDialog);

    quitAction_ = new QAction(tr("&Quit"), this);
    quitAction_->setShortcut(QKeySequence::Quit);
    quitAction_->setMenuRole(QAction::QuitRole);
    connect(quitAction_, &QAction::triggered, this, &QWidget::close);

    aboutAction_ = new QAction(tr("&About Athlos"), this);
    aboutAction_->setMenuRole(QAction::AboutRole);
    connect(aboutAction_, &QAction::triggered, this, &MainWindow::about);

    runProcessorAction_ = new QAction(tr("&Run Processor…"), this);
    runProcessorAction_->setShortcut(Qt::CTRL | Qt::Key_R);
    runProcessorAction_->setStatusTip(tr("Run any processor on streams of the project"));
    connect(runProcessorAction_, &QAction::triggered, this, [this] { openProcessorDialog(); });

    addPanelAction_ = new QAction(tr("Add &Time-Series Panel"), this);
    addPanelAction_->setStatusTip(tr("Plot the selected stream in another panel that shares the time cursor"));
    connect(addPanelAction_, &QAction::triggered, this, [this] {
        const QString path = currentItem();
        if (project_ && project_->stream(path)) addTimeSeriesPanel(path);
        else statusBar()->showMessage(tr("Select a stream first."), 5000);
    });
    undoAction_ = annotationEditor_->undoStack()->createUndoAction(this, tr("&Undo"));
    undoAction_->setShortcut(QKeySequence::Undo);
    redoAction_ = annotationEditor_->undoStack()->createRedoAction(this, tr("&Redo"));
    redoAction_->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence::Redo});
    annotateModeAction_ = new QAction(tr("&Annotate Mode"), this);
    annotateModeAction_->setCheckable(true);
    annotateModeAction_->setShortcut(Qt::CTRL | Qt::Key_M);
    annotateModeAction_->setStatusTip(tr("Drag on the plot to create intervals of the current class (Shift+drag works always)"));
    connect(annotateModeAction_, &QAction::toggled, this, [this](bool on) {
        annotationLayer_->setAnnotateMode(on);
        if (on) showAnnotationPanel();
    });
    addClassAction_ = new QAction(tr("Add Annotation &Class…"), this);
    connect(addClassAction_, &QAction::triggered, this, [this] { annotationPanel_->addClassDialog(); });
    preferencesAction_ = new QAction(tr("&Preferences…"), this);
    preferencesAction_->setMenuRole(QAction::PreferencesRole);
    connect(preferencesAction_, &QAction::triggered, this, [this] {
        bool ok = false;
        const QString name = QInputDialog::getText(this, tr("Preferences"), tr("Annotator name:"), QLineEdit::Normal,
                                                   AnnotationEditor::annotator(), &ok);
        if (ok && !name.trimmed().isEmpty()) AnnotationEditor::setAnnotator(name);
    });

    exportViewAction_ = new QAction(tr("&Export View…"), this);
    exportViewAction_->setShortcut(Qt::CTRL | Qt::Key_E);
    exportViewAction_->setStatusTip(tr("Save the shown plot as PNG, SVG or PDF"));
    connect(exportViewAction_, &QAction::triggered, this, [this] {
        QCustomPlot* plot = tabs_->currentWidget() == trajectory_ ? trajectory_->plot() : timeSeries_->plot();
        const QString written = PlotExporter::exportDialog(plot, this);
        if (!written.isEmpty()) statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(written)), 5000);
    });

    showAllAction_ = new QAction(tr("Show &All"), this);
    showAllAction_->setShortcut(Qt::CTRL | Qt::Key_0);
    connect(showAllAction_, &QAction::triggered, timeController_, &TimeController::showAll);
}

void MainWindow::createMenus()
{
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(newAction_);
    file->addAction(openAction_);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    connect(recentMenu_, &QMenu::aboutToShow, this, &MainWindow::rebuildRecentMenu);
    rebuildRecentMenu();
    file->addSeparator();
    file->addAction(saveAction_);
    file->addAction(saveAsAction_);
    file->addSeparator();
    file->addAction(importAction_);
    file->addAction(exportViewAction_);
    QAction* beforeQuit = file->addSeparator();
    file->addAction(quitAction_);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(undoAction_);
    edit->addAction(redoAction_);
    edit->addSeparator();
    edit->addAction(annotateModeAction_);
    edit->addAction(addClassAction_);
    edit->addSeparator();
    edit->addAction(preferencesAction_);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    viewMenu_ = view;
    view->addAction(addPanelAction_);
    view->addAction(showAllAction_);

    QMenu* processing = menuBar()->addMenu(tr("&Processing"));
    processing->addAction(runProcessorAction_);
    createToolMenus(file, processing, view);
    // Tools of the File menu (import wizard…) sit with Import, before the quit separator.
    for (QAction* action : toolActions_) {
        if (!file->actions().contains(action)) continue;
        file->removeAction(action);
        file->insertAction(beforeQuit, action);
    }

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(aboutAction_);
}

void MainWindow::createDocks()
{
    treeModel_ = new ProjectTreeModel(this);
    tree_ = new QTreeView(this);
    tree_->setModel(treeModel_);
    tree_->setUniformRowHeights(true);
    tree_->setAlternatingRowColors(true);
    tree_->setSelectionMode(QAbstractItemView::SingleSelection);
    tree_->header()->setStretchLastSection(true);
    connect(tree_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& current) { onCurrentChanged(current); });
    connect(tree_, &QTreeView::activated, this, &MainWindow::onActivated);
    tree_->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(tree_, &QTreeView::customContextMenuRequested, this, &MainWindow::showTreeContextMenu);
    // A model reset replaces the selection model's contents, not the object: connect once.

    auto* treeDock = new QDockWidget(tr("Project"), this);
    treeDock->setObjectName(QStringLiteral("projectDock"));
    treeDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    treeDock->setWidget(tree_);
    addDockWidget(Qt::LeftDockWidgetArea, treeDock);

    details_ = new QTextBrowser(this);
    details_->setOpenLinks(false);
    auto* detailsDock = new QDockWidget(tr("Details"), this);
    detailsDock->setObjectName(QStringLiteral("detailsDock"));
    detailsDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    detailsDock->setWidget(details_);
    addDockWidget(Qt::LeftDockWidgetArea, detailsDock);
    splitDockWidget(treeDock, detailsDock, Qt::Vertical);
    resizeDocks({treeDock}, {380}, Qt::Horizontal);
    resizeDocks({treeDock, detailsDock}, {420, 300}, Qt::Vertical);
}

// --- project lifecycle ------------------------------------------------------------------------

void MainWindow::setProject(std::shared_ptr<Project> project)
{
    removeExtraPanels();
    timeSeries_->clear();
    trajectory_->clear();
    treeModel_->setProject(project.get());
    annotationLayer_->setRecording({});
    project_ = std::move(project);
    annotationEditor_->setProject(project_.get());
    tree_->expandAll();
    for (int c = 0; c < ProjectTreeModel::ColumnsColumn; ++c) tree_->resizeColumnToContents(c);
    details_->setHtml(project_ ? ItemDescription::projectHtml(*project_) : QString());
    if (project_) statusBar()->clearMessage();
    restoreLayout();
    updateTitle();
    updateActions();
    emit projectChanged();
}

bool MainWindow::newProject(const QString& path)
{
    if (!maybeSaveChanges()) return false;
    std::shared_ptr<Project> project = Project::create(path);
    setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        this, tr("Creating project…"), [project](const Progress& progress) { return project->save(progress); },
        interactive_);
    setBusy(false);
    if (!outcome.status) {
        showError(tr("Could not create the project"), outcome.status.message());
        return false;
    }
    setProject(project);
    RecentProjects::add(path);
    statusBar()->showMessage(tr("Created %1").arg(QDir::toNativeSeparators(path)), 5000);
    return true;
}

bool MainWindow::openProject(const QString& path)
{
    if (!maybeSaveChanges()) return false;
    auto opened = Project::open(path);
    if (!opened) {
        showError(tr("Could not open the project"), opened.message());
        if (!QFileInfo::exists(path)) RecentProjects::remove(path);
        return false;
    }
    setProject(std::shared_ptr<Project>(std::move(opened).value()));
    RecentProjects::add(path);
    statusBar()->showMessage(tr("Opened %1").arg(QDir::toNativeSeparators(path)), 5000);
    recoverJournal();
    return true;
}

bool MainWindow::saveProject()
{
    if (!project_) return false;
    storeLayout();
    // The panels' workers may be reading lazy samples; saving rebinds the streams to the new file.
    waitForLoads();
    std::shared_ptr<Project> project = project_;
    setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        this, tr("Saving…"), [project](const Progress& progress) { return project->save(progress); }, interactive_);
    setBusy(false);
    if (!outcome.status) {
        if (outcome.cancelled) statusBar()->showMessage(tr("Saving cancelled; the file on disk is unchanged."), 5000);
        else showError(tr("Could not save the project"), outcome.status.message());
        return false;
    }
    project_->setModified(false);
    afterSave();
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(project_->path())), 5000);
    return true;
}

bool MainWindow::saveProjectAs(const QString& path)
{
    if (!project_) return false;
    storeLayout();
    waitForLoads();
    std::shared_ptr<Project> project = project_;
    setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        this, tr("Saving…"), [project, path](const Progress& progress) { return project->saveAs(path, progress); },
        interactive_);
    setBusy(false);
    if (!outcome.status) {
        if (outcome.cancelled) statusBar()->showMessage(tr("Saving cancelled; nothing was written."), 5000);
        else showError(tr("Could not save the project"), outcome.status.message());
        return false;
    }
    project_->setModified(false);
    afterSave();
    RecentProjects::add(project_->path());
    updateTitle();
    details_->setHtml(ItemDescription::projectHtml(*project_));
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(project_->path())), 5000);
    return true;
}

bool MainWindow::importFiles(const QStringList& files)
{
    if (files.isEmpty()) return false;
    if (!project_) {
        showError(tr("Import"), tr("Create or open a project first, then import recordings into it."));
        return false;
    }
    auto merged = std::make_shared<ImportResult>();
    setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        this, files.size() == 1 ? tr("Importing 1 file…") : tr("Importing %1 files…").arg(files.size()),
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
        interactive_);
    setBusy(false);
    if (outcome.cancelled) {
        statusBar()->showMessage(tr("Import cancelled; the project is unchanged."), 5000);
        return false;
    }
    if (!outcome.status) {
        showError(tr("Import failed"), tr("Nothing was imported.\n\n%1").arg(outcome.status.message()));
        return false;
    }

    QStringList paths;
    for (const ImportedItem& item : merged->items) paths << item.path;
    const QStringList warnings = merged->warnings;
    const Status applied = applyImport(*project_, std::move(*merged), false);
    if (!applied) {
        showError(tr("Import failed"), tr("Nothing was imported.\n\n%1").arg(applied.message()));
        return false;
    }
    project_->setModified(true);
    treeModel_->refresh();
    tree_->expandAll();
    for (int c = 0; c < ProjectTreeModel::ColumnsColumn; ++c) tree_->resizeColumnToContents(c);
    updateTitle();
    if (!paths.isEmpty()) selectItem(paths.front());
    statusBar()->showMessage(tr("Imported %1").arg(paths.join(QStringLiteral(", "))), 8000);
    if (!warnings.isEmpty()) {
        if (interactive_) QMessageBox::information(this, tr("Import warnings"), warnings.join(QLatin1Char('\n')));
        else emit errorReported(warnings.join(QLatin1Char('\n')));
    }
    emit projectChanged();
    return true;
}

bool MainWindow::maybeSaveChanges()
{
    if (!project_ || !project_->isModified() || !interactive_) return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"),
        tr("The project %1 has unsaved changes. Save them?").arg(QFileInfo(project_->path()).completeBaseName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Save) return saveProject();
    // Discarded on purpose: the journal must not offer the edits again.
    if (answer == QMessageBox::Discard) annotationEditor_->journal().discard();
    return answer == QMessageBox::Discard;
}

// --- dialogs ----------------------------------------------------------------------------------

void MainWindow::newProjectDialog()
{
    QString path = QFileDialog::getSaveFileName(this, tr("New Project"), {},
                                                tr("Athlos projects (*.athlos)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QLatin1Char('.') + kProjectSuffix;
    newProject(path);
}

void MainWindow::openProjectDialog()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Project"), {},
                                                      tr("Athlos projects (*.athlos);;All files (*)"));
    if (!path.isEmpty()) openProject(path);
}

void MainWindow::saveAsDialog()
{
    if (!project_) return;
    QString path = QFileDialog::getSaveFileName(this, tr("Save Project As"), project_->path(),
                                                tr("Athlos projects (*.athlos)"));
    if (path.isEmpty()) return;
    if (QFileInfo(path).suffix().isEmpty()) path += QLatin1Char('.') + kProjectSuffix;
    saveProjectAs(path);
}

void MainWindow::importDialog()
{
    QStringList patterns;
    for (const auto& importer : importers())
        for (const QString& ext : importer->extensions()) {
            const QString pattern = QStringLiteral("*.") + ext;
            if (!patterns.contains(pattern)) patterns << pattern;
        }
    QString filter = patterns.isEmpty() ? QString() : tr("Recordings (%1)").arg(patterns.join(QLatin1Char(' '))) + QStringLiteral(";;");
    filter += tr("All files (*)");
    const QStringList files = QFileDialog::getOpenFileNames(this, tr("Import Recordings"), {}, filter);
    if (!files.isEmpty()) importFiles(files);
}

void MainWindow::rebuildRecentMenu()
{
    recentMenu_->clear();
    const QStringList paths = RecentProjects::list();
    int number = 1;
    for (const QString& path : paths) {
        QAction* action = recentMenu_->addAction(
            QStringLiteral("&%1 %2").arg(number++ % 10).arg(QFileInfo(path).fileName()));
        action->setToolTip(QDir::toNativeSeparators(path));
        action->setStatusTip(QDir::toNativeSeparators(path));
        connect(action, &QAction::triggered, this, [this, path] { openProject(path); });
    }
    if (paths.isEmpty()) {
        recentMenu_->addAction(tr("No recent projects"))->setEnabled(false);
        return;
    }
    recentMenu_->addSeparator();
    connect(recentMenu_->addAction(tr("Clear List")), &QAction::triggered, this, [] { RecentProjects::clear(); });
}

void MainWindow::about()
{
    const QString versions = ui::libraryVersions();
    QMessageBox::about(this, tr("About Athlos"),
                       QStringLiteral("<h3>Athlos %1</h3><p>%2</p><p>%3</p><pre>%4</pre>")
                           .arg(appVersion().toHtmlEscaped(),
                                tr("Analysis of sports recordings from local positioning systems, IMUs and GNSS.").toHtmlEscaped(),
                                tr("Built with:").toHtmlEscaped(), versions.toHtmlEscaped()));
}

void MainWindow::showError(const QString& title, const QString& message)
{
    statusBar()->showMessage(title, 8000);
    emit errorReported(message);
    if (interactive_) QMessageBox::critical(this, title, message);
}

// --- window chrome ----------------------------------------------------------------------------

void MainWindow::updateTitle()
{
    if (!project_) {
        setWindowTitle(tr("Athlos"));
        setWindowModified(false);
        return;
    }
    // "[*]" is where Qt shows '*' while the window is modified.
    setWindowTitle(tr("%1[*] — Athlos").arg(QFileInfo(project_->path()).completeBaseName()));
    setWindowModified(project_->isModified());
}

void MainWindow::setBusy(bool busy)
{
    busy_ = busy;
    annotationEditor_->setLocked(busy);
    menuBar()->setEnabled(!busy);
    centralWidget()->setEnabled(!busy);
    for (QDockWidget* dock : findChildren<QDockWidget*>()) dock->setEnabled(!busy);
    for (QAction* action : {newAction_, openAction_, saveAction_, saveAsAction_, importAction_, quitAction_,
                            runProcessorAction_})
        action->setEnabled(!busy);
    for (QAction* action : toolActions_) action->setEnabled(!busy);
    if (!busy) updateActions();
}

void MainWindow::updateActions()
{
    const bool open = project_ != nullptr;
    saveAction_->setEnabled(open);
    saveAsAction_->setEnabled(open);
    importAction_->setEnabled(open);
    runProcessorAction_->setEnabled(open);
    // Tools work on a project; they are offered once one is open.
    for (QAction* action : toolActions_) action->setEnabled(open);
}

void MainWindow::closeEvent(QCloseEvent* event)
{
    if (busy_ || !maybeSaveChanges()) {
        event->ignore();
        return;
    }
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event)
{
    if (!busy_ && !localFiles(event->mimeData()).isEmpty()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event)
{
    const QStringList files = localFiles(event->mimeData());
    if (files.isEmpty() || busy_) return;
    event->acceptProposedAction();
    // Not inside the drop handler: the import spins an event loop and may show dialogs, which
    // must not happen while the platform's drag-and-drop is still in progress.
    QTimer::singleShot(0, this, [this, files] { importFiles(files); });
}

// --- selection and plotting -------------------------------------------------------------------

bool MainWindow::selectItem(const QString& path)
{
    const QModelIndex index = treeModel_->indexOf(path);
    if (!index.isValid()) return false;
    if (tree_->currentIndex() == index) onCurrentChanged(index);
    else tree_->setCurrentIndex(index);
    tree_->scrollTo(index);
    return true;
}

QString MainWindow::currentItem() const
{
    return treeModel_->pathOf(tree_->currentIndex());
}

void MainWindow::showTimeSeriesView()
{
    tabs_->setCurrentWidget(timeSeries_);
}

void MainWindow::showTrajectoryView()
{
    tabs_->setCurrentWidget(trajectory_);
}

QString MainWindow::firstStream() const
{
    if (!project_) return {};
    for (const auto& [name, recording] : project_->recordings())
        if (!recording.streams.empty()) return name + QLatin1Char('/') + recording.streams.begin()->first;
    return {};
}

QString MainWindow::firstPositionStream() const
{
    if (!project_) return {};
    for (const auto& [name, recording] : project_->recordings())
        for (const auto& [streamName, stream] : recording.streams)
            if (TrajectoryPanel::isPositionStream(stream.info())) return name + QLatin1Char('/') + streamName;
    return {};
}

void MainWindow::waitForLoads()
{
    for (const ExtraPanel& extra : extraPanels_) extra.panel->waitForLoad();
    timeSeries_->waitForLoad();
    trajectory_->waitForLoad();
}

void MainWindow::waitForPlots()
{
    waitForLoads();
    // Layout first (plot widths decide the decimation), then draw synchronously.
    for (int i = 0; i < 3; ++i) {
        QCoreApplication::processEvents();
        for (TimeSeriesPanel* panel : timeSeriesPanels()) panel->plot()->replot(QCustomPlot::rpImmediateRefresh);
        trajectory_->plot()->replot(QCustomPlot::rpImmediateRefresh);
    }
}

std::shared_ptr<const Stream> MainWindow::sharedStream(const QString& path) const
{
    if (!project_) return {};
    const Stream* stream = project_->stream(path);
    if (!stream) return {};
    // Aliasing pointer: keeps the whole project alive while a worker still reads the stream.
    return std::shared_ptr<const Stream>(project_, stream);
}

void MainWindow::onCurrentChanged(const QModelIndex& current)
{
    const QString path = treeModel_->pathOf(current);
    showDetails(path);
    if (treeModel_->nodeType(current) == ProjectTreeModel::NodeType::Stream) plotItem(path);
}

void MainWindow::onActivated(const QModelIndex& index)
{
    if (treeModel_->nodeType(index) != ProjectTreeModel::NodeType::Stream) return;
    const Stream* stream = project_ ? project_->stream(treeModel_->pathOf(index)) : nullptr;
    // Double-click brings the plot forward; a position stream stays on the trajectory if shown.
    if (!(stream && tabs_->currentWidget() == trajectory_ && TrajectoryPanel::isPositionStream(stream->info())))
        showTimeSeriesView();
}

void MainWindow::plotItem(const QString& path)
{
    std::shared_ptr<const Stream> stream = sharedStream(path);
    if (!stream) return;
    if (timeSeries_->stream() != stream.get()) {
        timeSeries_->setStream(stream, path);
        annotationLayer_->setRecording(ItemPath::parse(path).recording);
        annotationPanel_->refresh();
    }
    if (TrajectoryPanel::isPositionStream(stream->info()) && trajectory_->stream() != stream.get())
        trajectory_->setStream(stream, path);
}

void MainWindow::showDetails(const QString& path)
{
    if (!project_) {
        details_->clear();
        return;
    }
    if (path.isEmpty()) {
        details_->setHtml(ItemDescription::projectHtml(*project_));
    } else if (const Stream* stream = project_->stream(path)) {
        details_->setHtml(ItemDescription::streamHtml(path, stream->info()));
    } else if (const Table* table = project_->table(path)) {
        details_->setHtml(ItemDescription::tableHtml(path, *table));
    } else if (const Recording* recording = project_->recording(path)) {
        details_->setHtml(ItemDescription::recordingHtml(*recording));
    }
}

// --- workspace: processors and tools ----------------------------------------------------------

void MainWindow::createToolMenus(QMenu* file, QMenu* processing, QMenu* view)
{
    // Menus appear in the order tools first name them, between Processing and Help.
    std::vector<std::pair<QString, QMenu*>> menus{{QStringLiteral("File"), file},
                                                  {QStringLiteral("Processing"), processing},
                                                  {QStringLiteral("View"), view}};
    QList<QMenu*> separated;
    for (const ToolEntry& entry : registeredTools()) {
        const QString menuName = QString::fromUtf8(entry.menu ? entry.menu : "Processing");
        auto it = std::find_if(menus.begin(), menus.end(), [&](const auto& m) { return m.first == menuName; });
        QMenu* menu = nullptr;
        if (it == menus.end()) {
            menu = menuBar()->addMenu(QCoreApplication::translate("Tools", entry.menu));
            menus.emplace_back(menuName, menu);
        } else {
            menu = it->second;
        }
        if ((menu == processing || menu == view) && !separated.contains(menu)) {
            menu->addSeparator();
            separated << menu;
        }
        QAction* action = menu->addAction(QCoreApplication::translate("Tools", entry.text));
        action->setData(entry.id);
        action->setObjectName(entry.id);
        const auto launch = entry.launch;
        connect(action, &QAction::triggered, this, [this, launch] {
            if (launch && !busy_) launch(*this);
        });
        toolActions_ << action;
    }
}

void MainWindow::addDock(QDockWidget* dock, Qt::DockWidgetArea area)
{
    dock->setParent(this);
    addDockWidget(area, dock);
    if (viewMenu_ && !viewMenu_->actions().contains(dock->toggleViewAction())) viewMenu_->addAction(dock->toggleViewAction());
    dock->show();
    dock->raise();
}

QAction* MainWindow::toolAction(const QString& id) const
{
    for (QAction* action : toolActions_)
        if (action->data().toString() == id) return action;
    return nullptr;
}

Expected<RunOutcome> MainWindow::runProcessor(const RunRequest& request)
{
    if (!project_) return makeError(tr("Open a project first."));
    if (busy_) return makeError(tr("Another job is still running."));
    const auto processor = ProcessorRegistry::instance().find(request.processorId);
    if (!processor) return makeError(tr("Unknown processor '%1'.").arg(request.processorId));

    // The runner reads the inputs and finally inserts the outputs on the worker. Panel loads
    // must not read concurrently, and a panel must not show a stream that is about to be
    // replaced in place (re-running into the same output).
    waitForLoads();
    const auto replaced = [&](const Stream* shown) {
        if (!shown) return false;
        for (const QString& path : project_->streamPaths())
            if (project_->stream(path) == shown
                && (path == request.output || path.startsWith(request.output + QLatin1Char('-'))))
                return true;
        return false;
    };
    if (replaced(timeSeries_->stream())) timeSeries_->clear();
    if (replaced(trajectory_->stream())) trajectory_->clear();

    std::shared_ptr<Project> project = project_;
    auto result = std::make_shared<std::optional<Expected<RunOutcome>>>();
    setBusy(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        this, tr("Running %1…").arg(processor->name()),
        [project, processor, request, result](const Progress& progress) -> Status {
            *result = athlos::runProcessor(*project, *processor, request, progress);
            if (!result->value()) return result->value().error();
            return {};
        },
        interactive_);
    setBusy(false);
    if (outcome.cancelled && !outcome.status) {
        statusBar()->showMessage(tr("%1 cancelled; the project is unchanged.").arg(processor->name()), 5000);
        return makeError(tr("Cancelled; the project is unchanged."));
    }
    if (!result->has_value()) return makeError(outcome.status ? tr("The processor did not run.") : outcome.status.message());
    Expected<RunOutcome> run = std::move(**result);
    if (!run) return run;
    project_->setModified(true);
    projectModified();
    if (!run->written.isEmpty()) selectItem(run->written.front());
    statusBar()->showMessage(tr("%1 wrote %2").arg(processor->name(), run->written.join(QStringLiteral(", "))), 8000);
    return run;
}

void MainWindow::projectModified()
{
    if (!project_) return;
    const QString current = currentItem();
    treeModel_->refresh();
    tree_->expandAll();
    for (int c = 0; c < ProjectTreeModel::ColumnsColumn; ++c) tree_->resizeColumnToContents(c);
    if (!current.isEmpty()) selectItem(current);
    updateTitle();
    emit projectChanged();
}

void MainWindow::showItem(const QString& path)
{
    if (!selectItem(path)) return;
    const Stream* stream = project_ ? project_->stream(path) : nullptr;
    if (stream && TrajectoryPanel::isPositionStream(stream->info()) && tabs_->currentWidget() == trajectory_) return;
    if (stream) showTimeSeriesView();
}

RunRequest MainWindow::rerunRequest(const QString& path) const
{
    if (!project_) return {};
    const Provenance* provenance = nullptr;
    if (const Stream* stream = project_->stream(path)) provenance = &stream->info().provenance;
    else if (const Table* table = project_->table(path)) provenance = &table->provenance;
    if (!provenance || !ItemDescription::isResult(*provenance)) return {};
    RunRequest request;
    request.processorId = provenance->processorId;
    for (const ProvenanceInput& input : provenance->inputs) request.inputs << input.name;
    request.parameters = provenance->parameters.toVariantMap();
    request.output = path;
    return request;
}

void MainWindow::openProcessorDialog(const RunRequest& prefill)
{
    if (!project_ || busy_) return;
    ProcessorDialog dialog(*this, this);
    if (!prefill.processorId.isEmpty() && !dialog.setRequest(prefill)) {
        showError(tr("Re-run"), tr("The processor '%1' is not available (is its plugin installed?).")
                                    .arg(prefill.processorId));
        return;
    }
    dialog.exec();
}

void MainWindow::showTreeContextMenu(const QPoint& pos)
{
    if (!project_ || busy_) return;
    const QString path = treeModel_->pathOf(tree_->indexAt(pos));
    QMenu menu(this);
    const RunRequest rerun = rerunRequest(path);
    if (!rerun.processorId.isEmpty()) {
        menu.addAction(tr("Re-run with Changed Parameters…"), this, [this, rerun] { openProcessorDialog(rerun); });
        menu.addSeparator();
    }
    menu.addAction(runProcessorAction_);
    menu.exec(tree_->viewport()->mapToGlobal(pos));
}

// --- time panels and layout -------------------------------------------------------------------

namespace {
const QString kLayoutKey = QStringLiteral("ui_layout");
const QString kPanelsKey = QStringLiteral("ui_panels");
}  // namespace

QList<TimeSeriesPanel*> MainWindow::timeSeriesPanels() const
{
    QList<TimeSeriesPanel*> panels{timeSeries_};
    for (const ExtraPanel& extra : extraPanels_) panels << extra.panel;
    return panels;
}

TimeSeriesPanel* MainWindow::addTimeSeriesPanel(const QString& path)
{
    std::shared_ptr<const Stream> stream = sharedStream(path);
    if (!stream) return nullptr;
    ExtraPanel extra;
    extra.path = path;
    extra.dock = new QDockWidget(path, this);
    // Stable names: saveState/restoreState match docks by object name.
    extra.dock->setObjectName(QStringLiteral("timeSeriesDock%1").arg(nextPanelNumber_++));
    extra.dock->setAttribute(Qt::WA_DeleteOnClose);
    extra.panel = new TimeSeriesPanel(extra.dock);
    extra.panel->setTimeController(timeController_);
    addExportMenu(extra.panel->plot());
    extra.dock->setWidget(extra.panel);
    addDockWidget(Qt::BottomDockWidgetArea, extra.dock);
    connect(extra.panel, &TimeSeriesPanel::loaded, this, &MainWindow::updateTimeBounds);
    QDockWidget* dock = extra.dock;
    connect(dock, &QObject::destroyed, this, [this, dock] {
        extraPanels_.removeIf([dock](const ExtraPanel& e) { return e.dock == dock; });
    });
    extra.panel->setStream(std::move(stream), path);
    extraPanels_ << extra;
    return extra.panel;
}

void MainWindow::removeExtraPanels()
{
    const QList<ExtraPanel> panels = extraPanels_;
    extraPanels_.clear();
    for (const ExtraPanel& extra : panels) {
        extra.panel->waitForLoad();
        extra.panel->clear();
        removeDockWidget(extra.dock);
        delete extra.dock;
    }
    nextPanelNumber_ = 1;
}

void MainWindow::updateTimeBounds()
{
    double begin = std::numeric_limits<double>::infinity(), end = -begin, step = 0;
    for (TimeSeriesPanel* panel : timeSeriesPanels()) {
        const StreamData* data = panel->data();
        if (!data || data->rows() == 0) continue;
        begin = std::min(begin, data->t.front());
        end = std::max(end, data->t.back());
        if (panel == timeSeries_ || step == 0) step = data->medianInterval();
    }
    if (!(begin <= end)) return;
    // The view the panel chose (its full range) survives the reset of the bounds.
    const double viewBegin = timeSeries_->data() ? timeController_->visibleBegin() : begin;
    const double viewEnd = timeSeries_->data() ? timeController_->visibleEnd() : end;
    timeController_->setBounds(begin, end);
    if (step > 0) timeController_->setStep(step);
    timeController_->setVisibleRange(viewBegin, viewEnd);
}

void MainWindow::storeLayout()
{
    if (!project_) return;
    QJsonArray panels;
    for (const ExtraPanel& extra : extraPanels_)
        panels.append(QJsonObject{{QStringLiteral("name"), extra.dock->objectName()},
                                  {QStringLiteral("stream"), extra.path}});
    QJsonObject& meta = project_->meta().extra;
    meta[kPanelsKey] = panels;
    meta[kLayoutKey] = QString::fromLatin1(saveState().toBase64());
}

void MainWindow::restoreLayout()
{
    if (!project_) return;
    const QJsonObject& meta = project_->meta().extra;
    int highest = 0;
    for (const QJsonValue& value : meta.value(kPanelsKey).toArray()) {
        const QJsonObject panel = value.toObject();
        const QString name = panel.value(QStringLiteral("name")).toString();
        bool ok = false;
        const int number = name.mid(QStringLiteral("timeSeriesDock").size()).toInt(&ok);
        if (!ok) continue;
        nextPanelNumber_ = number;  // reuse the saved name so restoreState finds the dock
        if (addTimeSeriesPanel(panel.value(QStringLiteral("stream")).toString())) highest = std::max(highest, number);
    }
    nextPanelNumber_ = highest + 1;
    const QByteArray state = QByteArray::fromBase64(meta.value(kLayoutKey).toString().toLatin1());
    if (!state.isEmpty()) restoreState(state);
}

// --- annotation ---------------------------------------------------------------------------------

void MainWindow::createAnnotationTool()
{
    annotationEditor_ = new AnnotationEditor(this);
    annotationLayer_ = new AnnotationLayer(timeSeries_, annotationEditor_);
    annotationPanel_ = new AnnotationPanel(annotationEditor_, annotationLayer_, this);
    annotationDock_ = new QDockWidget(tr("Annotations"), this);
    annotationDock_->setObjectName(QStringLiteral("annotationDock"));
    annotationDock_->setWidget(annotationPanel_);
    addDockWidget(Qt::RightDockWidgetArea, annotationDock_);
    annotationDock_->hide();

    autosaveTimer_ = new QTimer(this);
    autosaveTimer_->setSingleShot(true);
    autosaveTimer_->setInterval(QSettings().value(QStringLiteral("annotation/autosave_seconds"), 30).toInt() * 1000);
    connect(autosaveTimer_, &QTimer::timeout, this, [this] { autosave(); });
    connect(annotationEditor_, &AnnotationEditor::annotationsChanged, this, [this] {
        updateTitle();
        // Idle autosave: every edit postpones it.
        if (autosaveTimer_->interval() > 0) autosaveTimer_->start();
    });
    connect(annotationEditor_, &AnnotationEditor::classesChanged, this, &MainWindow::updateTitle);
    connect(annotationEditor_, &AnnotationEditor::errorOccurred, this, [this](const QString& message) {
        statusBar()->showMessage(message, 8000);
        emit errorReported(message);
    });
}

void MainWindow::showAnnotationPanel()
{
    annotationDock_->show();
    annotationDock_->raise();
}

void MainWindow::setAutosaveDelay(int milliseconds)
{
    autosaveTimer_->stop();
    autosaveTimer_->setInterval(std::max(0, milliseconds));
}

bool MainWindow::autosave()
{
    if (!project_ || busy_ || !project_->isModified()) return false;
    waitForLoads();
    std::shared_ptr<Project> project = project_;
    // Not setBusy(): the window stays usable; only commands that change the project wait.
    busy_ = true;
    annotationEditor_->setLocked(true);
    const BackgroundTask::Outcome outcome = BackgroundTask::run(
        this, tr("Saving…"), [project](const Progress& progress) { return project->save(progress); }, false);
    busy_ = false;
    annotationEditor_->setLocked(false);
    if (!outcome.status) {
        statusBar()->showMessage(tr("Autosave failed: %1 (the journal keeps your edits)").arg(outcome.status.message()), 8000);
        return false;
    }
    project_->setModified(false);
    afterSave();
    updateTitle();
    statusBar()->showMessage(tr("Autosaved"), 3000);
    return true;
}

void MainWindow::afterSave()
{
    // The file now has every edit; a new journal starts (at the new path after Save As).
    annotationEditor_->journal().discard();
    annotationEditor_->journal().setProjectPath(project_->path());
}

void MainWindow::recoverJournal()
{
    if (!project_ || !AnnotationJournal::hasPendingEdits(project_->path())) return;
    if (interactive_) {
        const auto answer = QMessageBox::question(
            this, tr("Recover annotations"),
            tr("%1 has annotation edits that were not saved (the program ended unexpectedly). Recover them?")
                .arg(QFileInfo(project_->path()).fileName()),
            QMessageBox::Yes | QMessageBox::Discard, QMessageBox::Yes);
        if (answer != QMessageBox::Yes) {
            annotationEditor_->journal().discard();
            return;
        }
    }
    auto replayed = AnnotationJournal::replay(*project_);
    if (!replayed) {
        showError(tr("Could not recover annotations"), replayed.message());
        return;
    }
    // The journal stays until the next save: the file still lacks these edits.
    annotationEditor_->setProject(project_.get());
    annotationLayer_->rebuild();
    annotationPanel_->refresh();
    updateTitle();
    statusBar()->showMessage(tr("Annotation edits recovered from the journal: %1").arg(*replayed), 8000);
}

void MainWindow::addExportMenu(QCustomPlot* plot)
{
    plot->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(plot, &QWidget::customContextMenuRequested, this, [this, plot](const QPoint& pos) {
        QMenu menu(this);
        menu.addAction(tr("Export View…"), this, [this, plot] {
            const QString written = PlotExporter::exportDialog(plot, this);
            if (!written.isEmpty()) statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(written)), 5000);
        });
        menu.addAction(showAllAction_);
        menu.exec(plot->mapToGlobal(pos));
    });
}

}  // namespace athlos::ui
