#include "BatchEngines.h"

#include <QCoreApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QThread>
#include <QTimer>
#include <memory>

namespace athlos::cli {

TaskResult taskResultFrom(int exitCode, const QByteArray& out, const QByteArray& err) {
    TaskResult result;
    if (exitCode == 0) {
        result.state = out.contains("skipped (done)") ? TaskResult::State::Skipped : TaskResult::State::Done;
        return result;
    }
    result.state = exitCode == 130 ? TaskResult::State::Cancelled : TaskResult::State::Failed;
    // The task's one-line reason ("athlos: …"); notes and warnings come before it.
    const QList<QByteArray> lines = err.trimmed().split('\n');
    QString reason = QString::fromUtf8(lines.isEmpty() ? QByteArray() : lines.last().trimmed());
    if (reason.startsWith(QLatin1String("athlos: "))) reason = reason.mid(8);
    result.reason = reason.isEmpty() ? QStringLiteral("exit code %1 without a message").arg(exitCode) : reason;
    return result;
}

namespace {

// A running worker of the local engine.
struct Worker {
    int project = -1;
    std::unique_ptr<QProcess> process;
    QElapsedTimer clock;
};

}  // namespace

std::vector<TaskResult> runLocal(const QString& executable, const QString& pipelineFile, const QStringList& projects,
                                 const LocalOptions& options, const Progress& progress,
                                 const ResultCallback& onResult) {
    std::vector<TaskResult> results(std::size_t(projects.size()));
    std::vector<std::unique_ptr<Worker>> running;
    int next = 0, finished = 0;
    bool cancelled = false;
    QEventLoop loop;

    auto report = [&] {
        progress.report(
            double(finished) / double(std::max<qsizetype>(1, projects.size())),
            QStringLiteral("%1/%2 projects, %3 running").arg(finished).arg(projects.size()).arg(running.size()));
    };
    std::function<void()> fill;
    auto complete = [&](Worker* w, int exitCode, QProcess::ExitStatus status, const QString& why = {}) {
        TaskResult r =
            taskResultFrom(exitCode, w->process->readAllStandardOutput(), w->process->readAllStandardError());
        if (!why.isEmpty()) r.reason = why;
        if (cancelled && r.state == TaskResult::State::Failed) r.state = TaskResult::State::Cancelled;
        if (status == QProcess::CrashExit) {
            r.state = cancelled ? TaskResult::State::Cancelled : TaskResult::State::Failed;
            r.reason = QStringLiteral("the worker process was killed or crashed; the project is unchanged");
        }
        r.seconds = double(w->clock.elapsed()) / 1000.0;
        results[std::size_t(w->project)] = r;
        ++finished;
        onResult(w->project, r);
        // The process object may still be inside its own signal: delete it later.
        w->process.release()->deleteLater();
        std::erase_if(running, [w](const auto& x) { return x.get() == w; });
        report();
        fill();
    };
    fill = [&] {
        while (!cancelled && next < projects.size() && int(running.size()) < options.jobs) {
            auto w = std::make_unique<Worker>();
            w->project = next++;
            w->process = std::make_unique<QProcess>();
            Worker* raw = w.get();
            QObject::connect(raw->process.get(), &QProcess::finished, &loop,
                             [&complete, raw](int code, QProcess::ExitStatus status) { complete(raw, code, status); });
            QObject::connect(
                raw->process.get(), &QProcess::errorOccurred, &loop, [&complete, raw](QProcess::ProcessError e) {
                    if (e == QProcess::FailedToStart)
                        complete(raw, 127, QProcess::NormalExit,
                                 QStringLiteral("the worker could not start: %1").arg(raw->process->errorString()));
                });
            raw->clock.start();
            // In the list before start(): a failure to start may be reported from inside start().
            running.push_back(std::move(w));
            raw->process->start(executable, {QStringLiteral("batch-task"), pipelineFile, projects[raw->project]});
        }
        if (running.empty()) loop.quit();
    };

    // Ctrl-C: ask the workers to stop (SIGTERM cancels a run and leaves the project untouched), then
    // kill those that have not stopped after a grace period; atomic saves keep their projects intact.
    QTimer watch;
    QElapsedTimer sinceCancel;
    QObject::connect(&watch, &QTimer::timeout, &loop, [&] {
        if (!progress.isCancelled()) return;
        if (!cancelled) {
            cancelled = true;
            sinceCancel.start();
            for (const auto& w : running) w->process->terminate();
            if (running.empty()) loop.quit();
        } else if (sinceCancel.elapsed() > 3000) {
            for (const auto& w : running) w->process->kill();
        }
    });
    watch.start(100);
    report();
    QTimer::singleShot(0, &loop, [&] { fill(); });
    loop.exec();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::DeferredDelete);
    for (auto& r : results)
        if (r.state == TaskResult::State::Pending) r.state = TaskResult::State::Cancelled;
    return results;
}

