#include "core/processing/ProcessorRunner.h"

#include "core/processing/OutputChecks.h"
#include "core/processing/ProcessorRegistry.h"
#include "core/util/Version.h"

#include <QCryptographicHash>
#include <QDateTime>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonParseError>
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace athlos {
namespace {

// What a missing input could have been: the streams (or tables) of its recording, or the project's
// recordings when that does not exist either, e.g. " (walk has: l-heel, l-instep)".
QString whatIsThere(const Project& project, const QString& path, bool table) {
    const auto list = [](QStringList names) {
        constexpr int kShown = 12;
        if (names.size() > kShown) names = names.mid(0, kShown) << QStringLiteral("…");
        return names.join(QStringLiteral(", "));
    };
    const QString rec = ItemPath::parse(path).recording;
    const auto it = project.recordings().find(rec);
    if (it == project.recordings().end()) {
        QStringList recordings;
        for (const auto& r : project.recordings()) recordings << r.first;
        return recordings.isEmpty() ? QStringLiteral(" (the project has no recordings)")
                                    : QStringLiteral(" (recordings: %1)").arg(list(recordings));
    }
    QStringList names;
    if (table)
        for (const auto& t : it->second.tables) names << t.first;
    else
        for (const auto& st : it->second.streams) names << st.first;
    return names.isEmpty() ? QStringLiteral(" ('%1' has no %2)").arg(rec, table ? u"tables" : u"streams")
                           : QStringLiteral(" (%1 has: %2)").arg(rec, list(names));
}

}  // namespace

QByteArray tableHash(const Table& table) {
    QCryptographicHash hash(QCryptographicHash::Sha256);
    for (const auto& c : table.columns) {
        hash.addData(c.name.toUtf8());
        if (c.isText) {
            for (const auto& s : c.texts) hash.addData(s.toUtf8().append('\0'));
        } else {
            hash.addData(QByteArrayView(reinterpret_cast<const char*>(c.numbers.data()),
                                        qsizetype(c.numbers.size() * sizeof(double))));
        }
    }
    return hash.result().toHex();
}

QString outputPathFor(const QString& output, const QString& suffix) {
    return suffix.isEmpty() ? output : output + QLatin1Char('-') + suffix;
}

RunRequest pipelineStepRequest(const QJsonObject& step) {
    RunRequest request;
    request.processorId = step.value(QStringLiteral("processor")).toString();
    const QJsonValue input = step.value(QStringLiteral("input"));
    if (input.isArray()) {
        for (const auto& v : input.toArray()) request.inputs << v.toString();
    } else {
        request.inputs = input.toString().split(QLatin1Char(','), Qt::SkipEmptyParts);
    }
    request.output = step.value(QStringLiteral("output")).toString();
    request.parameters = step.value(QStringLiteral("params")).toObject().toVariantMap();
    return request;
}

namespace {

// An item a run may replace; imported data is never overwritten by a processor result.
bool isImported(const Provenance& p) { return p.processorId.startsWith(QLatin1String("import:")); }

const QLatin1String kAnnotationProvenance("annotation_provenance");

// Replaces the annotations a previous run of the same processor wrote for the same output path
// (manual annotations and other processors' predictions stay) and records the provenance.
void putAnnotations(Project& project, const QString& path, Annotations annotations, const Provenance& provenance) {
    Recording& rec = project.ensureRecording(ItemPath::parse(path).recording);
    auto& all = rec.annotations;
    std::erase_if(all, [&](const Annotation& a) { return a.source == provenance.processorId && a.annotator == path; });
    for (auto& a : annotations) {
        a.source = provenance.processorId;
        a.annotator = path;
        a.confidence = std::clamp(std::isfinite(a.confidence) ? a.confidence : 0.0, 0.0, 1.0);
        if (a.tEnd < a.tStart) std::swap(a.tStart, a.tEnd);
        all.push_back(std::move(a));
    }
    QJsonObject sources = rec.metadata.value(kAnnotationProvenance).toObject();
    sources[path] = provenance.toJson();
    rec.metadata[kAnnotationProvenance] = sources;
    project.setModified();
}

}  // namespace

Expected<ComputedRun> computeRun(const Project& project, const Processor& processor, const RunRequest& request,
                                 const Progress& progress) {
    const QString pid = processor.id();
    const auto specs = processor.inputs();

    // Inputs: count, existence, stream/table and kind.
    int required = 0;
    for (const auto& s : specs) required += s.optional ? 0 : 1;
    if (request.inputs.size() < required || request.inputs.size() > specs.size()) {
        QStringList roles;
        for (const auto& s : specs) roles << (s.optional ? QStringLiteral("[%1]").arg(s.name) : s.name);
        return makeError(QStringLiteral("%1 takes %2 input(s) (%3), got %4")
                             .arg(pid)
                             .arg(required == specs.size() ? QString::number(required)
                                                           : QStringLiteral("%1 to %2").arg(required).arg(specs.size()))
                             .arg(roles.join(QStringLiteral(", ")))
                             .arg(request.inputs.size()));
    }
    std::vector<const Stream*> streams(std::size_t(specs.size()), nullptr);
    std::vector<const Table*> tables(std::size_t(specs.size()), nullptr);
    std::vector<QString> inputPaths(std::size_t(specs.size()));
    std::vector<ProvenanceInput> provenanceInputs;
    for (int i = 0; i < request.inputs.size(); ++i) {
        const auto& spec = specs[i];
        const QString& path = request.inputs[i];
        inputPaths[std::size_t(i)] = path;
        if (spec.table) {
            const Table* t = project.table(path);
            if (!t)
                return makeError(QStringLiteral("input '%1' (%2): no table of that name in the project%3")
                                     .arg(path, spec.name, whatIsThere(project, path, true)));
            if (!spec.kinds.isEmpty() && !spec.kinds.contains(t->kind))
                return makeError(QStringLiteral("input '%1' (%2) is a '%3' table; %4 expects %5")
                                     .arg(path, spec.name, t->kind, pid, spec.kinds.join(QStringLiteral(" or "))));
            tables[std::size_t(i)] = t;
            provenanceInputs.push_back({path, tableHash(*t)});
        } else {
            const Stream* s = project.stream(path);
            if (!s)
                return makeError(QStringLiteral("input '%1' (%2): no stream of that name in the project%3")
                                     .arg(path, spec.name, whatIsThere(project, path, false)));
            if (!spec.kinds.isEmpty() && !spec.kinds.contains(s->kind()))
                return makeError(QStringLiteral("input '%1' (%2) is a '%3' stream; %4 expects %5")
                                     .arg(path, spec.name, s->kind(), pid, spec.kinds.join(QStringLiteral(" or "))));
            streams[std::size_t(i)] = s;
            provenanceInputs.push_back({path, s->info().contentHash});
        }
    }

    const ItemPath out = ItemPath::parse(request.output);
    if (!out.isValid())
        return makeError(QStringLiteral("--output '%1' must be <recording>/<name>").arg(request.output));
    for (const auto& o : processor.outputs()) {
        if (o.annotations) continue;
        const QString path = outputPathFor(request.output, o.suffix);
        const Stream* s = project.stream(path);
        const Table* t = project.table(path);
        if ((s && isImported(s->info().provenance)) || (t && isImported(t->provenance)))
            return makeError(
                QStringLiteral("output '%1' would replace imported data; choose another --output name").arg(path));
    }

    auto params = validateParameters(processor.parameters(), request.parameters);
    if (!params) return makeError(QStringLiteral("%1: %2").arg(pid, params.message()));

    RunContext context(project, specs, streams, tables, inputPaths, *params, request.output, progress);
    if (Status valid = processor.validate(context); !valid)
        return makeError(QStringLiteral("%1: %2").arg(pid, valid.message()));

    auto produced = processor.run(context);
    if (progress.isCancelled()) return cancelledError();
    if (!produced) return makeError(QStringLiteral("%1: %2").arg(pid, produced.message()));
    // Nothing is stored unless every output holds something (OutputChecks.h).
    for (const auto& item : *produced)
        if (Status useful = checkOutputUseful(item, outputPathFor(request.output, item.suffix)); !useful)
            return makeError(QStringLiteral("%1: %2").arg(pid, useful.message()));

    ComputedRun computed;
    computed.output = request.output;
    computed.produced = std::move(*produced);
    Provenance& provenance = computed.provenance;
    provenance.processorId = pid;
    provenance.processorVersion = processor.version();
    provenance.parameters = QJsonObject::fromVariantMap(*params);
    provenance.inputs = provenanceInputs;
    for (const ProvenanceInput& read : context.extraReads()) provenance.inputs.push_back(read);
    provenance.appVersion = appVersion();
    provenance.time = QDateTime::currentDateTimeUtc();
    progress.report(1.0, QStringLiteral("done"));
    return computed;
}

RunOutcome storeRun(Project& project, ComputedRun run) {
    const Provenance& provenance = run.provenance;
    RunOutcome outcome;
    outcome.parameters = provenance.parameters;
    for (auto& item : run.produced) {
        const QString path = outputPathFor(run.output, item.suffix);
        if (auto* stream = std::get_if<Stream>(&item.item)) {
            stream->info().provenance = provenance;
            project.putStream(path, std::move(*stream));
        } else if (auto* table = std::get_if<Table>(&item.item)) {
            table->provenance = provenance;
            project.putTable(path, std::move(*table));
        } else {
            putAnnotations(project, path, std::move(std::get<Annotations>(item.item)), provenance);
            outcome.annotated << path;
            continue;
        }
        outcome.written << path;
    }
    return outcome;
}

Expected<RunOutcome> runProcessor(Project& project, const Processor& processor, const RunRequest& request,
                                  const Progress& progress) {
    auto computed = computeRun(project, processor, request, progress);
    if (!computed) return computed.error();
    return storeRun(project, std::move(*computed));
}

Expected<RunOutcome> runProcessor(Project& project, const RunRequest& request, const Progress& progress) {
    auto processor = ProcessorRegistry::instance().find(request.processorId);
    if (!processor)
        return makeError(QStringLiteral("unknown processor '%1' (available: %2)")
                             .arg(request.processorId, ProcessorRegistry::instance().ids().join(QStringLiteral(", "))));
    return runProcessor(project, *processor, request, progress);
}

namespace {

// What an item path held before a pipeline step replaced it, to undo a failed pipeline. For an
// annotation output: the recording's annotations and metadata (absent: no such recording).
struct Snapshot {
    QString path;
    std::optional<Stream> stream;
    std::optional<Table> table;
    bool annotations = false;
    std::optional<std::pair<Annotations, QJsonObject>> recording;
};

void restore(Project& project, const std::vector<Snapshot>& snapshots, bool wasModified) {
    for (auto it = snapshots.rbegin(); it != snapshots.rend(); ++it) {
        if (it->annotations) {
            const QString name = ItemPath::parse(it->path).recording;
            Recording* rec = project.recording(name);
            if (it->recording && rec) {
                rec->annotations = it->recording->first;
                rec->metadata = it->recording->second;
            } else if (!it->recording && rec && rec->streams.empty() && rec->tables.empty()) {
                project.removeRecording(name);
            } else if (rec) {
                rec->annotations.clear();
                rec->metadata.remove(kAnnotationProvenance);
            }
            continue;
        }
        project.removeItem(it->path);
        if (it->stream) project.putStream(it->path, *it->stream);
        if (it->table) project.putTable(it->path, *it->table);
    }
    project.setModified(wasModified);
}

}  // namespace

Expected<QStringList> runPipeline(Project& project, const QJsonObject& pipeline, const Progress& progress) {
    const QJsonArray steps = pipeline.value(QStringLiteral("steps")).toArray();
    if (steps.isEmpty()) return makeError(QStringLiteral("pipeline has no \"steps\" array"));

    const bool wasModified = project.isModified();
    std::vector<Snapshot> snapshots;
    QStringList written;
    QJsonArray record;
    const QString started = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    for (int i = 0; i < steps.size(); ++i) {
        const QJsonObject step = steps[i].toObject();
        auto fail = [&](const QString& message) -> Expected<QStringList> {
            restore(project, snapshots, wasModified);
            return makeError(QStringLiteral("pipeline step %1: %2").arg(i + 1).arg(message));
        };
        const RunRequest request = pipelineStepRequest(step);
        if (request.processorId.isEmpty()) return fail(QStringLiteral("missing \"processor\""));

        auto processor = ProcessorRegistry::instance().find(request.processorId);
        if (!processor) return fail(QStringLiteral("unknown processor '%1'").arg(request.processorId));
        for (const auto& o : processor->outputs()) {
            Snapshot s;
            s.path = outputPathFor(request.output, o.suffix);
            if (o.annotations) {
                s.annotations = true;
                if (const Recording* rec = project.recording(ItemPath::parse(s.path).recording))
                    s.recording = std::make_pair(rec->annotations, rec->metadata);
                snapshots.push_back(std::move(s));
                continue;
            }
            if (const Stream* st = project.stream(s.path)) s.stream = *st;
            if (const Table* t = project.table(s.path)) s.table = *t;
            snapshots.push_back(std::move(s));
        }
        const double begin = double(i) / steps.size(), end = double(i + 1) / steps.size();
        Progress sub = progress.sub(begin, end);
        auto outcome = runProcessor(project, *processor, request, sub);
        if (!outcome) return fail(outcome.message());
        written << outcome->written;
        QJsonObject done = step;
        done[QStringLiteral("params")] = outcome->parameters;
        done[QStringLiteral("written")] = QJsonArray::fromStringList(outcome->written);
        if (!outcome->annotated.isEmpty())
            done[QStringLiteral("annotations")] = QJsonArray::fromStringList(outcome->annotated);
        record.append(done);
    }
    QJsonObject entry{{QStringLiteral("name"), pipeline.value(QStringLiteral("name")).toString()},
                      {QStringLiteral("started"), started},
                      {QStringLiteral("finished"), QDateTime::currentDateTimeUtc().toString(Qt::ISODate)},
                      {QStringLiteral("app_version"), appVersion()},
                      {QStringLiteral("steps"), record}};
    project.pipelineHistory().append(entry);
    project.setModified();
    return written;
}

Expected<QJsonObject> readPipelineFile(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return makeError(QStringLiteral("%1: %2").arg(path, file.errorString()));
    QJsonParseError error;
    const QByteArray bytes = file.readAll();
    const QJsonDocument doc = QJsonDocument::fromJson(bytes, &error);
    if (error.error != QJsonParseError::NoError) {
        const QByteArray head = bytes.left(error.offset);
        const int line = int(head.count('\n')) + 1;
        const int column = int(error.offset - (head.lastIndexOf('\n') + 1)) + 1;
        return makeError(QStringLiteral("%1:%2:%3: %4").arg(path).arg(line).arg(column).arg(error.errorString()));
    }
    if (!doc.isObject()) return makeError(QStringLiteral("%1: a pipeline is a JSON object with \"steps\"").arg(path));
    return doc.object();
}

}  // namespace athlos
