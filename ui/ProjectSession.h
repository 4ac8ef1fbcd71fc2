#pragma once
// The project's life in the main window: new, open, save, save as, the idle autosave, import,
// the crash journal's recovery on open, and the question about unsaved changes. Each operation
// reports its own errors (dialog when interactive, errorReported always) and returns whether it
// succeeded. Long work runs on a worker thread (BackgroundTask) while the window takes no input.
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QCoreApplication>
#include <QString>
#include <QStringList>
#include <functional>

class QTimer;

namespace athlos::ui {

class MainWindow;

class ProjectSession {
    // The texts were, and stay, the main window's: one translation context for the window.
    Q_DECLARE_TR_FUNCTIONS(athlos::ui::MainWindow)

public:
    // The window's annotation editor must exist: its edits start the autosave timer.
    explicit ProjectSession(MainWindow& window);
    ProjectSession(const ProjectSession&) = delete;
    ProjectSession& operator=(const ProjectSession&) = delete;

    bool newProject(const QString& path);
    bool openProject(const QString& path);
    bool saveProject();
    bool saveProjectAs(const QString& path);
    // Imports every file (format detected, recording named after the file) on a worker thread.
    // All or nothing: the project changes only if every file was read and every name is free.
    bool importFiles(const QStringList& files);
    // Interactive only: asks whether to save unsaved changes. False: the user cancelled.
    bool maybeSaveChanges();

    // Idle time after an annotation edit before the project is saved in the background (0 = never).
    void setAutosaveDelay(int milliseconds);
    // Saves without dialog and without taking input away; annotation edits wait meanwhile.
    bool autosave();

    // The file dialogs in front of the operations (File menu).
    void newProjectDialog();
    void openProjectDialog();
    void saveAsDialog();
    void importDialog();

private:
    // Stores the layout, runs save on a worker with progress, and on success marks the project
    // saved and discards the journal; errors and cancellation are reported here.
    bool runSave(const std::function<Status(const Progress&)>& save, const QString& cancelledMessage);
    // Offers (interactive) or applies (tests, offscreen) the crash journal of a just opened project.
    void recoverJournal();
    void afterSave();

    MainWindow& window_;
    QTimer* autosaveTimer_ = nullptr;
};

}  // namespace athlos::ui
