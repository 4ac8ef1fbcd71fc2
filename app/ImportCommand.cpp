// athlos import
#include "CommandParser.h"
#include "Commands.h"
#include "TerminalProgress.h"

#include "core/io/Importer.h"
#include "core/io/MultiImport.h"
#include "core/io/TimeFormats.h"
#include "core/model/Project.h"
#include "core/model/StreamKinds.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <cmath>
#include <cstdio>

namespace athlos::cli {

int cmdImport(const QStringList& args) {
    QStringList formats;
    for (const auto& importer : importers()) formats << importer->format();
    CommandParser p(
        QStringLiteral("import <project> <file>... | <folder> --as <rec>[/<stream>] [--format F] [--kind K] "
                       "[--column SRC=CHANNEL[:UNIT]]... [--skip COL]... [--drop-unmapped] [--time-column "
                       "COL[:FORMAT]] [--date D] [--start T]"),
        QStringLiteral("Import a recording into a project. Nothing is written unless the whole import "
                       "succeeds; errors name the file, line and column."));
    p.addPositional(QStringLiteral("project"),
                    QStringLiteral("The .athlos file; created when it does not exist and the import succeeds."));
    p.addPositional(
        QStringLiteral("file"),
        QStringLiteral("The recording to import. Several files of one kind become one stream (the ranges of "
                       "several anchors, pieces of one recording); a folder gives one stream per file."));
    p.addOption({QStringLiteral("as"), QStringLiteral("Recording name, or <rec>/<stream> to name the stream too."),
                 QStringLiteral("rec")});
    p.addOption({QStringLiteral("format"),
                 QStringLiteral("auto (default) or one of: ") + formats.join(QStringLiteral(", ")), QStringLiteral("F"),
                 QStringLiteral("auto")});
    p.addOption({QStringLiteral("kind"),
                 QStringLiteral("Stream kind for CSV: ") + streamKindNames().join(QStringLiteral(", ")),
                 QStringLiteral("K")});
    p.addOption({QStringLiteral("time-repair"),
                 QStringLiteral(
                     "Non-increasing time stamps: reject (default), sort (sort, drop duplicates) or drop (drop them)."),
                 QStringLiteral("mode"), QStringLiteral("reject")});
    p.addOption({QStringLiteral("frame"), QStringLiteral("Coordinate frame, overriding the kind's default."),
                 QStringLiteral("name")});
    p.addOption({QStringLiteral("beacons"),
                 QStringLiteral("A beacon table (id,x,y,z) to import alongside, as <rec>/beacons."),
                 QStringLiteral("file")});
    p.addOption({QStringLiteral("overwrite"), QStringLiteral("Replace existing streams of the same name.")});
    p.addOption({QStringLiteral("column"),
                 QStringLiteral("CSV: store column SRC as CHANNEL, its values in UNIT (converted to SI); repeatable. "
                                "SRC=:UNIT keeps the name."),
                 QStringLiteral("SRC=CHANNEL[:UNIT]")});
    p.addOption(
        {QStringLiteral("skip"), QStringLiteral("CSV: leave column COL out; repeatable."), QStringLiteral("COL")});
    p.addOption(
        {QStringLiteral("drop-unmapped"),
         QStringLiteral("CSV: leave out every column that is neither mapped with --column nor known to the kind.")});
    p.addOption({QStringLiteral("time-column"),
                 QStringLiteral("CSV: the column with the time stamps (default t, in s) and their format: ") +
                     timeFormatNames() + QStringLiteral("."),
                 QStringLiteral("COL[:FORMAT]")});
    p.addOption({QStringLiteral("date"), QStringLiteral("The date of clock times (hh:mm:ss) when the file has none."),
                 QStringLiteral("YYYY-MM-DD")});
    p.addOption({QStringLiteral("start"), QStringLiteral("UTC date-time of t = 0 for relative times (ISO 8601)."),
                 QStringLiteral("datetime")});
    p.addOption({QStringLiteral("rate"),
                 QStringLiteral("gaitmap: the sampling rate of a file whose first column is a sample index (default: "
                                "found from the motion, said in a warning)."),
                 QStringLiteral("HZ")});
    p.addOption(
        {QStringLiteral("labels"),
         QStringLiteral("CSV: a per-sample label column (numbers or text) that becomes annotations: runs of equal "
                        "labels; an empty cell is no annotation."),
         QStringLiteral("COL")});
    p.addOption({QStringLiteral("label-names"), QStringLiteral("Names of number labels: 0=rest,1=run,..."),
                 QStringLiteral("V=NAME,...")});
    p.addOption(
        {QStringLiteral("origin"),
         QStringLiteral("The project's geodetic origin for local ENU x, y, z of GNSS streams (default: the first fix "
                        "of the first GNSS import)."),
         QStringLiteral("LAT,LON[,H]")});
    p.addOption(
        {QStringLiteral("roster"),
         QStringLiteral("Folder import: a CSV file,athlete,number,team,position,mass_kg naming each file's athlete."),
         QStringLiteral("file")});
    p.addOption({QStringLiteral("athlete"), QStringLiteral("Athlete name, stored in the recording's metadata."),
                 QStringLiteral("name")});
    if (auto code = p.parse(args, 2, 100000)) return *code;

    const QString projectPath = p.positional()[0];
    const QStringList files = p.positional().mid(1);
    const QString file = files.front();
    const bool folder = files.size() == 1 && QFileInfo(file).isDir();
    if (p.parser().isSet(QStringLiteral("roster")) && !folder)
        return fail(QStringLiteral("--roster applies to a folder import (one file per athlete)"), Usage);
    ImportOptions options;
    options.format = p.parser().value(QStringLiteral("format"));
    options.kind = p.parser().value(QStringLiteral("kind"));
    options.target = p.parser().value(QStringLiteral("as"));
    options.timeRepair = p.parser().value(QStringLiteral("time-repair"));
    options.frame = p.parser().value(QStringLiteral("frame"));
    options.overwrite = p.parser().isSet(QStringLiteral("overwrite"));
    options.dropUnmapped = p.parser().isSet(QStringLiteral("drop-unmapped"));
    if (options.target.isEmpty()) options.target = folder ? QDir(file).dirName() : QFileInfo(file).completeBaseName();
    if (!QStringList{QStringLiteral("reject"), QStringLiteral("sort"), QStringLiteral("drop")}.contains(
            options.timeRepair))
        return fail(QStringLiteral("--time-repair '%1': use reject, sort or drop").arg(options.timeRepair), Usage);

    for (const QString& spec : p.parser().values(QStringLiteral("column"))) {
        const qsizetype eq = spec.indexOf(QLatin1Char('='));
        if (eq <= 0) return fail(QStringLiteral("--column '%1': expected SRC=CHANNEL[:UNIT]").arg(spec), Usage);
        const QString target = spec.mid(eq + 1);
        const qsizetype colon = target.indexOf(QLatin1Char(':'));
        ColumnMapping m;
        m.source = spec.left(eq).trimmed();
        m.channel = (colon < 0 ? target : target.left(colon)).trimmed();
        m.unit = colon < 0 ? QString() : target.mid(colon + 1).trimmed();
        if (m.channel.isEmpty() && m.unit.isEmpty())
            return fail(QStringLiteral("--column '%1': give a channel name, a unit or both").arg(spec), Usage);
        options.columns.push_back(m);
    }
    for (const QString& column : p.parser().values(QStringLiteral("skip")))
        options.columns.push_back({column.trimmed(), {}, {}, true});
    if (p.parser().isSet(QStringLiteral("time-column"))) {
        const QString spec = p.parser().value(QStringLiteral("time-column"));
        const auto split = splitTimeColumnSpec(spec);
        if (!split) return fail(QStringLiteral("--time-column '%1': %2").arg(spec, split.message()), Usage);
        options.timeColumn = split->first;
        options.timeUnit = split->second;
        if (options.timeColumn.isEmpty())
            return fail(QStringLiteral("--time-column '%1': expected COL[:FORMAT]").arg(spec), Usage);
    }
    if (p.parser().isSet(QStringLiteral("date"))) {
        options.date = p.parser().value(QStringLiteral("date")).trimmed();
        if (!QRegularExpression(QStringLiteral("^\\d{4}-\\d{2}-\\d{2}$")).match(options.date).hasMatch())
            return fail(QStringLiteral("--date '%1': expected YYYY-MM-DD").arg(options.date), Usage);
    }
    if (p.parser().isSet(QStringLiteral("rate"))) {
        bool ok = false;
        options.rate = p.parser().value(QStringLiteral("rate")).toDouble(&ok);
        if (!ok || !std::isfinite(options.rate) || options.rate <= 0.0 || options.rate > 1e6)
            return fail(QStringLiteral("--rate '%1': expected a sampling rate in Hz (> 0)")
                            .arg(p.parser().value(QStringLiteral("rate"))),
                        Usage);
    }
    if (p.parser().isSet(QStringLiteral("start"))) {
        options.start = p.parser().value(QStringLiteral("start")).trimmed();
        if (const auto start = parseUtc(options.start); !start)
            return fail(QStringLiteral("--start: %1").arg(start.message()), Usage);
    }
    if (p.parser().isSet(QStringLiteral("origin"))) {
        const auto origin = parseGeodeticOrigin(p.parser().value(QStringLiteral("origin")));
        if (!origin) return fail(QStringLiteral("--%1").arg(origin.message()), Usage);
        options.origin = *origin;
    }
    options.labelColumn = p.parser().value(QStringLiteral("labels")).trimmed();
    if (p.parser().isSet(QStringLiteral("label-names"))) {
        if (options.labelColumn.isEmpty()) return fail(QStringLiteral("--label-names needs --labels COL"), Usage);
        auto names = parseLabelNames(p.parser().value(QStringLiteral("label-names")));
        if (!names)
            return fail(
                QStringLiteral("--") +
                    QString(names.message()).replace(QStringLiteral("label names"), QStringLiteral("label-names")),
                Usage);
        options.labelNames = std::move(*names);
    }
    if (const QString athlete = p.parser().value(QStringLiteral("athlete")).trimmed(); !athlete.isEmpty())
        options.metadata.insert(QStringLiteral("athlete"), athlete);

    bool created = false;
    auto project = openOrCreateForChange(projectPath, created);
    if (!project) return fail(project.message());

    TerminalProgress bar(QStringLiteral("import"));
    auto result =
        folder ? importFolder(file, options, p.parser().value(QStringLiteral("roster")), bar.progress().sub(0.0, 0.7))
               : importFiles(files, options, bar.progress().sub(0.0, 0.7));
    if (!result) return fail(result.message(), result.message() == u"cancelled" ? Cancelled : Failed);
    if (p.parser().isSet(QStringLiteral("beacons"))) {
        ImportOptions beaconOptions = options;
        beaconOptions.columns.clear();  // the mapping describes the recording's file, not the beacon table
        beaconOptions.timeColumn.clear();
        beaconOptions.timeUnit.clear();
        beaconOptions.metadata = {};
        beaconOptions.format = QStringLiteral("csv");
        beaconOptions.kind = QStringLiteral("beacons");
        beaconOptions.target = ItemPath::parse(options.target).recording + QStringLiteral("/beacons");
        auto beacons = importFile(p.parser().value(QStringLiteral("beacons")), beaconOptions);
        if (!beacons) return fail(beacons.message());
        for (auto& item : beacons->items) result->items.push_back(std::move(item));
    }
    for (const auto& warning : result->warnings) std::fprintf(stderr, "athlos: warning: %s\n", qUtf8Printable(warning));
    QStringList written;
    for (const auto& item : result->items) written << item.path;
    for (const auto& [rec, list] : result->annotations)
        if (!list.empty()) written << QStringLiteral("%1 annotations onto %2").arg(list.size()).arg(rec);
    if (Status s = applyImport(**project, std::move(result).value(), options.overwrite); !s) return fail(s.message());
    if (Status s = (*project)->save(bar.progress().sub(0.7, 1.0)); !s)
        return fail(s.message(), s.message() == u"cancelled" ? Cancelled : Failed);
    bar.finish();
    if (created) std::printf("created project %s\n", qUtf8Printable(projectPath));
    for (const auto& w : written) std::printf("imported %s\n", qUtf8Printable(w));
    return Ok;
}

}  // namespace athlos::cli
