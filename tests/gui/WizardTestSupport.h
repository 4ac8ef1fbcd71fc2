#pragma once
// Shared by the wizard tests: a Workspace double over an in-memory project that counts
// modifications and remembers what it was asked to show (each test adds its own runProcessor()),
// and a child-widget lookup that fails loudly.
#include "core/processing/ProcessorRunner.h"
#include "ui/TimeController.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"

#include <QDockWidget>
#include <QList>
#include <QObject>
#include <QString>
#include <QStringList>
#include <QWidget>
#include <QtGlobal>

namespace athlos::testing {

class WorkspaceDouble : public ui::Workspace {
public:
    explicit WorkspaceDouble(Project* project) : project_(project) {}
    ~WorkspaceDouble() override {
        qDeleteAll(docks);
        qDeleteAll(views);
    }
    Project* project() override { return project_; }
    QWidget* window() override { return nullptr; }
    void projectModified() override { ++modifications; }
    void showItem(const QString& path) override { shown = path; }
    ui::TimeController* timeController() const override { return &time_; }
    void addDock(QDockWidget* dock, Qt::DockWidgetArea) override { docks.append(dock); }
    void resizeDock(QDockWidget*, int, Qt::Orientation) override {}
    void addView(QWidget* view, const QString&) override { views.append(view); }
    ui::WorkspaceNotifier* notifier() override { return &notifier_; }
    QString currentItem() const override { return selected; }
    bool selectItem(const QString& path) override {
        selected = path;
        return true;
    }
    void showTimeSeriesView() override {}
    void waitForPlots() override {}
    ui::AnnotationEditor* annotationEditor() const override { return nullptr; }

    Project* project_;
    mutable ui::TimeController time_;
    ui::WorkspaceNotifier notifier_;
    QList<QDockWidget*> docks;
    QList<QWidget*> views;
    QList<RunRequest> requests;
    int modifications = 0;
    QString shown;
    QString selected;
};

// What a processor double reports: the paths it wrote.
inline RunOutcome wrote(QStringList paths) {
    RunOutcome outcome;
    outcome.written = std::move(paths);
    return outcome;
}

template <class T>
T* child(QObject* parent, const char* name) {
    T* widget = parent->findChild<T*>(QLatin1String(name));
    if (!widget) qFatal("no child %s", name);
    return widget;
}

}  // namespace athlos::testing
