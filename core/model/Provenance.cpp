#include "core/model/Provenance.h"

#include <QJsonArray>

namespace athlos {

QJsonObject Provenance::toJson() const {
    QJsonObject json;
    if (isEmpty()) return json;
    json[QStringLiteral("processor")] = processorId;
    json[QStringLiteral("processor_version")] = processorVersion;
    json[QStringLiteral("parameters")] = parameters;
    QJsonArray in;
    for (const auto& input : inputs)
        in.append(QJsonObject{{QStringLiteral("name"), input.name},
                              {QStringLiteral("hash"), QString::fromLatin1(input.hash)}});
    json[QStringLiteral("inputs")] = in;
    if (!sourceFile.isEmpty()) json[QStringLiteral("source_file")] = sourceFile;
    json[QStringLiteral("app_version")] = appVersion;
    json[QStringLiteral("time")] = time.toUTC().toString(Qt::ISODateWithMs);
    return json;
}

Provenance Provenance::fromJson(const QJsonObject& json) {
    Provenance p;
    p.processorId = json.value(QStringLiteral("processor")).toString();
    p.processorVersion = json.value(QStringLiteral("processor_version")).toString();
    p.parameters = json.value(QStringLiteral("parameters")).toObject();
    for (const auto& value : json.value(QStringLiteral("inputs")).toArray()) {
        const auto o = value.toObject();
        p.inputs.push_back(
            {o.value(QStringLiteral("name")).toString(), o.value(QStringLiteral("hash")).toString().toLatin1()});
    }
    p.sourceFile = json.value(QStringLiteral("source_file")).toString();
    p.appVersion = json.value(QStringLiteral("app_version")).toString();
    p.time = QDateTime::fromString(json.value(QStringLiteral("time")).toString(), Qt::ISODateWithMs);
    return p;
}

}  // namespace athlos
