#pragma once
// Runs a long job (import, save) on a worker thread while the GUI stays live: a modal progress
// dialog shows the job's Progress reports and its Cancel button trips the job's CancelToken.
// Returns when the job is done, so callers read like sequential code.
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QCoreApplication>
#include <QString>
#include <functional>

class QWidget;

namespace athlos::ui {

class BackgroundTask {
    Q_DECLARE_TR_FUNCTIONS(athlos::ui::BackgroundTask)

public:
    using Job = std::function<Status(const Progress&)>;

    struct Outcome {
        Status status;
        bool cancelled = false;  // the user pressed Cancel (status then holds the job's error)
    };

    // showDialog false: no dialog (tests, offscreen rendering); the job still runs off-thread
    // and the call still waits for it while processing events.
    static Outcome run(QWidget* parent, const QString& label, const Job& job, bool showDialog = true);

    // The same dialog for a job that must run on the GUI thread (it draws widgets: a PDF with plots):
    // the job runs here, and each of its progress reports updates the dialog and processes events, so
    // Cancel trips its CancelToken at the next report.
    static Outcome runHere(QWidget* parent, const QString& label, const Job& job);
};

}  // namespace athlos::ui
