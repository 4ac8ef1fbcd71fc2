#pragma once
// What tools, wizards and views may use from the main window, without depending on it.
// MainWindow implements it; wizards (ui/wizards/) and views (ui/views/) receive a Workspace&.
#include "core/processing/ProcessorRunner.h"
#include "core/util/Expected.h"

#include <QString>
#include <Qt>

class QDockWidget;
class QWidget;

namespace athlos {
class Project;
}

namespace athlos::ui {

class AnnotationEditor;
class TimeController;
class WorkspaceNotifier;

class Workspace {
public:
    virtual ~Workspace() = default;

    // The open project, or nullptr. Read freely on the GUI thread; change it only through
    // runProcessor() or followed by projectModified().
    virtual Project* project() = 0;
    // Parent for dialogs.
    virtual QWidget* window() = 0;
    // Runs a processor on a worker thread with a progress dialog and Cancel; on success the outputs
    // are in the project and in the tree. Errors are returned (and not shown) so a wizard can
    // present them in context.
    virtual Expected<RunOutcome> runProcessor(const RunRequest& request) = 0;
    // After a direct change of the project (e.g. a geometry or table edit): refresh tree and title.
    virtual void projectModified() = 0;
    // Selects and shows "rec/item" (plots a stream).
    virtual void showItem(const QString& path) = 0;
    // The one time cursor and visible range that every panel, video and playback view follows.
    virtual TimeController* timeController() const = 0;
    // Adds a tool's dock (video, playback, joint angles, action timeline…) to the window; the
    // window owns it and lists it under View. Give the dock a stable objectName.
    virtual void addDock(QDockWidget* dock, Qt::DockWidgetArea area = Qt::BottomDockWidgetArea) = 0;
    // Resizes a dock added with addDock(): its width (Qt::Horizontal) or height (Qt::Vertical).
    virtual void resizeDock(QDockWidget* dock, int size, Qt::Orientation orientation) = 0;
    // Adds a tool's view (track, orientation, playback…) as a tab next to the time-series and
    // trajectory panels and brings it forward; the window owns it.
    virtual void addView(QWidget* view, const QString& title) = 0;

    // Signals: projectChanged() when the project is opened, closed, replaced or modified.
    virtual WorkspaceNotifier* notifier() = 0;
    // The item selected in the project tree ("rec" or "rec/item"), or empty.
    virtual QString currentItem() const = 0;
    // Selects "rec" or "rec/item" in the project tree; a stream is then plotted (without bringing
    // the time-series panel forward, unlike showItem()). False if there is no such item.
    virtual bool selectItem(const QString& path) = 0;
    // Brings the time-series panel forward.
    virtual void showTimeSeriesView() = 0;
    // Blocks until the panels finished loading and lays out and replots them (screenshot views).
    virtual void waitForPlots() = 0;
    // The window's annotation editor: annotation edits go through it (undo, journal, autosave).
    virtual AnnotationEditor* annotationEditor() const = 0;
};

}  // namespace athlos::ui
