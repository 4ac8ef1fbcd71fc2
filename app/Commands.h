#pragma once
// `athlos <command> …`: one function per command, each returning the process exit code.
// Exit codes: 0 success, 1 failure (one-line reason on stderr), 2 usage error, 130 cancelled.
#include <QStringList>

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

// Prints "athlos: <message>" on stderr and returns code.
int fail(const QString& message, int code = Failed);

}  // namespace athlos::cli
