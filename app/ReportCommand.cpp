// `athlos report`: the coach's PDF report (ui/report/SessionReport): session metrics computed where
// missing (both cores), the project saved with them, then the team page and a page per athlete.
#include "app/CommandParser.h"
#include "app/Commands.h"
#include "app/TerminalProgress.h"
#include "core/io/Exporter.h"
#include "ui/report/GaitReport.h"
#include "ui/report/SessionReport.h"

#include <cstdio>

namespace athlos::cli {

namespace {
int exitCode(const Error& error) { return error.message == u"cancelled" ? Cancelled : Failed; }

// `report --gait REC`: reads the project, changes nothing (the summary is computed in memory).
int gaitReport(CommandParser& p, const QString& pdf, const QVariantMap& parameters) {
    auto project = Project::open(p.positional()[0]);
    if (!project) return fail(project.message());
    QStringList strides;
    for (const QString& s : p.parser().value(QStringLiteral("strides")).split(QLatin1Char(','), Qt::SkipEmptyParts))
        strides << s.trimmed();
    auto input = ui::GaitReport::strideTables(**project, p.parser().value(QStringLiteral("gait")).trimmed(), strides);
    if (!input) return fail(input.message());
    auto summary = ui::GaitReport::summary(**project, *input, parameters);
    if (!summary) return fail(summary.message());
    TerminalProgress bar(QStringLiteral("report"));
    if (Status s = ui::GaitReport::writePdf(**project, *input, *summary, pdf, bar.progress()); !s)
        return fail(s.message(), exitCode(s.error()));
    bar.finish();
    std::printf("wrote %s (gait report of %s)\n", qUtf8Printable(pdf),
                qUtf8Printable(input->strides.join(QStringLiteral(", "))));
    return Ok;
}
}  // namespace

int cmdReport(const QStringList& args) {
    CommandParser p(
        QStringLiteral(
            "report <project> --to report.pdf [--recording R] [--csv team.csv] [--param k=v …]\n"
            "       athlos report <project> --to gait.pdf --gait REC [--strides REC/A,REC/B] [--param k=v …]"),
        QStringLiteral("Write the coach's session report as a PDF: a team page (table and distance bars) "
                       "and a page per athlete (speed over time, zone bars, heat map on the venue, splits, "
                       "action counts). session-metrics runs first for every athlete whose metrics are "
                       "missing or stale (with the given parameters) and the project is saved with them; "
                       "Ctrl-C cancels and leaves the project untouched. With --gait: the gait report of a "
                       "recording's stride tables (gait-parameters, one per foot): the steady-state summary of "
                       "gait-summary (its parameters with --param), stride length and gait speed over time, and "
                       "every stride; the project is not changed."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addOption({QStringLiteral("to"), QStringLiteral("The PDF to write."), QStringLiteral("file")});
    p.addOption({QStringLiteral("recording"),
                 QStringLiteral("Only this recording (default: every recording with "
                                "athletes)."),
                 QStringLiteral("rec")});
    p.addOption({QStringLiteral("csv"), QStringLiteral("Also write the team table as CSV."), QStringLiteral("file")});
    p.addOption({QStringLiteral("param"),
                 QStringLiteral("session-metrics parameter for missing metrics (with --gait: gait-summary parameter), "
                                "repeatable."),
                 QStringLiteral("k=v")});
    p.addOption({QStringLiteral("gait"),
                 QStringLiteral("The gait report of this recording's gait-parameters tables instead."),
                 QStringLiteral("rec")});
    p.addOption({QStringLiteral("strides"),
                 QStringLiteral("With --gait: the stride tables to report, when the recording has several per foot."),
                 QStringLiteral("rec/a,rec/b")});
    if (auto code = p.parse(args, 1, 1)) return *code;
    const QString pdf = p.parser().value(QStringLiteral("to"));
    if (pdf.isEmpty()) return fail(QStringLiteral("report needs --to <file.pdf>"), Usage);
    QVariantMap parameters;
    for (const QString& kv : p.parser().values(QStringLiteral("param"))) {
        const int eq = kv.indexOf(QLatin1Char('='));
        if (eq <= 0) return fail(QStringLiteral("--param '%1': expected name=value").arg(kv), Usage);
        parameters.insert(kv.left(eq).trimmed(), kv.mid(eq + 1).trimmed());
    }

    if (p.parser().isSet(QStringLiteral("gait"))) return gaitReport(p, pdf, parameters);
    if (p.parser().isSet(QStringLiteral("strides"))) return fail(QStringLiteral("--strides needs --gait REC"), Usage);

    auto project = openForChange(p.positional()[0]);
    if (!project) return fail(project.message());
    auto athletes = ui::SessionReport::athletes(**project, p.parser().value(QStringLiteral("recording")));
    if (!athletes) {
        // A project of gait recordings: say how to report those instead.
        const QStringList gait = ui::GaitReport::recordingsWithStrides(**project);
        return fail(athletes.message() + (gait.isEmpty()
                                              ? QString()
                                              : QStringLiteral("; for the gait report of its stride tables: --gait %1")
                                                    .arg(gait.join(QStringLiteral(" or --gait ")))));
    }
    TerminalProgress bar(QStringLiteral("report"));
    auto computed = ui::SessionReport::computeMissing(**project, *athletes, parameters, bar.progress().sub(0.0, 0.75));
    if (!computed) return fail(computed.message(), exitCode(computed.error()));
    if (*computed > 0)
        if (Status s = (*project)->save(bar.progress().sub(0.75, 0.8)); !s)
            return fail(s.message(), exitCode(s.error()));
    if (p.parser().isSet(QStringLiteral("csv"))) {
        auto team = ui::SessionReport::teamTable(**project, *athletes);
        if (!team) return fail(team.message());
        if (Status s = exportTableCsv(*team, p.parser().value(QStringLiteral("csv"))); !s) return fail(s.message());
    }
    if (Status s = ui::SessionReport::writePdf(**project, *athletes, pdf, bar.progress().sub(0.8, 1.0)); !s)
        return fail(s.message(), exitCode(s.error()));
    bar.finish();
    std::printf("computed session metrics for %d of %lld athletes\nwrote %s (%lld pages)\n", *computed,
                static_cast<long long>(athletes->size()), qUtf8Printable(pdf),
                static_cast<long long>(athletes->size() + 1));
    return Ok;
}

}  // namespace athlos::cli
