#pragma once
// Where a stream or table came from: a processor run (id, version, parameters, inputs with their
// content hashes) or an import (importer id, source file). Stored as JSON next to the data.
#include <QDateTime>
#include <QJsonObject>
#include <QString>
#include <vector>

namespace athlos {

struct ProvenanceInput {
    QString name;     // "rec/stream"
    QByteArray hash;  // content hash at run time
};

struct Provenance {
    QString processorId;  // processor id, or "import:<format>"
    QString processorVersion;
    QJsonObject parameters;  // validated parameters, including defaults
    std::vector<ProvenanceInput> inputs;
    QString sourceFile;  // for imports
    QString appVersion;
    QDateTime time;  // UTC

    bool isEmpty() const { return processorId.isEmpty(); }
    QJsonObject toJson() const;
    static Provenance fromJson(const QJsonObject& json);
};

}  // namespace athlos
