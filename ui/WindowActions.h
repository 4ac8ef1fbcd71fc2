#pragma once
// The menus and actions of the main window: File (project lifecycle, recent projects, import,
// export), Edit (undo, annotation), View, Processing, the menus registered tools ask for, and
// Help; and which of them are enabled (a project is open, no background job runs).
#include <QCoreApplication>
#include <QList>
#include <QString>

class QAction;
class QCustomPlot;
class QMenu;

namespace athlos::ui {

class MainWindow;

class WindowActions {
    // The texts were, and stay, the main window's: one translation context for the window.
    Q_DECLARE_TR_FUNCTIONS(athlos::ui::MainWindow)

public:
    // Creates every action and fills window's menu bar; the window's parts must exist.
    explicit WindowActions(MainWindow& window);
    WindowActions(const WindowActions&) = delete;
    WindowActions& operator=(const WindowActions&) = delete;

    // Project commands need an open project; tools too.
    void updateEnabled(bool projectOpen);
    // While a background job runs no command may start.
    void setBusy(bool busy, bool projectOpen);
    // The context menu of a plot: export it, show all.
    void addExportMenu(QCustomPlot* plot);
    // A tool's dock is listed under View.
    void addToViewMenu(QAction* action);

    QAction* runProcessorAction() const { return runProcessor_; }
    // The menu action of a registered tool (by ToolEntry::id).
    QAction* toolAction(const QString& id) const;

private:
    void createActions();
    void createMenus();
    void createToolMenus(QMenu* file, QMenu* processing, QMenu* view);
    void rebuildRecentMenu();
    void exportPlot(QCustomPlot* plot);
    void about();

    MainWindow& window_;
    QMenu* recentMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QAction* new_ = nullptr;
    QAction* open_ = nullptr;
    QAction* save_ = nullptr;
    QAction* saveAs_ = nullptr;
    QAction* import_ = nullptr;
    QAction* quit_ = nullptr;
    QAction* about_ = nullptr;
    QAction* runProcessor_ = nullptr;
    QAction* addPanel_ = nullptr;
    QAction* showAll_ = nullptr;
    QAction* exportView_ = nullptr;
    QAction* undo_ = nullptr;
    QAction* redo_ = nullptr;
    QAction* annotateMode_ = nullptr;
    QAction* addClass_ = nullptr;
    QAction* preferences_ = nullptr;
    QList<QAction*> toolActions_;
};

}  // namespace athlos::ui