namespace {

QString shellQuote(const QString& s) {
    QString q = s;
    q.replace(QLatin1Char('\''), QLatin1String("'\\''"));
    return QLatin1Char('\'') + q + QLatin1Char('\'');
}

struct Command {
    int exitCode = -1;
    QByteArray out, err;
    QString error;  // could not start / timed out
};

Command runCommand(const QString& program, const QStringList& args, int timeoutMs = 60000) {
    QProcess p;
    p.start(program, args);
    Command c;
    if (!p.waitForStarted(timeoutMs)) {
        c.error = QStringLiteral("%1: %2").arg(program, p.errorString());
        return c;
    }
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished(1000);
        c.error = QStringLiteral("%1: no answer within %2 s").arg(program).arg(timeoutMs / 1000);
        return c;
    }
    c.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    c.out = p.readAllStandardOutput();
    c.err = p.readAllStandardError();
    return c;
}

QString firstLine(const QByteArray& text) { return QString::fromUtf8(text.trimmed().split('\n').value(0)).trimmed(); }

bool writeFile(const QString& path, const QByteArray& bytes, QFileDevice::Permissions permissions = {}) {
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate) || f.write(bytes) != bytes.size()) return false;
    if (permissions) f.setPermissions(permissions);
    return true;
}

// The job script: array task i runs projects [i·chunk, (i+1)·chunk) one after the other and leaves,
// per project j, out-j, err-j and rc-j (written last, by rename, so a present rc-j is complete).
QByteArray jobScript(const QString& executable, const QString& workDir, int chunk, int projects) {
    QString s = QStringLiteral(
                    "#!/bin/sh\n"
                    "# Written by athlos batch --engine slurm: one array task per chunk of projects.\n"
                    "W=%1\nEXE=%2\nCHUNK=%3\nN=%4\n"
                    "i=$((SLURM_ARRAY_TASK_ID * CHUNK))\n"
                    "end=$((i + CHUNK)); [ \"$end\" -gt \"$N\" ] && end=$N\n"
                    "status=0\n"
                    "while [ \"$i\" -lt \"$end\" ]; do\n"
                    "  p=$(sed -n \"$((i + 1))p\" \"$W/projects.txt\")\n"
                    "  \"$EXE\" batch-task \"$W/pipeline.json\" \"$p\" >\"$W/out-$i\" 2>\"$W/err-$i\"\n"
                    "  rc=$?\n"
                    "  echo \"$rc\" >\"$W/rc-$i.tmp\" && mv \"$W/rc-$i.tmp\" \"$W/rc-$i\"\n"
                    "  [ \"$rc\" -ne 0 ] && status=$rc\n"
                    "  i=$((i + 1))\n"
                    "done\n"
                    "exit $status\n")
                    .arg(shellQuote(workDir), shellQuote(executable))
                    .arg(chunk)
                    .arg(projects);
    return s.toUtf8();
}

// What the controller says about an array task that left no result (still in its memory for
// MinJobAge seconds after the end): state, reason and exit code.
QString schedulerReason(const QString& jobId, int task, const QString& workDir) {
    QString reason;
    const Command c = runCommand(QStringLiteral("scontrol"),
                                 {QStringLiteral("-o"), QStringLiteral("show"), QStringLiteral("job"),
                                  QStringLiteral("%1_%2").arg(jobId).arg(task)},
                                 20000);
    if (c.error.isEmpty() && c.exitCode == 0) {
        QStringList parts;
        for (const QString& field : QString::fromUtf8(c.out).split(QLatin1Char(' '), Qt::SkipEmptyParts))
            if (field.startsWith(QLatin1String("JobState=")) || field.startsWith(QLatin1String("Reason=")) ||
                field.startsWith(QLatin1String("ExitCode=")))
                parts << field.trimmed();
        reason = parts.join(QLatin1Char(' '));
    }
    QFile err(QStringLiteral("%1/slurm-%2.err").arg(workDir).arg(task));
    if (err.open(QIODevice::ReadOnly)) {
        const QList<QByteArray> lines = err.readAll().trimmed().split('\n');
        const QString last = QString::fromUtf8(lines.last()).trimmed();
        if (!last.isEmpty()) reason += (reason.isEmpty() ? QString() : QStringLiteral("; ")) + last;
    }
    return QStringLiteral("Slurm task %1 left no result (%2)")
        .arg(task)
        .arg(reason.isEmpty() ? QStringLiteral("the scheduler no longer knows it") : reason);
}

}  // namespace

