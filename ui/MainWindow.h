#pragma once
// The main window: project tree and details on the left, time-series and trajectory panels in
// the centre. A thin shell: every change to the project goes through core (Project, importFile,
// applyImport, save), long jobs run on worker threads. The window composes its parts and
// implements Workspace; the parts do the work: ProjectSession (new, open, save, autosave,
// import, journal recovery), WindowActions (menus), PanelLayout (plots, docks, stored layout),
// ProjectBrowser (tree, details) and ProcessorLauncher (processor runs).
#include "ui/Workspace.h"

#include <QList>
#include <QMainWindow>
#include <QString>
#include <QStringList>
#include <memory>

class QAction;
class QDockWidget;
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
class PanelLayout;
class ProcessorLauncher;
class ProjectBrowser;
class ProjectSession;
class ProjectTreeModel;
class TimeController;
class TimeSeriesPanel;
class TrajectoryPanel;
class WindowActions;
class WorkspaceNotifier;

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
    void addView(QWidget* view, const QString& title) override;
    void resizeDock(QDockWidget* dock, int size, Qt::Orientation orientation) override;
    // Emits projectChanged() whenever the window does.
    WorkspaceNotifier* notifier() override { return notifier_; }

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
    bool selectItem(const QString& path) override;
    QString currentItem() const override;
    void showTimeSeriesView() override;
    void showTrajectoryView();
    // The first stream of the first recording that has one, and the first position-like stream.
    QString firstStream() const;
    QString firstPositionStream() const;
    // Blocks until both panels finished loading and lays out and replots them.
    void waitForPlots() override;

    // The one time cursor every time panel follows.
    TimeController* timeController() const override;
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
    AnnotationEditor* annotationEditor() const override { return annotationEditor_; }
    AnnotationLayer* annotationLayer() const { return annotationLayer_; }
    AnnotationPanel* annotationPanel() const { return annotationPanel_; }
    void showAnnotationPanel();
    // Idle time after an edit before the project is saved in the background (0 = never).
    void setAutosaveDelay(int milliseconds);
    // Saves without dialog and without taking input away; annotation edits wait meanwhile.
    bool autosave();

    TimeSeriesPanel* timeSeriesPanel() const;
    TrajectoryPanel* trajectoryPanel() const;
    ProjectTreeModel* treeModel() const;
    QTreeView* treeView() const;
    QTextBrowser* detailsView() const;

signals:
    void errorReported(const QString& message);
    void projectChanged();

protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

private:
    // The window's parts; each has one job and works on the window's shared state below.
    friend class ProjectSession;
    friend class ProcessorLauncher;
    friend class WindowActions;

    void createAnnotationTool();
    void updateTitle();
    // While a background job runs, the window takes no commands (the progress dialog appears
    // only after a moment, and until then the window would still accept input).
    void setBusy(bool busy);
    void showError(const QString& title, const QString& message);
    void plotItem(const QString& path);
    void onActivated(const QString& path);

    std::shared_ptr<Project> project_;
    bool interactive_ = true;
    bool busy_ = false;  // a background job runs inside a nested event loop

    WorkspaceNotifier* notifier_ = nullptr;
    PanelLayout* panels_ = nullptr;
    ProjectBrowser* browser_ = nullptr;
    AnnotationEditor* annotationEditor_ = nullptr;
    AnnotationLayer* annotationLayer_ = nullptr;
    AnnotationPanel* annotationPanel_ = nullptr;
    QDockWidget* annotationDock_ = nullptr;
    std::unique_ptr<ProjectSession> session_;
    std::unique_ptr<ProcessorLauncher> launcher_;
    std::unique_ptr<WindowActions> actions_;
};

}  // namespace athlos::ui
