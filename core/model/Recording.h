#pragma once
// One capture (a race, a training, a trial): metadata plus named streams and tables.
#include "core/model/Annotation.h"
#include "core/model/Stream.h"
#include "core/model/Table.h"

#include <QJsonObject>
#include <QString>
#include <map>

namespace athlos {

struct Recording {
    QString name;
    QJsonObject metadata;  // sport, athlete(s), date, device, notes
    std::map<QString, Stream> streams;
    std::map<QString, Table> tables;
    Annotations annotations;

    bool contains(const QString& item) const { return streams.count(item) || tables.count(item); }
};

}  // namespace athlos
