#include "ui/MainWindow.h"

#include "core/io/Importer.h"
#include "core/model/Project.h"
#include "core/util/Version.h"
#include "ui/BackgroundTask.h"
#include "ui/ItemDescription.h"
#include "ui/ProjectTreeModel.h"
#include "ui/RecentProjects.h"
#include "ui/TimeSeriesPanel.h"
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
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>
#include <QTabWidget>
#include <QTextBrowser>
#include <QTimer>
#include <QTreeView>
#include <qcustomplot.h>

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

    timeSeries_ = new TimeSeriesPanel(this);
    trajectory_ = new TrajectoryPanel(this);
    tabs_ = new QTabWidget(this);
    tabs_->setDocumentMode(true);
    tabs_->addTab(timeSeries_, tr("Time series"));
    tabs_->addTab(trajectory_, tr("Trajectory"));
    setCentralWidget(tabs_);

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
    file->addSeparator();
    file->addAction(quitAction_);

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
    timeSeries_->clear();
    trajectory_->clear();
    treeModel_->setProject(project.get());
    project_ = std::move(project);
    tree_->expandAll();
    for (int c = 0; c < ProjectTreeModel::ColumnsColumn; ++c) tree_->resizeColumnToContents(c);
    details_->setHtml(project_ ? ItemDescription::projectHtml(*project_) : QString());
    if (project_) statusBar()->clearMessage();
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
    return true;
}

bool MainWindow::saveProject()
{
    if (!project_) return false;
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
    updateTitle();
    statusBar()->showMessage(tr("Saved %1").arg(QDir::toNativeSeparators(project_->path())), 5000);
    return true;
}

bool MainWindow::saveProjectAs(const QString& path)
{
    if (!project_) return false;
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
    menuBar()->setEnabled(!busy);
    centralWidget()->setEnabled(!busy);
    for (QDockWidget* dock : findChildren<QDockWidget*>()) dock->setEnabled(!busy);
    for (QAction* action : {newAction_, openAction_, saveAction_, saveAsAction_, importAction_, quitAction_})
        action->setEnabled(!busy);
    if (!busy) updateActions();
}

void MainWindow::updateActions()
{
    const bool open = project_ != nullptr;
    saveAction_->setEnabled(open);
    saveAsAction_->setEnabled(open);
    importAction_->setEnabled(open);
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
    timeSeries_->waitForLoad();
    trajectory_->waitForLoad();
}

void MainWindow::waitForPlots()
{
    timeSeries_->waitForLoad();
    trajectory_->waitForLoad();
    // Layout first (plot widths decide the decimation), then draw synchronously.
    for (int i = 0; i < 3; ++i) {
        QCoreApplication::processEvents();
        timeSeries_->plot()->replot(QCustomPlot::rpImmediateRefresh);
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
    if (timeSeries_->stream() != stream.get()) timeSeries_->setStream(stream, path);
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

}  // namespace athlos::ui
