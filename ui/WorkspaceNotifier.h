#pragma once
// The signals of a Workspace. Workspace is an interface and no QObject (MainWindow already is
// one, through QMainWindow), so it hands out this object for tools to connect to.
#include <QObject>

namespace athlos::ui {

class WorkspaceNotifier : public QObject {
    Q_OBJECT

public:
    using QObject::QObject;

signals:
    // The project was opened, closed or replaced, or changed through Workspace::projectModified()
    // (a processor run, a geometry or link edit). A view that reads the project compares
    // Workspace::project() with the project it was opened on.
    void projectChanged();
};

}  // namespace athlos::ui
