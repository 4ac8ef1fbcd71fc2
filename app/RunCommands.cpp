// athlos processors | run | pipeline
#include "CommandParser.h"
#include "Commands.h"
#include "TerminalProgress.h"

#include "core/model/Project.h"
#include "core/processing/ProcessorRegistry.h"
#include "core/processing/ProcessorRunner.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <cstdio>

namespace athlos::cli {
namespace {

int exitFor(const Error& error) { return error.message == u"cancelled" ? Cancelled : Failed; }

void printProcessor(const Processor& p) {
    std::printf("%s  (version %s)\n  %s\n", qUtf8Printable(p.id()), qUtf8Printable(p.version()),
                qUtf8Printable(p.description()));
    for (const auto& in : p.inputs())
        std::printf("  input  %-12s %s%s%s\n", qUtf8Printable(in.name), in.table ? "table " : "",
                    qUtf8Printable(in.kinds.isEmpty() ? QStringLiteral("any") : in.kinds.join(QLatin1Char('|'))),
                    in.optional ? " (optional)" : "");
    for (const auto& s : p.parameters()) {
        QString detail = s.typeName();
        if (s.type == ParameterSpec::Type::Choice) detail = s.choices.join(QLatin1Char('|'));
        if (s.defaultValue.isValid())
            detail += QStringLiteral(", default ") + s.defaultValue.toString();
        else if (!s.optional)
            detail += QStringLiteral(", required");
        if (!s.unit.isEmpty()) detail += QStringLiteral(", ") + s.unit;
        std::printf("  --param %-14s %s\n      %s\n", qUtf8Printable(s.name + QStringLiteral("=…")),
                    qUtf8Printable(detail), qUtf8Printable(s.help));
    }
}

// An output a processor stored although a plausibility check failed (accepted with a parameter such
// as imu-calibration's accept_implausible) carries the finding in its attribute "implausible".
void warnImplausible(const Project& project, const QStringList& written) {
    for (const auto& path : written) {
        QJsonObject attributes;
        if (const Stream* s = project.stream(path)) attributes = s->info().attributes;
        if (const Table* t = project.table(path)) attributes = t->attributes;
        const QString finding = attributes.value(QStringLiteral("implausible")).toString();
        if (!finding.isEmpty())
            std::fprintf(stderr, "athlos: warning: %s is implausible: %s\n", qUtf8Printable(path),
                         qUtf8Printable(finding));
    }
}
}  // namespace

int cmdProcessors(const QStringList& args) {
    CommandParser p(QStringLiteral("processors [--json]"),
                    QStringLiteral("List processors with their parameter schemas."));
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable output.")});
    if (auto code = p.parse(args, 0, 0)) return *code;
    auto& registry = ProcessorRegistry::instance();
    for (const auto& e : registry.loadErrors())
        std::fprintf(stderr, "athlos: warning: plugin not loaded: %s\n", qUtf8Printable(e));
    if (p.parser().isSet(QStringLiteral("json"))) {
        QJsonArray list;
        for (const auto& id : registry.ids()) list.append(registry.find(id)->describe());
        std::fputs(QJsonDocument(list).toJson(QJsonDocument::Indented).constData(), stdout);
        return Ok;
    }
    for (const auto& id : registry.ids()) {
        printProcessor(*registry.find(id));
        std::printf("\n");
    }
    return Ok;
}

int cmdRun(const QStringList& args) {
    CommandParser p(
        QStringLiteral("run <project> <processor> --input <rec/stream>[,…] --output <rec/stream> [--param k=v …]"),
        QStringLiteral("Run a processor and store its result with provenance. The project is saved only "
                       "when the run succeeds; Ctrl-C cancels and leaves it untouched."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addPositional(QStringLiteral("processor"), QStringLiteral("Processor id (see athlos processors)."));
    p.addOption({QStringLiteral("input"),
                 QStringLiteral("Input streams/tables, comma-separated, in the processor's order."),
                 QStringLiteral("items")});
    p.addOption(
        {QStringLiteral("output"), QStringLiteral("Name of the result: <recording>/<name>."), QStringLiteral("item")});
    p.addOption({QStringLiteral("param"), QStringLiteral("Parameter, repeatable."), QStringLiteral("k=v")});
    if (auto code = p.parse(args, 2, 2)) return *code;

    RunRequest request;
    request.processorId = p.positional()[1];
    request.inputs = p.parser().value(QStringLiteral("input")).split(QLatin1Char(','), Qt::SkipEmptyParts);
    request.output = p.parser().value(QStringLiteral("output"));
    if (request.output.isEmpty()) return fail(QStringLiteral("run needs --output <recording>/<name>"), Usage);
    for (const QString& kv : p.parser().values(QStringLiteral("param"))) {
        const int eq = kv.indexOf(QLatin1Char('='));
        if (eq <= 0) return fail(QStringLiteral("--param '%1': expected name=value").arg(kv), Usage);
        request.parameters.insert(kv.left(eq).trimmed(), kv.mid(eq + 1).trimmed());
    }
    auto processor = ProcessorRegistry::instance().find(request.processorId);
    if (!processor)
        return fail(QStringLiteral("unknown processor '%1' (available: %2)")
                        .arg(request.processorId, ProcessorRegistry::instance().ids().join(QStringLiteral(", "))));

    auto project = openForChange(p.positional()[0]);
    if (!project) return fail(project.message());
    TerminalProgress bar(request.processorId);
    auto outcome = runProcessor(**project, *processor, request, bar.progress().sub(0.0, 0.9));
    if (!outcome) return fail(outcome.message(), exitFor(outcome.error()));
    if (Status s = (*project)->save(bar.progress().sub(0.9, 1.0)); !s) return fail(s.message(), exitFor(s.error()));
    bar.finish();
    for (const auto& w : outcome->written) std::printf("wrote %s\n", qUtf8Printable(w));
    for (const auto& a : outcome->annotated) std::printf("annotated %s\n", qUtf8Printable(a));
    warnImplausible(**project, outcome->written);
    return Ok;
}

int cmdPipeline(const QStringList& args) {
    CommandParser p(
        QStringLiteral("pipeline <project> <pipeline.json>"),
        QStringLiteral("Run the steps of a pipeline file in order and record the pipeline in the project. "
                       "Format: {\"name\": …, \"steps\": [{\"processor\": id, \"input\": \"rec/a\" or [..], "
                       "\"output\": \"rec/b\", \"params\": {…}}]}. If any step fails nothing is saved."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addPositional(QStringLiteral("pipeline"), QStringLiteral("The pipeline JSON file."));
    if (auto code = p.parse(args, 2, 2)) return *code;
    auto pipeline = readPipelineFile(p.positional()[1]);
    if (!pipeline) return fail(pipeline.message());
    auto project = openForChange(p.positional()[0]);
    if (!project) return fail(project.message());
    TerminalProgress bar(QStringLiteral("pipeline"));
    auto written = runPipeline(**project, *pipeline, bar.progress().sub(0.0, 0.9));
    if (!written) return fail(written.message(), exitFor(written.error()));
    if (Status s = (*project)->save(bar.progress().sub(0.9, 1.0)); !s) return fail(s.message(), exitFor(s.error()));
    bar.finish();
    for (const auto& w : *written) std::printf("wrote %s\n", qUtf8Printable(w));
    return Ok;
}

}  // namespace athlos::cli
