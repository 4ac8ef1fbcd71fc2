// athlos new | info | export
#include "CommandParser.h"
#include "Commands.h"
#include "TerminalProgress.h"

#include "core/io/AnnotationIo.h"
#include "core/io/Exporter.h"
#include "core/model/Project.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <cstdio>

namespace athlos::cli {

int fail(const QString& message, int code) {
    std::fprintf(stderr, "athlos: %s\n", qUtf8Printable(message));
    return code;
}

Expected<std::unique_ptr<Project>> openForChange(const QString& path) {
    auto project = Project::openForChange(path);
    if (project)
        for (const QString& note : (*project)->notes())
            std::fprintf(stderr, "athlos: note: %s\n", qUtf8Printable(note));
    return project;
}

Expected<std::unique_ptr<Project>> openOrCreateForChange(const QString& path, bool& created) {
    created = !QFileInfo::exists(path);
    if (!created) return openForChange(path);
    if (const QFileInfo folder(QFileInfo(path).absolutePath()); !folder.isDir())
        return makeError(QStringLiteral("cannot create project '%1': folder '%2' does not exist")
                             .arg(path, QDir::toNativeSeparators(folder.filePath())));
    auto project = Project::create(path);
    if (Status s = project->lockForChange(); !s) return s.error();
    if (QFileInfo::exists(path)) {  // another process created it meanwhile: add to that one
        project.reset();
        created = false;
        return openForChange(path);
    }
    return project;
}

int cmdNew(const QStringList& args) {
    CommandParser p(QStringLiteral("new <project> [--sport S]"), QStringLiteral("Create an empty project file."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file to create."));
    p.addOption({QStringLiteral("sport"), QStringLiteral("Sport of the project (e.g. athletics, football)."),
                 QStringLiteral("S")});
    p.addOption({QStringLiteral("force"), QStringLiteral("Replace an existing file.")});
    if (auto code = p.parse(args, 1, 1)) return *code;
    const QString path = p.positional()[0];
    if (QFileInfo::exists(path) && !p.parser().isSet(QStringLiteral("force")))
        return fail(QStringLiteral("'%1' already exists (use --force to replace it)").arg(path));
    auto project = Project::create(path, p.parser().value(QStringLiteral("sport")));
    if (Status s = project->save(); !s) return fail(s.message());
    return Ok;
}

namespace {

QJsonObject streamJson(const QString& rec, const Stream& s) {
    const auto& i = s.info();
    QJsonArray columns;
    for (const auto& c : i.columns)
        columns.append(QJsonObject{{QStringLiteral("name"), c.name}, {QStringLiteral("unit"), c.unit}});
    QJsonObject json{{QStringLiteral("path"), rec + QLatin1Char('/') + i.name},
                     {QStringLiteral("kind"), i.kind},
                     {QStringLiteral("frame"), i.frame},
                     {QStringLiteral("samples"), double(i.rows)},
                     {QStringLiteral("t_begin"), i.tBegin},
                     {QStringLiteral("t_end"), i.tEnd},
                     {QStringLiteral("columns"), columns},
                     {QStringLiteral("attributes"), i.attributes},
                     {QStringLiteral("content_hash"), QString::fromLatin1(i.contentHash)}};
    if (!i.provenance.isEmpty()) json[QStringLiteral("provenance")] = i.provenance.toJson();
    return json;
}

QJsonObject tableJson(const QString& rec, const Table& t) {
    QJsonArray columns;
    for (const auto& c : t.columns)
        columns.append(QJsonObject{
            {QStringLiteral("name"), c.name}, {QStringLiteral("unit"), c.unit}, {QStringLiteral("text"), c.isText}});
    QJsonObject json{{QStringLiteral("path"), rec + QLatin1Char('/') + t.name},
                     {QStringLiteral("kind"), t.kind},
                     {QStringLiteral("rows"), double(t.rows())},
                     {QStringLiteral("columns"), columns},
                     {QStringLiteral("attributes"), t.attributes}};
    if (!t.provenance.isEmpty()) json[QStringLiteral("provenance")] = t.provenance.toJson();
    return json;
}

// Models without their definitions (which can be MBs of OpenCV text).
QJsonArray modelsJson(const Project& project) {
    QJsonArray models;
    for (const auto& [name, model] : project.models())
        models.append(QJsonObject{{QStringLiteral("name"), name},
                                  {QStringLiteral("format"), model.format},
                                  {QStringLiteral("bytes"), double(model.definition.size())},
                                  {QStringLiteral("description"), model.description}});
    return models;
}

QJsonObject projectJson(const Project& project) {
    const auto& m = project.meta();
    QJsonArray recordings;
    for (const auto& [name, rec] : project.recordings()) {
        QJsonArray streams, tables;
        for (const auto& [n, s] : rec.streams) streams.append(streamJson(name, s));
        for (const auto& [n, t] : rec.tables) tables.append(tableJson(name, t));
        recordings.append(QJsonObject{{QStringLiteral("name"), name},
                                      {QStringLiteral("metadata"), rec.metadata},
                                      {QStringLiteral("streams"), streams},
                                      {QStringLiteral("tables"), tables},
                                      {QStringLiteral("annotations"), int(rec.annotations.size())}});
    }
    QJsonArray geometry;
    for (const auto& [name, g] : project.geometry()) geometry.append(name);
    return {{QStringLiteral("path"), project.path()},
            {QStringLiteral("format_version"), m.formatVersion},
            {QStringLiteral("app_version"), m.appVersion},
            {QStringLiteral("created"), m.created},
            {QStringLiteral("modified"), m.modified},
            {QStringLiteral("sport"), m.sport},
            {QStringLiteral("recordings"), recordings},
            {QStringLiteral("geometry"), geometry},
            {QStringLiteral("annotation_classes"), QJsonArray::fromStringList(project.annotationClasses())},
            {QStringLiteral("pipelines"), project.pipelineHistory()},
            {QStringLiteral("models"), modelsJson(project)}};
}

void printText(const Project& project) {
    const auto& m = project.meta();
    std::printf("%s\n  format %d, written by Athlos %s, modified %s%s\n", qUtf8Printable(project.path()),
                m.formatVersion, qUtf8Printable(m.appVersion), qUtf8Printable(m.modified),
                m.sport.isEmpty() ? "" : qUtf8Printable(QStringLiteral(", sport ") + m.sport));
    for (const auto& [name, rec] : project.recordings()) {
        std::printf("%s\n", qUtf8Printable(name));
        for (const auto& [n, s] : rec.streams) {
            const auto& i = s.info();
            QStringList cols;
            for (const auto& c : i.columns)
                cols << (c.unit.isEmpty() ? c.name : QStringLiteral("%1[%2]").arg(c.name, c.unit));
            const double rate = i.rows > 1 && i.tEnd > i.tBegin ? (i.rows - 1) / (i.tEnd - i.tBegin) : 0.0;
            std::printf("  %-24s %-14s %10lld samples  %.3f..%.3f s  ~%.4g Hz  frame %s\n    columns: %s\n",
                        qUtf8Printable(name + QLatin1Char('/') + n), qUtf8Printable(i.kind), i.rows, i.tBegin, i.tEnd,
                        rate, qUtf8Printable(i.frame.isEmpty() ? QStringLiteral("-") : i.frame),
                        qUtf8Printable(cols.join(QStringLiteral(", "))));
            if (!i.provenance.isEmpty())
                std::printf("    from: %s %s %s\n", qUtf8Printable(i.provenance.processorId),
                            qUtf8Printable(i.provenance.processorVersion),
                            qUtf8Printable(QString::fromUtf8(
                                QJsonDocument(i.provenance.parameters).toJson(QJsonDocument::Compact))));
        }
        for (const auto& [n, t] : rec.tables)
            std::printf("  %-24s %-14s %10lld rows (table)\n", qUtf8Printable(name + QLatin1Char('/') + n),
                        qUtf8Printable(t.kind), t.rows());
        if (!rec.annotations.empty()) std::printf("  %zu annotations\n", rec.annotations.size());
    }
    if (!project.pipelineHistory().isEmpty())
        std::printf("%lld pipeline run(s) recorded\n", qlonglong(project.pipelineHistory().size()));
    for (const auto& [name, model] : project.models()) {
        const QJsonObject& d = model.description;
        QStringList classes;
        for (const auto& c : d.value(QStringLiteral("classes")).toArray()) classes << c.toString();
        const QJsonObject cv = d.value(QStringLiteral("cross_validation")).toObject();
        std::printf("model %s: %s on %s, %lld classes (%s), %.1f kB", qUtf8Printable(name),
                    qUtf8Printable(d.value(QStringLiteral("classifier")).toString(model.format)),
                    qUtf8Printable(d.value(QStringLiteral("input")).toString()), qlonglong(classes.size()),
                    qUtf8Printable(classes.join(QStringLiteral(", "))), double(model.definition.size()) / 1e3);
        if (cv.contains(QStringLiteral("balanced_accuracy")))
            std::printf(", cross-validated balanced accuracy %.3f (%s)",
                        cv.value(QStringLiteral("balanced_accuracy")).toDouble(),
                        qUtf8Printable(cv.value(QStringLiteral("scheme")).toString()));
        if (d.contains(QStringLiteral("feature_selection")))
            std::printf(", %lld of %lld features selected by mutual information",
                        qlonglong(d.value(QStringLiteral("feature_selection"))
                                      .toObject()
                                      .value(QStringLiteral("features"))
                                      .toArray()
                                      .size()),
                        qlonglong(d.value(QStringLiteral("features")).toArray().size()));
        std::printf("\n");
    }
}

}  // namespace

int cmdInfo(const QStringList& args) {
    CommandParser p(QStringLiteral("info <project> [--json]"),
                    QStringLiteral("Describe a project without reading its samples."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable output.")});
    if (auto code = p.parse(args, 1, 1)) return *code;
    auto project = Project::open(p.positional()[0]);
    if (!project) return fail(project.message());
    if (p.parser().isSet(QStringLiteral("json")))
        std::fputs(QJsonDocument(projectJson(**project)).toJson(QJsonDocument::Indented).constData(), stdout);
    else
        printText(**project);
    return Ok;
}

int cmdExport(const QStringList& args) {
    CommandParser p(
        QStringLiteral("export <project> <rec/stream>|<rec>/annotations --to <file.csv|file.h5|file.json|file.eaf>"),
        QStringLiteral(
            "Export a stream or table to CSV (round-trips exactly) or HDF5; a recording's annotations "
            "to CSV (start,end,label,confidence,source,annotator; s), JSON or ELAN .eaf (one tier per label)."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addPositional(QStringLiteral("item"), QStringLiteral("Stream or table as <recording>/<name>."));
    p.addOption(
        {QStringLiteral("to"),
         QStringLiteral(
             "Output file; the format follows the extension (.csv, .h5/.hdf5; annotations: .csv, .json, .eaf)."),
         QStringLiteral("file")});
    if (auto code = p.parse(args, 2, 2)) return *code;
    const QString to = p.parser().value(QStringLiteral("to"));
    if (to.isEmpty()) return fail(QStringLiteral("export needs --to <file.csv|file.h5>"), Usage);
    const QString suffix = QFileInfo(to).suffix().toLower();
    const bool csv = suffix == u"csv" || suffix == u"txt";
    const bool h5 = suffix == u"h5" || suffix == u"hdf5";
    const bool annotations = p.positional()[1].endsWith(QStringLiteral("/annotations"));
    const bool json = suffix == u"json" && annotations;
    const bool eaf = suffix == u"eaf" && annotations;
    if (!csv && !h5 && !json && !eaf)
        return fail(QStringLiteral("--to '%1': use a .csv or .h5 file name (.json or .eaf for annotations)").arg(to),
                    Usage);

    auto project = Project::open(p.positional()[0]);
    if (!project) return fail(project.message());
    const QString item = p.positional()[1];
    TerminalProgress bar(QStringLiteral("export"));
    Status status;
    if (const Stream* s = (*project)->stream(item)) {
        status = csv ? exportStreamCsv(*s, to, bar.progress()) : exportStreamHdf5(*s, to);
    } else if (const Table* t = (*project)->table(item)) {
        status = csv ? exportTableCsv(*t, to) : exportTableHdf5(*t, to);
    } else if (const Recording* rec = (*project)->recording(item.section(QLatin1Char('/'), 0, 0));
               rec && item.section(QLatin1Char('/'), 1) == QLatin1String("annotations")) {
        if (h5) return fail(QStringLiteral("--to '%1': annotations export to .csv, .json or .eaf").arg(to), Usage);
        status = exportAnnotations(rec->annotations, to);
    } else {
        return fail(QStringLiteral("'%1' has no stream or table '%2' (see athlos info)").arg(p.positional()[0], item));
    }
    bar.finish();
    if (!status) return fail(status.message(), status.message() == u"cancelled" ? Cancelled : Failed);
    return Ok;
}

}  // namespace athlos::cli