Expected<std::vector<TaskResult>> runSlurm(const QString& executable, const QString& pipelineFile,
                                           const QStringList& projects, const SlurmOptions& options,
                                           const Progress& progress, const ResultCallback& onResult) {
    const QString wd = options.workDir;
    if (!QDir().mkpath(wd)) return makeError(QStringLiteral("cannot create the work folder '%1'").arg(wd));
    QStringList absolute;
    for (const QString& p : projects) {
        if (p.contains(QLatin1Char('\n')))
            return makeError(QStringLiteral("project path with a line break: '%1'").arg(p));
        absolute << QFileInfo(p).absoluteFilePath();
    }
    const int n = int(projects.size());
    const int chunk = std::max(1, options.chunk);
    const int tasks = (n + chunk - 1) / chunk;
    QFile source(pipelineFile);
    if (!source.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("%1: %2").arg(pipelineFile, source.errorString()));
    if (!writeFile(wd + QStringLiteral("/pipeline.json"), source.readAll()) ||
        !writeFile(wd + QStringLiteral("/projects.txt"),
                   (absolute.join(QLatin1Char('\n')) + QLatin1Char('\n')).toUtf8()) ||
        !writeFile(wd + QStringLiteral("/job.sh"), jobScript(executable, wd, chunk, n),
                   QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner))
        return makeError(QStringLiteral("cannot write into the work folder '%1'").arg(wd));

    QString array = QStringLiteral("--array=0-%1").arg(tasks - 1);
    if (options.throttle > 0) array += QStringLiteral("%%1").arg(options.throttle);
    QStringList args{QStringLiteral("--parsable"), array, QStringLiteral("--job-name=athlos-batch"),
                     QStringLiteral("--output=%1/slurm-%a.out").arg(wd),
                     QStringLiteral("--error=%1/slurm-%a.err").arg(wd)};
    args << options.extraArgs << wd + QStringLiteral("/job.sh");
    const Command submitted = runCommand(QStringLiteral("sbatch"), args);
    if (!submitted.error.isEmpty()) return makeError(QStringLiteral("sbatch could not run: %1").arg(submitted.error));
    if (submitted.exitCode != 0)
        return makeError(QStringLiteral("sbatch refused the job: %1").arg(firstLine(submitted.err + submitted.out)));
    const QString jobId = firstLine(submitted.out).section(QLatin1Char(';'), 0, 0);
    if (jobId.isEmpty()) return makeError(QStringLiteral("sbatch printed no job id"));
    std::printf("submitted Slurm job array %s (%d task(s)), work folder %s\n", qUtf8Printable(jobId), tasks,
                qUtf8Printable(wd));
    std::fflush(stdout);

    std::vector<TaskResult> results(static_cast<std::size_t>(n));
    QElapsedTimer clock;
    clock.start();
    int finished = 0, squeueErrors = 0;
    // Collects every project whose rc file appeared; returns whether all have one.
    auto collect = [&] {
        for (int j = 0; j < n; ++j) {
            if (results[std::size_t(j)].state != TaskResult::State::Pending) continue;
            QFile rc(QStringLiteral("%1/rc-%2").arg(wd).arg(j));
            if (!rc.open(QIODevice::ReadOnly)) continue;
            bool ok = false;
            const int code = rc.readAll().trimmed().toInt(&ok);
            auto read = [&](const QString& name) {
                QFile f(QStringLiteral("%1/%2-%3").arg(wd, name).arg(j));
                return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
            };
            TaskResult r = taskResultFrom(ok ? code : 1, read(QStringLiteral("out")), read(QStringLiteral("err")));
            r.seconds = double(clock.elapsed()) / 1000.0;
            results[std::size_t(j)] = r;
            ++finished;
            onResult(j, r);
        }
        progress.report(double(finished) / n,
                        QStringLiteral("%1/%2 projects (job %3)").arg(finished).arg(n).arg(jobId));
    };
    for (;;) {
        if (progress.isCancelled()) {
            // scancel signals the tasks (SIGTERM, then SIGKILL after KillWait): their runs are cancelled
            // or killed before the atomic rename, so their projects stay as they were.
            runCommand(QStringLiteral("scancel"), {jobId}, 20000);
            collect();
            for (auto& r : results)
                if (r.state == TaskResult::State::Pending) r.state = TaskResult::State::Cancelled;
            return results;
        }
        const Command q = runCommand(
            QStringLiteral("squeue"),
            {QStringLiteral("-h"), QStringLiteral("-j"), jobId, QStringLiteral("-o"), QStringLiteral("%i %T")}, 30000);
        collect();
        if (q.error.isEmpty() && q.exitCode == 0) {
            squeueErrors = 0;
            if (q.out.trimmed().isEmpty()) break;  // no task pending or running any more
        } else if (q.error.isEmpty() && (q.err.contains("Invalid job id") || q.err.contains("invalid job id"))) {
            break;  // already purged from the controller's memory
        } else if (++squeueErrors >= 10) {
            runCommand(QStringLiteral("scancel"), {jobId}, 20000);
            return makeError(QStringLiteral("squeue failed 10 times in a row (job %1 cancelled): %2")
                                 .arg(jobId, q.error.isEmpty() ? firstLine(q.err) : q.error));
        }
        QThread::msleep(static_cast<unsigned long>(options.pollSeconds * 1000.0));
    }
    // A file system shared over NFS may show the last rc files a moment late.
    for (int attempt = 0; attempt < 10 && finished < n; ++attempt) {
        collect();
        if (finished < n) QThread::msleep(500);
    }
    for (int j = 0; j < n; ++j) {
        if (results[std::size_t(j)].state != TaskResult::State::Pending) continue;
        results[std::size_t(j)] = {TaskResult::State::Failed, schedulerReason(jobId, j / chunk, wd),
                                   double(clock.elapsed()) / 1000.0};
        onResult(j, results[std::size_t(j)]);
    }
    return results;
}

}  // namespace athlos::cli
