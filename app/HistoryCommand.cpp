// `athlos history`: every athlete's sessions across projects (their session-metrics `whole` rows) against
// a rolling 4-week baseline, with flags (core/model/SessionHistory).
#include "app/CommandParser.h"
#include "app/Commands.h"
#include "core/io/Exporter.h"
#include "core/model/SessionHistory.h"

#include <QFileInfo>
#include <cstdio>

namespace athlos::cli {

namespace {

// The athlete and date of a metrics table: from its positions stream (provenance input 0), else the
// recording's metadata.
Expected<SessionRecord> recordOf(const Project& project, const QString& recording, const Table& table) {
    SessionRecord r;
    const QString where = QStringLiteral("%1: %2/%3").arg(QFileInfo(project.path()).fileName(), recording, table.name);
    r.session = where;
    const Recording* rec = project.recording(recording);
    const Stream* positions =
        table.provenance.inputs.empty() ? nullptr : project.stream(table.provenance.inputs.front().name);
    const QJsonObject attrs = positions ? positions->info().attributes : QJsonObject();
    for (const char* key : {"athlete", "label"})
        if (r.athlete.isEmpty()) r.athlete = attrs.value(QLatin1String(key)).toString();
    if (r.athlete.isEmpty() && rec) r.athlete = rec->metadata.value(QStringLiteral("athlete")).toString();
    if (r.athlete.isEmpty() && positions) r.athlete = positions->name();
    QString date = attrs.value(QStringLiteral("t0_utc")).toString();
    if (date.isEmpty() && rec) date = rec->metadata.value(QStringLiteral("date")).toString();
    r.date = QDateTime::fromString(date, Qt::ISODateWithMs);
    if (!r.date.isValid()) r.date = QDateTime::fromString(date, Qt::ISODate);
    if (!r.date.isValid())
        return makeError(QStringLiteral("%1: the session has no date (import with absolute time stamps or --start, "
                                        "or set the recording's metadata 'date')")
                             .arg(where));
    const TableColumn* period = table.column(QStringLiteral("period"));
    const int whole = period ? static_cast<int>(period->texts.indexOf(QStringLiteral("whole"))) : -1;
    if (whole < 0) return makeError(QStringLiteral("%1: no 'whole' row").arg(where));
    for (const auto& c : table.columns)
        if (!c.isText) r.values[c.name] = c.numbers[std::size_t(whole)];
    return r;
}

}  // namespace

int cmdHistory(const QStringList& args) {
    CommandParser p(QStringLiteral("history <project>… --to history.csv [--athlete A] [--metrics m1,m2…] "
                                   "[--baseline-days 28] [--low 0.8] [--high 1.5]"),
                    QStringLiteral("Every athlete's sessions (the whole rows of their session-metrics tables, in any "
                                   "number of projects) against the mean of the same athlete's sessions in the 4 weeks "
                                   "before, with the ratio and a flag outside [low, high] (acute:chronic workload "
                                   "ratio, Gabbett 2016: 0.8 and 1.5)."));
    p.addPositional(QStringLiteral("projects"), QStringLiteral("The .athlos files."));
    p.addOption({QStringLiteral("to"), QStringLiteral("The CSV to write."), QStringLiteral("file")});
    p.addOption({QStringLiteral("athlete"), QStringLiteral("Only this athlete."), QStringLiteral("name")});
    p.addOption(
        {QStringLiteral("metrics"), QStringLiteral("Metrics (columns of session-metrics)."), QStringLiteral("list")});
    p.addOption({QStringLiteral("baseline-days"), QStringLiteral("Length of the baseline window (days)."),
                 QStringLiteral("days")});
    p.addOption({QStringLiteral("low"), QStringLiteral("Flag ratios below this."), QStringLiteral("ratio")});
    p.addOption({QStringLiteral("high"), QStringLiteral("Flag ratios above this."), QStringLiteral("ratio")});
    if (auto code = p.parse(args, 1, 1000)) return *code;
    const QString out = p.parser().value(QStringLiteral("to"));
    if (out.isEmpty()) return fail(QStringLiteral("history needs --to <file.csv>"), Usage);
    SessionHistory::Params params;
    auto number = [&](const char* option, double& target) -> bool {
        if (!p.parser().isSet(QLatin1String(option))) return true;
        bool ok = false;
        target = p.parser().value(QLatin1String(option)).toDouble(&ok);
        return ok && target > 0;
    };
    for (const char* option : {"baseline-days", "low", "high"}) {
        double& target = QLatin1String(option) == QLatin1String("baseline-days") ? params.baselineDays
                         : QLatin1String(option) == QLatin1String("low")         ? params.lowRatio
                                                                                 : params.highRatio;
        if (!number(option, target))
            return fail(QStringLiteral("--%1 '%2': expected a positive number")
                            .arg(QLatin1String(option), p.parser().value(QLatin1String(option))),
                        Usage);
    }
    if (p.parser().isSet(QStringLiteral("metrics")))
        params.metrics = p.parser().value(QStringLiteral("metrics")).split(QLatin1Char(','), Qt::SkipEmptyParts);
    const QString athlete = p.parser().value(QStringLiteral("athlete"));

    std::vector<SessionRecord> records;
    for (const QString& path : p.positional()) {
        auto project = Project::open(path);
        if (!project) return fail(project.message());
        for (const auto& [name, rec] : (*project)->recordings())
            for (const auto& [tableName, table] : rec.tables) {
                if (table.kind != QLatin1String("session-metrics")) continue;
                auto r = recordOf(**project, name, table);
                if (!r) return fail(r.message());
                if (athlete.isEmpty() || r->athlete == athlete) records.push_back(std::move(*r));
            }
    }
    if (records.empty())
        return fail(athlete.isEmpty() ? QStringLiteral("no session-metrics tables in the given projects (run "
                                                       "session-metrics or report first)")
                                      : QStringLiteral("--athlete '%1': no sessions of that athlete").arg(athlete));
    auto table = SessionHistory::build(std::move(records), params);
    if (!table) return fail(QStringLiteral("--metrics: %1").arg(table.message()));
    if (Status s = exportTableCsv(*table, out); !s) return fail(s.message());
    const TableColumn* flags = table->column(QStringLiteral("flags"));
    int flagged = 0;
    for (int i = 0; i < flags->texts.size(); ++i)
        if (!flags->texts[i].isEmpty()) {
            ++flagged;
            std::printf("%s  %s  %s: %s\n", qUtf8Printable(table->column(QStringLiteral("date"))->texts[i]),
                        qUtf8Printable(table->column(QStringLiteral("athlete"))->texts[i]),
                        qUtf8Printable(table->column(QStringLiteral("session"))->texts[i]),
                        qUtf8Printable(flags->texts[i]));
        }
    std::printf("wrote %s (%lld sessions, %d flagged)\n", qUtf8Printable(out), table->rows(), flagged);
    return Ok;
}

}  // namespace athlos::cli
