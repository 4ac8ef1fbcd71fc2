#include "core/processing/PipelineProvenance.h"

#include "core/processing/ProcessorRegistry.h"
#include "core/processing/ProcessorRunner.h"

#include <QJsonArray>
#include <QJsonDocument>

namespace athlos {
namespace {

// Parameters as the provenance JSON holds them after a save and a reload: a fresh validation
// yields doubles where the reloaded JSON has integers, so both go through the same text form.
QByteArray canonical(const QJsonObject& parameters) {
    const QByteArray text = QJsonDocument(parameters).toJson(QJsonDocument::Compact);
    return QJsonDocument::fromJson(text).toJson(QJsonDocument::Compact);
}

// Why the stored provenance does not match the step, or an empty string when it does.
QString mismatch(const Project& project, const Provenance& stored, const Processor& processor,
                 const QByteArray& parameters, const std::vector<ProvenanceInput>& inputs) {
    if (stored.processorId != processor.id())
        return QStringLiteral("made by '%1', not '%2'").arg(stored.processorId, processor.id());
    if (stored.processorVersion != processor.version())
        return QStringLiteral("made by version %1, now %2").arg(stored.processorVersion, processor.version());
    if (canonical(stored.parameters) != parameters) return QStringLiteral("made with other parameters");
    if (stored.inputs.size() < inputs.size()) return QStringLiteral("made from other inputs");
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        if (stored.inputs[i].name != inputs[i].name) return QStringLiteral("made from other inputs");
        if (stored.inputs[i].hash != inputs[i].hash)
            return QStringLiteral("input '%1' changed since").arg(inputs[i].name);
    }
    // Streams and tables the run read besides its declared inputs (RunContext::recordRead): compared as
    // they are now.
    for (std::size_t i = inputs.size(); i < stored.inputs.size(); ++i) {
        const QString& name = stored.inputs[i].name;
        const Stream* s = project.stream(name);
        const Table* t = s ? nullptr : project.table(name);
        if (!s && !t) return QStringLiteral("made from '%1', which is gone").arg(name);
        if ((s ? s->info().contentHash : tableHash(*t)) != stored.inputs[i].hash)
            return QStringLiteral("input '%1' changed since").arg(name);
    }
    return {};
}

}  // namespace

Expected<PipelineCheck> checkPipelineDone(const Project& project, const QJsonObject& pipeline) {
    const QJsonArray steps = pipeline.value(QStringLiteral("steps")).toArray();
    if (steps.isEmpty()) return makeError(QStringLiteral("pipeline has no \"steps\" array"));
    auto notDone = [](int step, const QString& why) {
        return PipelineCheck{false, QStringLiteral("step %1: %2").arg(step + 1).arg(why)};
    };
    for (int i = 0; i < steps.size(); ++i) {
        const RunRequest request = pipelineStepRequest(steps[i].toObject());
        auto processor = ProcessorRegistry::instance().find(request.processorId);
        if (!processor)
            return makeError(
                QStringLiteral("pipeline step %1: unknown processor '%2'").arg(i + 1).arg(request.processorId));
        auto params = validateParameters(processor->parameters(), request.parameters);
        if (!params)
            return makeError(
                QStringLiteral("pipeline step %1: %2: %3").arg(i + 1).arg(processor->id(), params.message()));
        const QByteArray parameters = canonical(QJsonObject::fromVariantMap(*params));

        const auto specs = processor->inputs();
        std::vector<ProvenanceInput> inputs;
        for (int k = 0; k < request.inputs.size(); ++k) {
            const QString& path = request.inputs[k];
            if (k < specs.size() && specs[k].table) {
                const Table* t = project.table(path);
                if (!t) return notDone(i, QStringLiteral("input '%1' is missing").arg(path));
                inputs.push_back({path, tableHash(*t)});
            } else {
                const Stream* s = project.stream(path);
                if (!s) return notDone(i, QStringLiteral("input '%1' is missing").arg(path));
                inputs.push_back({path, s->info().contentHash});
            }
        }

        // A processor may leave a declared secondary output out (nothing to report); every output
        // present must be current, and at least one must be present.
        int present = 0;
        for (const auto& o : processor->outputs()) {
            const QString path = outputPathFor(request.output, o.suffix);
            Provenance stored;
            if (o.annotations) {
                const Recording* rec = project.recording(ItemPath::parse(path).recording);
                const QJsonObject sources =
                    rec ? rec->metadata.value(QStringLiteral("annotation_provenance")).toObject() : QJsonObject();
                if (!sources.contains(path)) continue;
                stored = Provenance::fromJson(sources.value(path).toObject());
            } else if (const Stream* s = project.stream(path)) {
                stored = s->info().provenance;
            } else if (const Table* t = project.table(path)) {
                stored = t->provenance;
            } else {
                continue;
            }
            ++present;
            if (const QString why = mismatch(project, stored, *processor, parameters, inputs); !why.isEmpty())
                return notDone(i, QStringLiteral("'%1' was %2").arg(path, why));
        }
        if (present == 0) return notDone(i, QStringLiteral("'%1' is not computed yet").arg(request.output));
    }
    return PipelineCheck{true, {}};
}

}  // namespace athlos
