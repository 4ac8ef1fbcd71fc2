#include "core/processing/Processor.h"

#include <QJsonArray>

namespace athlos {

RunContext::RunContext(const Project& project, std::vector<const Stream*> streams, std::vector<const Table*> tables,
                       std::vector<QString> inputPaths, QVariantMap parameters, QString outputPath, Progress progress)
    : project_(project),
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
