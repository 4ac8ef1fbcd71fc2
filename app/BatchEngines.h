#pragma once
// The two ways `athlos batch` runs a pipeline over many projects. Both run every project in a process
// of its own (`athlos batch-task <pipeline> <project>`), which opens the project, skips it when its
// provenance shows the pipeline done, otherwise runs the pipeline and saves atomically: a killed or
// failed task leaves its project as it was.
//   local: up to N worker processes on this machine (QProcess);
//   slurm: one job array (sbatch --array, a task per project or per chunk of projects), polled with
//          squeue until it ends; each project's exit code and reason are read back from files the
//          job script writes into a work folder that the cluster's nodes share with this one.
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QString>
#include <QStringList>
#include <functional>
#include <vector>

namespace athlos::cli {

struct TaskResult {
    enum class State { Pending, Done, Skipped, Failed, Cancelled };
    State state = State::Pending;
    QString reason;  // why it failed, or what the scheduler said
    double seconds = 0.0;
};

// Called once per project as soon as its result is known (index into the project list).
using ResultCallback = std::function<void(int project, const TaskResult& result)>;

struct LocalOptions {
    int jobs = 1;
};

struct SlurmOptions {
    QStringList extraArgs;  // --slurm-args, split like a shell would
    int chunk = 1;          // projects per array task
    int throttle = 0;       // at most this many tasks at once (--array=…%N), 0 = no limit
    QString workDir;        // must be visible from the compute nodes
    double pollSeconds = 1.0;
};

// Both return one result per project; a cancelled run (Ctrl-C, through progress) marks the projects
// that had not finished as Cancelled.
std::vector<TaskResult> runLocal(const QString& executable, const QString& pipelineFile, const QStringList& projects,
                                 const LocalOptions& options, const Progress& progress, const ResultCallback& onResult);
// Errors (sbatch refused, squeue unusable) name the command and its message.
Expected<std::vector<TaskResult>> runSlurm(const QString& executable, const QString& pipelineFile,
                                           const QStringList& projects, const SlurmOptions& options,
                                           const Progress& progress, const ResultCallback& onResult);

// The result a finished `batch-task` reported: its exit code, standard output and standard error.
TaskResult taskResultFrom(int exitCode, const QByteArray& out, const QByteArray& err);

}  // namespace athlos::cli
