// athlos batch | batch-task: a pipeline over many projects, on local worker processes or a Slurm job array.
#include "BatchEngines.h"
#include "CommandParser.h"
#include "Commands.h"
#include "TerminalProgress.h"

#include "core/io/Exporter.h"
#include "core/model/Project.h"
#include "core/model/SummaryTable.h"
#include "core/processing/PipelineProvenance.h"
#include "core/processing/ProcessorRunner.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QProcess>
#include <QThread>
#include <cstdio>
#include <unistd.h>

namespace athlos::cli {
namespace {

int exitFor(const Error& error) { return error.message == u"cancelled" ? Cancelled : Failed; }

const char* stateText(TaskResult::State s) {
    switch (s) {
        case TaskResult::State::Done:
            return "done";
        case TaskResult::State::Skipped:
            return "skipped (done)";
        case TaskResult::State::Failed:
            return "failed";
        case TaskResult::State::Cancelled:
            return "cancelled";
        case TaskResult::State::Pending:
            break;
    }
    return "not run";
}

// Stacks every table called (or of kind) tableName of every recording of every project into one CSV.
Status writeSummary(const QStringList& projects, const std::vector<TaskResult>& results, const QString& tableName,
                    const QString& file) {
    SummaryTable summary;
    for (int i = 0; i < projects.size(); ++i) {
        const auto state = results[std::size_t(i)].state;
        if (state != TaskResult::State::Done && state != TaskResult::State::Skipped) continue;
        auto project = Project::open(projects[i]);
        if (!project) return makeError(project.message());
        for (const auto& [recName, rec] : (*project)->recordings())
            for (const auto& [name, table] : rec.tables)
                if (name == tableName || table.kind == tableName)
                    if (Status s = summary.add(projects[i], recName, table); !s) return s;
    }
    if (summary.sources() == 0)
        std::fprintf(stderr, "athlos: warning: no table named or of kind '%s' in the projects; %s has a header only\n",
                     qUtf8Printable(tableName), qUtf8Printable(file));
    return exportTableCsv(summary.table(), file);
}

}  // namespace

int cmdBatchTask(const QStringList& args) {
    CommandParser p(QStringLiteral("batch-task <pipeline.json> <project>"),
                    QStringLiteral("One project of athlos batch: skip it when its provenance shows the pipeline done, "
                                   "else run the pipeline and save the project atomically."));
    p.addPositional(QStringLiteral("pipeline"), QStringLiteral("The pipeline JSON file."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    if (auto code = p.parse(args, 2, 2)) return *code;
    auto pipeline = readPipelineFile(p.positional()[0]);
    if (!pipeline) return fail(pipeline.message());
    auto project = openForChange(p.positional()[1]);
    if (!project) return fail(project.message());
    auto check = checkPipelineDone(**project, *pipeline);
    if (!check) return fail(check.message());
    if (check->done) {
        std::printf("skipped (done)\n");
        return Ok;
    }
    TerminalProgress bar(QStringLiteral("pipeline"));
    auto written = runPipeline(**project, *pipeline, bar.progress().sub(0.0, 0.9));
    // A cancelled step comes back as "pipeline step N: cancelled".
    if (!written) return fail(written.message(), bar.progress().isCancelled() ? Cancelled : Failed);
    if (Status s = (*project)->save(bar.progress().sub(0.9, 1.0)); !s) return fail(s.message(), exitFor(s.error()));
    bar.finish();
    for (const auto& w : *written) std::printf("wrote %s\n", qUtf8Printable(w));
    return Ok;
}

int cmdBatch(const QStringList& args) {
    CommandParser p(
        QStringLiteral("batch <pipeline.json> <project>… [--jobs N] [--engine local|slurm] [--slurm-args '…'] "
                       "[--summary out.csv]"),
        QStringLiteral(
            "Run a pipeline over many projects, each in a process of its own that saves its project atomically "
            "(a failed or killed task leaves its project as it was). A project whose provenance shows every step "
            "done with the same processor version, parameters and input contents is skipped. Exit code 1 if any "
            "project failed; one line per project either way."));
    p.addPositional(QStringLiteral("pipeline"), QStringLiteral("The pipeline JSON file (see athlos pipeline)."));
    p.addPositional(QStringLiteral("projects"), QStringLiteral("The .athlos files."));
    p.addOption({QStringLiteral("jobs"),
                 QStringLiteral("Worker processes at once (local; default: the number of cores). With slurm: at most "
                                "N array tasks at once."),
                 QStringLiteral("N")});
    p.addOption({QStringLiteral("engine"), QStringLiteral("local (worker processes here) or slurm (one job array)."),
                 QStringLiteral("local|slurm"), QStringLiteral("local")});
    p.addOption({QStringLiteral("slurm-args"),
                 QStringLiteral("Extra sbatch options, split like a shell would (e.g. '--partition=short --time=10')."),
                 QStringLiteral("options")});
    p.addOption({QStringLiteral("chunk"), QStringLiteral("slurm: projects per array task (default 1)."),
                 QStringLiteral("K"), QStringLiteral("1")});
    p.addOption({QStringLiteral("work-dir"),
                 QStringLiteral("slurm: folder for the job script and the tasks' results, visible from the compute "
                                "nodes (default: athlos-batch-<time>-<pid> in the current folder; removed when "
                                "every project succeeded)."),
                 QStringLiteral("dir")});
    p.addOption({QStringLiteral("poll"), QStringLiteral("slurm: seconds between squeue polls (default 2)."),
                 QStringLiteral("s"), QStringLiteral("2")});
    p.addOption({QStringLiteral("summary"),
                 QStringLiteral("Merge the tables named --summary-table of every recording of every project into one "
                                "CSV with leading columns project and recording."),
                 QStringLiteral("out.csv")});
    p.addOption({QStringLiteral("summary-table"),
                 QStringLiteral("Name or kind of the tables --summary merges (default metrics)."),
                 QStringLiteral("name"), QStringLiteral("metrics")});
    if (auto code = p.parse(args, 2, 1 << 20)) return *code;
    const auto& parser = p.parser();

    const QString engine = parser.value(QStringLiteral("engine"));
    if (engine != u"local" && engine != u"slurm")
        return fail(QStringLiteral("--engine '%1': use local or slurm").arg(engine), Usage);
    bool ok = true;
    int jobs = QThread::idealThreadCount();
    if (parser.isSet(QStringLiteral("jobs"))) {
        jobs = parser.value(QStringLiteral("jobs")).toInt(&ok);
        if (!ok || jobs < 1 || jobs > 1024)
            return fail(QStringLiteral("--jobs '%1': expected a whole number from 1 to 1024")
                            .arg(parser.value(QStringLiteral("jobs"))),
                        Usage);
    }
    const int chunk = parser.value(QStringLiteral("chunk")).toInt(&ok);
    if (!ok || chunk < 1)
        return fail(
            QStringLiteral("--chunk '%1': expected a whole number ≥ 1").arg(parser.value(QStringLiteral("chunk"))),
            Usage);
    const double poll = parser.value(QStringLiteral("poll")).toDouble(&ok);
    if (!ok || poll < 0.1 || poll > 600)
        return fail(
            QStringLiteral("--poll '%1': expected seconds from 0.1 to 600").arg(parser.value(QStringLiteral("poll"))),
            Usage);

    const QString pipelineFile = QFileInfo(p.positional()[0]).absoluteFilePath();
    auto pipeline = readPipelineFile(pipelineFile);
    if (!pipeline) return fail(pipeline.message());
    if (pipeline->value(QStringLiteral("steps")).toArray().isEmpty())
        return fail(QStringLiteral("%1: pipeline has no \"steps\" array").arg(p.positional()[0]));
    const QStringList projects = p.positional().mid(1);
    const QString executable = QCoreApplication::applicationFilePath();

    TerminalProgress bar(QStringLiteral("batch"));
    QElapsedTimer clock;
    clock.start();
    int reported = 0;
    const int width = int(QString::number(projects.size()).size());
    auto onResult = [&](int i, const TaskResult& r) {
        bar.finish();
        ++reported;
        QString line = QStringLiteral("[%1/%2] %3: %4")
                           .arg(reported, width)
                           .arg(projects.size())
                           .arg(projects[i], QString::fromLatin1(stateText(r.state)));
        if (!r.reason.isEmpty() && r.state != TaskResult::State::Done && r.state != TaskResult::State::Skipped)
            line += QStringLiteral(": ") + r.reason;
        if (r.state == TaskResult::State::Done) line += QStringLiteral(" (%1 s)").arg(r.seconds, 0, 'f', 1);
        std::printf("%s\n", qUtf8Printable(line));
        std::fflush(stdout);
    };

    std::vector<TaskResult> results;
    QString workDir;
    if (engine == u"local") {
        results = runLocal(executable, pipelineFile, projects, LocalOptions{jobs}, bar.progress(), onResult);
    } else {
        SlurmOptions options;
        options.extraArgs = QProcess::splitCommand(parser.value(QStringLiteral("slurm-args")));
        options.chunk = chunk;
        options.throttle = parser.isSet(QStringLiteral("jobs")) ? jobs : 0;
        options.pollSeconds = poll;
        workDir = parser.value(QStringLiteral("work-dir"));
        if (workDir.isEmpty())
            workDir = QDir::current().filePath(
                QStringLiteral("athlos-batch-%1-%2")
                    .arg(QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyyMMdd-HHmmss")))
                    .arg(::getpid()));
        options.workDir = QFileInfo(workDir).absoluteFilePath();
        auto slurm = runSlurm(executable, pipelineFile, projects, options, bar.progress(), onResult);
        if (!slurm) return fail(slurm.message());
        results = std::move(*slurm);
    }
    bar.finish();

    int done = 0, skipped = 0, failed = 0, cancelled = 0;
    for (const auto& r : results) {
        done += r.state == TaskResult::State::Done;
        skipped += r.state == TaskResult::State::Skipped;
        failed += r.state == TaskResult::State::Failed;
        cancelled += r.state == TaskResult::State::Cancelled || r.state == TaskResult::State::Pending;
    }
    std::printf("batch: %d done, %d skipped, %d failed, %d cancelled in %.1f s\n", done, skipped, failed, cancelled,
                double(clock.elapsed()) / 1000.0);
    if (engine == u"slurm" && failed == 0 && cancelled == 0) QDir(workDir).removeRecursively();

    if (parser.isSet(QStringLiteral("summary")) && cancelled == 0) {
        const QString out = parser.value(QStringLiteral("summary"));
        if (Status s = writeSummary(projects, results, parser.value(QStringLiteral("summary-table")), out); !s)
            return fail(QStringLiteral("--summary: %1").arg(s.message()));
        std::printf("summary %s\n", qUtf8Printable(out));
    }
    if (cancelled > 0) return fail(QStringLiteral("cancelled; unfinished projects are unchanged"), Cancelled);
    if (failed > 0)
        return fail(
            QStringLiteral("%1 of %2 project(s) failed%3")
                .arg(failed)
                .arg(projects.size())
                .arg(engine == u"slurm" ? QStringLiteral(" (task output kept in %1)").arg(workDir) : QString()));
    return Ok;
}

}  // namespace athlos::cli
