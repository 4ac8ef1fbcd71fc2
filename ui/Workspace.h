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

class TimeController;

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
};

}  // namespace athlos::ui
