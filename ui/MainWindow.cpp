#include "ui/MainWindow.h"

#include "core/model/Project.h"
#include "ui/AnnotationEditor.h"
#include "ui/AnnotationLayer.h"
#include "ui/AnnotationPanel.h"
#include "ui/PanelLayout.h"
#include "ui/ProcessorLauncher.h"
#include "ui/ProjectBrowser.h"
#include "ui/ProjectSession.h"
#include "ui/TimeSeriesPanel.h"
#include "ui/TrajectoryPanel.h"
#include "ui/WindowActions.h"
#include "ui/WorkspaceNotifier.h"

#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <qcustomplot.h>

namespace athlos::ui {

namespace {

QStringList localFiles(const QMimeData* mime) {
    QStringList files;
    if (!mime || !mime->hasUrls()) return files;
    for (const QUrl& url : mime->urls())
        if (url.isLocalFile() && QFileInfo(url.toLocalFile()).isFile()) files << url.toLocalFile();
    return files;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowIcon(QIcon(QStringLiteral(":/athlos/icons/athlos.svg")));
    setAcceptDrops(true);
    notifier_ = new WorkspaceNotifier(this);
    connect(this, &MainWindow::projectChanged, notifier_, &WorkspaceNotifier::projectChanged);

    // Order matters: the actions need the panels, the annotation editor and the session.
    panels_ = new PanelLayout(*this);
    createAnnotationTool();
    browser_ = new ProjectBrowser(*this);
    session_ = std::make_unique<ProjectSession>(*this);
    launcher_ = std::make_unique<ProcessorLauncher>(*this);
    actions_ = std::make_unique<WindowActions>(*this);

    actions_->addExportMenu(panels_->timeSeries()->plot());
    actions_->addExportMenu(panels_->trajectory()->plot());
    connect(panels_, &PanelLayout::plotAdded, this, [this](QCustomPlot* plot) { actions_->addExportMenu(plot); });
    connect(browser_, &ProjectBrowser::streamSelected, this, &MainWindow::plotItem);
    connect(browser_, &ProjectBrowser::streamActivated, this, &MainWindow::onActivated);
    connect(browser_, &ProjectBrowser::contextMenuRequested, this, [this](const QString& path, const QPoint& pos) {
        launcher_->showContextMenu(path, pos, actions_->runProcessorAction());
    });

    statusBar()->showMessage(tr("Open a project, or drop recordings onto the window to import them."));
    resize(1280, 800);
    updateTitle();
    actions_->updateEnabled(false);
}

MainWindow::~MainWindow() {
    // Panels may hold pointers into the project; drop them before the project goes.
    panels_->setProject(nullptr);
    browser_->setProject(nullptr);
}

void MainWindow::createAnnotationTool() {
    annotationEditor_ = new AnnotationEditor(this);
    annotationLayer_ = new AnnotationLayer(panels_->timeSeries(), annotationEditor_);
    annotationPanel_ = new AnnotationPanel(annotationEditor_, annotationLayer_, this);
    annotationDock_ = new QDockWidget(tr("Annotations"), this);
    annotationDock_->setObjectName(QStringLiteral("annotationDock"));
    annotationDock_->setWidget(annotationPanel_);
    addDockWidget(Qt::RightDockWidgetArea, annotationDock_);
    annotationDock_->hide();

    connect(annotationEditor_, &AnnotationEditor::annotationsChanged, this, &MainWindow::updateTitle);
    connect(annotationEditor_, &AnnotationEditor::classesChanged, this, &MainWindow::updateTitle);
    connect(annotationEditor_, &AnnotationEditor::errorOccurred, this, [this](const QString& message) {
        statusBar()->showMessage(message, 8000);
        emit errorReported(message);
    });
}

void MainWindow::setProject(std::shared_ptr<Project> project) {
    panels_->setProject(project);
    annotationLayer_->setRecording({});
    project_ = std::move(project);
    browser_->setProject(project_.get());
    annotationEditor_->setProject(project_.get());
    if (project_) statusBar()->clearMessage();
    panels_->restoreLayout();
    updateTitle();
    actions_->updateEnabled(project_ != nullptr);
    emit projectChanged();
}

// --- project lifecycle: ProjectSession ----------------------------------------------------------

bool MainWindow::newProject(const QString& path) { return session_->newProject(path); }
bool MainWindow::openProject(const QString& path) { return session_->openProject(path); }
bool MainWindow::saveProject() { return session_->saveProject(); }
bool MainWindow::saveProjectAs(const QString& path) { return session_->saveProjectAs(path); }
bool MainWindow::importFiles(const QStringList& files) { return session_->importFiles(files); }
void MainWindow::setAutosaveDelay(int milliseconds) { session_->setAutosaveDelay(milliseconds); }
bool MainWindow::autosave() { return session_->autosave(); }

// --- workspace: ProcessorLauncher ---------------------------------------------------------------

Expected<RunOutcome> MainWindow::runProcessor(const RunRequest& request) { return launcher_->run(request); }
RunRequest MainWindow::rerunRequest(const QString& path) const { return launcher_->rerunRequest(path); }
void MainWindow::openProcessorDialog(const RunRequest& prefill) { launcher_->openDialog(prefill); }
QAction* MainWindow::toolAction(const QString& id) const { return actions_->toolAction(id); }

void MainWindow::projectModified() {
    if (!project_) return;
    const QString current = currentItem();
    browser_->refresh();
    if (!current.isEmpty()) selectItem(current);
    updateTitle();
    emit projectChanged();
}

void MainWindow::showItem(const QString& path) {
    if (!selectItem(path)) return;
    const Stream* stream = project_ ? project_->stream(path) : nullptr;
    if (stream && TrajectoryPanel::isPositionStream(stream->info()) && panels_->isTrajectoryShown()) return;
    if (stream) showTimeSeriesView();
}

void MainWindow::addDock(QDockWidget* dock, Qt::DockWidgetArea area) {
    dock->setParent(this);
    addDockWidget(area, dock);
    actions_->addToViewMenu(dock->toggleViewAction());
    dock->show();
    dock->raise();
}

void MainWindow::resizeDock(QDockWidget* dock, int size, Qt::Orientation orientation) {
    resizeDocks({dock}, {size}, orientation);
}

// --- panels: PanelLayout ------------------------------------------------------------------------

TimeController* MainWindow::timeController() const { return panels_->timeController(); }
TimeSeriesPanel* MainWindow::addTimeSeriesPanel(const QString& path) { return panels_->addTimeSeriesPanel(path); }
QList<TimeSeriesPanel*> MainWindow::timeSeriesPanels() const { return panels_->timeSeriesPanels(); }
void MainWindow::storeLayout() { panels_->storeLayout(); }
void MainWindow::restoreLayout() { panels_->restoreLayout(); }
void MainWindow::showTimeSeriesView() { panels_->showTimeSeriesView(); }
void MainWindow::showTrajectoryView() { panels_->showTrajectoryView(); }
void MainWindow::waitForPlots() { panels_->waitForPlots(); }

void MainWindow::addView(QWidget* view, const QString& title) {
    panels_->tabs()->setCurrentIndex(panels_->tabs()->addTab(view, title));
}
TimeSeriesPanel* MainWindow::timeSeriesPanel() const { return panels_->timeSeries(); }
TrajectoryPanel* MainWindow::trajectoryPanel() const { return panels_->trajectory(); }

void MainWindow::plotItem(const QString& path) {
    if (!panels_->plot(path)) return;
    // The annotations shown are those of the plotted stream's recording.
    annotationLayer_->setRecording(ItemPath::parse(path).recording);
    annotationPanel_->refresh();
}

void MainWindow::onActivated(const QString& path) {
    const Stream* stream = project_ ? project_->stream(path) : nullptr;
    // Double-click brings the plot forward; a position stream stays on the trajectory if shown.
    if (!(stream && panels_->isTrajectoryShown() && TrajectoryPanel::isPositionStream(stream->info())))
        showTimeSeriesView();
}

QString MainWindow::firstStream() const {
    if (!project_) return {};
    for (const auto& [name, recording] : project_->recordings())
        if (!recording.streams.empty()) return name + QLatin1Char('/') + recording.streams.begin()->first;
    return {};
}

QString MainWindow::firstPositionStream() const {
    if (!project_) return {};
    for (const auto& [name, recording] : project_->recordings())
        for (const auto& [streamName, stream] : recording.streams)
            if (TrajectoryPanel::isPositionStream(stream.info())) return name + QLatin1Char('/') + streamName;
    return {};
}

// --- tree: ProjectBrowser -----------------------------------------------------------------------

bool MainWindow::selectItem(const QString& path) { return browser_->selectItem(path); }
QString MainWindow::currentItem() const { return browser_->currentItem(); }
ProjectTreeModel* MainWindow::treeModel() const { return browser_->model(); }
QTreeView* MainWindow::treeView() const { return browser_->view(); }
QTextBrowser* MainWindow::detailsView() const { return browser_->details(); }

// --- annotation ---------------------------------------------------------------------------------

void MainWindow::showAnnotationPanel() {
    annotationDock_->show();
    annotationDock_->raise();
}

// --- window chrome ------------------------------------------------------------------------------

void MainWindow::showError(const QString& title, const QString& message) {
    statusBar()->showMessage(title, 8000);
    emit errorReported(message);
    if (interactive_) QMessageBox::critical(this, title, message);
}

void MainWindow::updateTitle() {
    if (!project_) {
        setWindowTitle(tr("Athlos"));
        setWindowModified(false);
        return;
    }
    // "[*]" is where Qt shows '*' while the window is modified.
    setWindowTitle(tr("%1[*] — Athlos").arg(QFileInfo(project_->path()).completeBaseName()));
    setWindowModified(project_->isModified());
}

void MainWindow::setBusy(bool busy) {
    busy_ = busy;
    annotationEditor_->setLocked(busy);
    menuBar()->setEnabled(!busy);
    centralWidget()->setEnabled(!busy);
    for (QDockWidget* dock : findChildren<QDockWidget*>()) dock->setEnabled(!busy);
    actions_->setBusy(busy, project_ != nullptr);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (busy_ || !session_->maybeSaveChanges()) {
        event->ignore();
        return;
    }
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    if (!busy_ && !localFiles(event->mimeData()).isEmpty()) event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QStringList files = localFiles(event->mimeData());
    if (files.isEmpty() || busy_) return;
    event->acceptProposedAction();
    // Not inside the drop handler: the import spins an event loop and may show dialogs, which
    // must not happen while the platform's drag-and-drop is still in progress.
    QTimer::singleShot(0, this, [this, files] { importFiles(files); });
}

}  // namespace athlos::ui
