#pragma once
// The main window: project tree and details on the left, time-series and trajectory panels in
// the centre. A thin shell: every change to the project goes through core (Project, importFile,
// applyImport, save), long jobs run on worker threads.
#include "ui/Workspace.h"

#include <QList>
#include <QMainWindow>
#include <QString>
#include <QStringList>
#include <memory>

class QAction;
class QCustomPlot;
class QDockWidget;
class QMenu;
class QModelIndex;
class QTabWidget;
class QTimer;
class QTextBrowser;
class QTreeView;

namespace athlos {
class Project;
class Stream;
}  // namespace athlos

namespace athlos::ui {

class AnnotationEditor;
class AnnotationLayer;
class AnnotationPanel;
class ProjectTreeModel;
class TimeController;
class TimeSeriesPanel;
class TrajectoryPanel;

class MainWindow : public QMainWindow, public Workspace {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Non-interactive: no modal dialogs. Errors go to errorReported() and the status bar, and
    // unsaved changes are discarded without asking (tests, offscreen rendering).
    void setInteractive(bool interactive) { interactive_ = interactive; }
    bool isInteractive() const { return interactive_; }

    Project* project() const { return project_.get(); }

    // Workspace ------------------------------------------------------------------------
    Project* project() override { return project_.get(); }
    using QWidget::window;
    QWidget* window() override { return this; }
    // The window takes no input while the processor runs (the worker mutates the project).
    Expected<RunOutcome> runProcessor(const RunRequest& request) override;
    void projectModified() override;
    void showItem(const QString& path) override;

    // Processing → Run processor…, optionally pre-filled (re-run from provenance).
    void openProcessorDialog(const RunRequest& prefill = {});
    // The request that produced the result at path (processor, inputs, parameters, output),
    // or an empty request if path is not a processor result.
    RunRequest rerunRequest(const QString& path) const;
    // The menu action of a registered tool (by ToolEntry::id), for tests.
    QAction* toolAction(const QString& id) const;
    // Replaces the current project without asking about unsaved changes.
    void setProject(std::shared_ptr<Project> project);

    // The user-level operations; each reports its own errors and returns whether it succeeded.
    bool newProject(const QString& path);
    bool openProject(const QString& path);
    bool saveProject();
    bool saveProjectAs(const QString& path);
    // Imports every file (format detected, recording named after the file) on a worker thread.
    // All or nothing: the project changes only if every file was read and every name is free.
    bool importFiles(const QStringList& files);

    // Selects "rec" or "rec/item" in the project tree; a stream is then plotted.
    bool selectItem(const QString& path);
    QString currentItem() const;
    void showTimeSeriesView();
    void showTrajectoryView();
    // The first stream of the first recording that has one, and the first position-like stream.
    QString firstStream() const;
    QString firstPositionStream() const;
    // Blocks until both panels finished loading and lays out and replots them.
    void waitForPlots();

    // The one time cursor every time panel follows.
    TimeController* timeController() const override { return timeController_; }
    void addDock(QDockWidget* dock, Qt::DockWidgetArea area = Qt::BottomDockWidgetArea) override;
    // Another time-series panel in a dock, linked to the cursor, plotting path ("rec/stream").
    TimeSeriesPanel* addTimeSeriesPanel(const QString& path);
    // The central panel first, then the docked ones.
    QList<TimeSeriesPanel*> timeSeriesPanels() const;
    // The window layout (docks, their streams) goes into the project's metadata on save and
    // is restored on open, so every project reopens as it was left.
    void storeLayout();
    void restoreLayout();

    // Annotation tool on the main time-series panel.
    AnnotationEditor* annotationEditor() const { return annotationEditor_; }
    AnnotationLayer* annotationLayer() const { return annotationLayer_; }
    AnnotationPanel* annotationPanel() const { return annotationPanel_; }
    void showAnnotationPanel();
    // Idle time after an edit before the project is saved in the background (0 = never).
    void setAutosaveDelay(int milliseconds);
    // Saves without dialog and without taking input away; annotation edits wait meanwhile.
    bool autosave();

    TimeSeriesPanel* timeSeriesPanel() const { return timeSeries_; }
    TrajectoryPanel* trajectoryPanel() const { return trajectory_; }
    ProjectTreeModel* treeModel() const { return treeModel_; }
    QTreeView* treeView() const { return tree_; }
    QTextBrowser* detailsView() const { return details_; }

signals:
    void errorReported(const QString& message);
    void projectChanged();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    void createActions();
    void createMenus();
    void createDocks();
    void createToolMenus(QMenu* file, QMenu* processing, QMenu* view);
    void removeExtraPanels();
    void addExportMenu(QCustomPlot* plot);
    void createAnnotationTool();
    // Offers (interactive) or applies (tests, offscreen) the crash journal of a just opened project.
    void recoverJournal();
    void afterSave();
    void updateTimeBounds();
    void showTreeContextMenu(const QPoint& pos);
    void updateTitle();
    void updateActions();
    void rebuildRecentMenu();
    bool maybeSaveChanges();
    // While a background job runs, the window takes no commands (the progress dialog appears
    // only after a moment, and until then the window would still accept input).
    void setBusy(bool busy);
    void waitForLoads();
    void showError(const QString& title, const QString& message);
    void showDetails(const QString& path);
    void plotItem(const QString& path);
    std::shared_ptr<const Stream> sharedStream(const QString& path) const;
    void onCurrentChanged(const QModelIndex& current);
    void onActivated(const QModelIndex& index);

    void newProjectDialog();
    void openProjectDialog();
    void saveAsDialog();
    void importDialog();
    void about();

    std::shared_ptr<Project> project_;
    bool interactive_ = true;
    bool busy_ = false;  // a background job runs inside a nested event loop

    ProjectTreeModel* treeModel_ = nullptr;
    QTreeView* tree_ = nullptr;
    QTextBrowser* details_ = nullptr;
    QTabWidget* tabs_ = nullptr;
    TimeSeriesPanel* timeSeries_ = nullptr;
    TrajectoryPanel* trajectory_ = nullptr;
    TimeController* timeController_ = nullptr;
    struct ExtraPanel {
        QDockWidget* dock = nullptr;
        TimeSeriesPanel* panel = nullptr;
        QString path;
    };
    QList<ExtraPanel> extraPanels_;
    AnnotationEditor* annotationEditor_ = nullptr;
    AnnotationLayer* annotationLayer_ = nullptr;
    AnnotationPanel* annotationPanel_ = nullptr;
    QDockWidget* annotationDock_ = nullptr;
    QTimer* autosaveTimer_ = nullptr;
    int nextPanelNumber_ = 1;

    QMenu* recentMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QAction* newAction_ = nullptr;
    QAction* openAction_ = nullptr;
    QAction* saveAction_ = nullptr;
    QAction* saveAsAction_ = nullptr;
    QAction* importAction_ = nullptr;
    QAction* quitAction_ = nullptr;
    QAction* aboutAction_ = nullptr;
    QAction* runProcessorAction_ = nullptr;
    QAction* addPanelAction_ = nullptr;
    QAction* showAllAction_ = nullptr;
    QAction* exportViewAction_ = nullptr;
    QAction* undoAction_ = nullptr;
    QAction* redoAction_ = nullptr;
    QAction* annotateModeAction_ = nullptr;
    QAction* addClassAction_ = nullptr;
    QAction* preferencesAction_ = nullptr;
    QList<QAction*> toolActions_;
};

}  // namespace athlos::ui
