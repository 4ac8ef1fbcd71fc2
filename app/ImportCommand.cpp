// athlos import
#include "CommandParser.h"
#include "Commands.h"
#include "TerminalProgress.h"

#include "core/io/Importer.h"
#include "core/model/Project.h"
#include "core/model/StreamKinds.h"

#include <QFileInfo>
#include <cstdio>

namespace athlos::cli {

int cmdImport(const QStringList& args) {
    QStringList formats;
    for (const auto& importer : importers()) formats << importer->format();
    CommandParser p(QStringLiteral("import <project> <file> --as <rec>[/<stream>] [--format F] [--kind K]"),
                    QStringLiteral("Import a recording into a project. Nothing is written unless the whole import "
                                   "succeeds; errors name the file, line and column."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file (create it with athlos new)."));
    p.addPositional(QStringLiteral("file"), QStringLiteral("The recording to import."));
    p.addOption({QStringLiteral("as"), QStringLiteral("Recording name, or <rec>/<stream> to name the stream too."), QStringLiteral("rec")});
    p.addOption({QStringLiteral("format"), QStringLiteral("auto (default) or one of: ") + formats.join(QStringLiteral(", ")),
                 QStringLiteral("F"), QStringLiteral("auto")});
    p.addOption({QStringLiteral("kind"), QStringLiteral("Stream kind for CSV: ") + streamKindNames().join(QStringLiteral(", ")),
                 QStringLiteral("K")});
    p.addOption({QStringLiteral("time-repair"),
                 QStringLiteral("Non-increasing time stamps: reject (default), sort (sort, drop duplicates) or drop (drop them)."),
                 QStringLiteral("mode"), QStringLiteral("reject")});
    p.addOption({QStringLiteral("frame"), QStringLiteral("Coordinate frame, overriding the kind's default."), QStringLiteral("name")});
    p.addOption({QStringLiteral("beacons"), QStringLiteral("A beacon table (id,x,y,z) to import alongside, as <rec>/beacons."),
                 QStringLiteral("file")});
    p.addOption({QStringLiteral("overwrite"), QStringLiteral("Replace existing streams of the same name.")});
    if (auto code = p.parse(args, 2, 2)) return *code;

    const QString projectPath = p.positional()[0];
    const QString file = p.positional()[1];
    ImportOptions options;
    options.format = p.parser().value(QStringLiteral("format"));
    options.kind = p.parser().value(QStringLiteral("kind"));
    options.target = p.parser().value(QStringLiteral("as"));
    options.timeRepair = p.parser().value(QStringLiteral("time-repair"));
    options.frame = p.parser().value(QStringLiteral("frame"));
    options.overwrite = p.parser().isSet(QStringLiteral("overwrite"));
    if (options.target.isEmpty()) options.target = QFileInfo(file).completeBaseName();
    if (!QStringList{QStringLiteral("reject"), QStringLiteral("sort"), QStringLiteral("drop")}.contains(options.timeRepair))
        return fail(QStringLiteral("--time-repair '%1': use reject, sort or drop").arg(options.timeRepair), Usage);

    if (!QFileInfo::exists(projectPath))
        return fail(QStringLiteral("'%1' does not exist (create it with: athlos new %1)").arg(projectPath));
    auto project = Project::open(projectPath);
    if (!project) return fail(project.message());

    TerminalProgress bar(QStringLiteral("import"));
    auto result = importFile(file, options, bar.progress().sub(0.0, 0.7));
    if (!result) return fail(result.message(), result.message() == u"cancelled" ? Cancelled : Failed);
    if (p.parser().isSet(QStringLiteral("beacons"))) {
        ImportOptions beaconOptions = options;
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
    if (Status s = applyImport(**project, std::move(result).value(), options.overwrite); !s) return fail(s.message());
    if (Status s = (*project)->save(bar.progress().sub(0.7, 1.0)); !s)
        return fail(s.message(), s.message() == u"cancelled" ? Cancelled : Failed);
    bar.finish();
    for (const auto& w : written) std::printf("imported %s\n", qUtf8Printable(w));
    return Ok;
}

}  // namespace athlos::cli
