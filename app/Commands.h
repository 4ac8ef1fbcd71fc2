#pragma once
// `athlos <command> …`: one function per command, each returning the process exit code.
// Exit codes: 0 success, 1 failure (one-line reason on stderr), 2 usage error, 130 cancelled.
#include "core/model/Project.h"
#include "core/util/Expected.h"

#include <QStringList>
#include <memory>

namespace athlos::cli {

enum ExitCode { Ok = 0, Failed = 1, Usage = 2, Cancelled = 130 };

int cmdNew(const QStringList& args);
int cmdImport(const QStringList& args);
int cmdInfo(const QStringList& args);
int cmdProcessors(const QStringList& args);
int cmdRun(const QStringList& args);
int cmdExport(const QStringList& args);
int cmdPipeline(const QStringList& args);
int cmdScreenshot(const QStringList& args);
int cmdVenue(const QStringList& args);
int cmdReport(const QStringList& args);
int cmdHistory(const QStringList& args);
int cmdBatch(const QStringList& args);
// The per-project worker of batch (not listed in --help).
int cmdBatchTask(const QStringList& args);
int cmdTrain(const QStringList& args);

// Prints "athlos: <message>" on stderr and returns code.
int fail(const QString& message, int code = Failed);

// Opens a project to change it (its write lock held until the Project is destroyed) and prints
// what opening noted ("athlos: note: …") on stderr.
Expected<std::unique_ptr<Project>> openForChange(const QString& path);
// The same, but a missing file becomes a new, empty project held in memory (its lock held) and
// `created` is set: nothing is written until the caller saves it, so a failed import leaves no file.
Expected<std::unique_ptr<Project>> openOrCreateForChange(const QString& path, bool& created);

}  // namespace athlos::cli
