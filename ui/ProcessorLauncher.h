#pragma once
// Processors from the window: runs one on a worker thread with progress and Cancel (the
// Workspace's runProcessor), opens the Run Processor dialog, and re-runs a result with the
// request its provenance records (tree context menu).
#include "core/processing/ProcessorRunner.h"
#include "core/util/Expected.h"

#include <QCoreApplication>
#include <QString>

class QAction;
class QPoint;

namespace athlos::ui {

class MainWindow;

class ProcessorLauncher {
    // The texts were, and stay, the main window's: one translation context for the window.
    Q_DECLARE_TR_FUNCTIONS(athlos::ui::MainWindow)

public:
    explicit ProcessorLauncher(MainWindow& window);
    ProcessorLauncher(const ProcessorLauncher&) = delete;
    ProcessorLauncher& operator=(const ProcessorLauncher&) = delete;

    // The window takes no input while the processor runs (the worker mutates the project).
    Expected<RunOutcome> run(const RunRequest& request);
    // The request that produced the result at path, or an empty request if path is no result.
    RunRequest rerunRequest(const QString& path) const;
    // Processing → Run processor…, optionally pre-filled.
    void openDialog(const RunRequest& prefill = {});
    // The project tree's context menu on path: re-run a result, run any processor.
    void showContextMenu(const QString& path, const QPoint& globalPos, QAction* runProcessor);

private:
    MainWindow& window_;
};

}  // namespace athlos::ui
