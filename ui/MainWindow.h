#pragma once
// The main window: project tree and details on the left, time-series and trajectory panels in
// the centre. A thin shell: every change to the project goes through core (Project, importFile,
// applyImport, save), long jobs run on worker threads.
#include <QMainWindow>
#include <QString>
#include <QStringList>
#include <memory>

class QAction;
class QMenu;
class QModelIndex;
class QTabWidget;
class QTextBrowser;
class QTreeView;

namespace athlos {
class Project;
class Stream;
}  // namespace athlos

namespace athlos::ui {

class ProjectTreeModel;
class TimeSeriesPanel;
class TrajectoryPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT

public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Non-interactive: no modal dialogs. Errors go to errorReported() and the status bar, and
    // unsaved changes are discarded without asking (tests, offscreen rendering).
    void setInteractive(bool interactive) { interactive_ = interactive; }
    bool isInteractive() const { return interactive_; }

    Project* project() const { return project_.get(); }
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

    QMenu* recentMenu_ = nullptr;
    QAction* newAction_ = nullptr;
    QAction* openAction_ = nullptr;
    QAction* saveAction_ = nullptr;
    QAction* saveAsAction_ = nullptr;
    QAction* importAction_ = nullptr;
    QAction* quitAction_ = nullptr;
    QAction* aboutAction_ = nullptr;
};

}  // namespace athlos::ui
