#include "core/processing/Processor.h"

#include <QJsonArray>

namespace athlos {

Error InputSamples::error(const QString& message) const {
    return makeError(QStringLiteral("input '%1' (%2): %3").arg(path, role, message));
}

Expected<double> InputSamples::samplingInterval() const {
    if (data->rows() < 2) return error(QStringLiteral("%1 sample(s); at least 2 are needed").arg(data->rows()));
    const double ts = data->medianInterval();
    if (!(ts > 0.0)) return error(QStringLiteral("no positive sampling interval"));
    return ts;
}

RunContext::RunContext(const Project& project, QList<InputSpec> inputSpecs, std::vector<const Stream*> streams,
                       std::vector<const Table*> tables, std::vector<QString> inputPaths, QVariantMap parameters,
                       QString outputPath, Progress progress)
    : project_(project),
      inputSpecs_(std::move(inputSpecs)),
      streams_(std::move(streams)),
      tables_(std::move(tables)),
      inputPaths_(std::move(inputPaths)),
      parameters_(std::move(parameters)),
      outputPath_(std::move(outputPath)),
      progress_(std::move(progress)) {}

const Stream* RunContext::stream(int index) const {
    return index >= 0 && index < int(streams_.size()) ? streams_[std::size_t(index)] : nullptr;
}

const Table* RunContext::table(int index) const {
    return index >= 0 && index < int(tables_.size()) ? tables_[std::size_t(index)] : nullptr;
}

QString RunContext::inputRole(int index) const {
    return index >= 0 && index < inputSpecs_.size() ? inputSpecs_[index].name : QStringLiteral("#%1").arg(index + 1);
}

Error RunContext::inputError(int index, const QString& message) const {
    const QString path = index >= 0 && index < inputCount() ? inputPath(index) : QString();
    if (path.isEmpty()) return makeError(QStringLiteral("input '%1': %2").arg(inputRole(index), message));
    return makeError(QStringLiteral("input '%1' (%2): %3").arg(path, inputRole(index), message));
}

Expected<InputSamples> RunContext::samples(int index) const {
    const Stream* s = stream(index);
    if (!s) return makeError(QStringLiteral("input '%1' was not given").arg(inputRole(index)));
    auto data = s->data();
    if (!data) return inputError(index, QStringLiteral("cannot read its samples: %1").arg(data.message()));
    return InputSamples{s, std::move(data).value(), inputPath(index), inputRole(index)};
}

// Tables may be recorded as well as streams (position-filter's noise profile, with tableHash):
// checkPipelineDone looks a recorded path up as a stream, then as a table.
void RunContext::recordRead(const QString& path, const QByteArray& hash) const {
    for (const QString& declared : inputPaths_)
        if (declared == path) return;
    for (const ProvenanceInput& read : extraReads_)
        if (read.name == path) return;
    extraReads_.push_back({path, hash});
}

Expected<const Table*> RunContext::requireTable(int index) const {
    const Table* t = table(index);
    if (!t) return makeError(QStringLiteral("input '%1' was not given").arg(inputRole(index)));
    return t;
}

QJsonObject Processor::describe() const {
    QJsonArray params;
    for (const auto& p : parameters()) params.append(p.toJson());
    QJsonArray in;
    for (const auto& i : inputs())
        in.append(QJsonObject{{QStringLiteral("name"), i.name},
                              {QStringLiteral("kinds"), QJsonArray::fromStringList(i.kinds)},
                              {QStringLiteral("table"), i.table},
                              {QStringLiteral("optional"), i.optional},
                              {QStringLiteral("help"), i.help}});
    QJsonArray out;
    for (const auto& o : outputs())
        out.append(QJsonObject{{QStringLiteral("kind"), o.kind},
                               {QStringLiteral("table"), o.table},
                               {QStringLiteral("suffix"), o.suffix},
                               {QStringLiteral("annotations"), o.annotations},
                               {QStringLiteral("help"), o.help}});
    return {{QStringLiteral("id"), id()},
            {QStringLiteral("name"), name()},
            {QStringLiteral("description"), description()},
            {QStringLiteral("version"), version()},
            {QStringLiteral("parameters"), params},
            {QStringLiteral("inputs"), in},
            {QStringLiteral("outputs"), out}};
}

}  // namespace athlos
