#pragma once
// A small table without a time axis (beacon positions, calibration parameters, reports).
// Columns are numeric (float64 with a unit) or text.
#include "core/model/Provenance.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <vector>

namespace athlos {

struct TableColumn {
    QString name;
    QString unit;  // empty for text columns
    bool isText = false;
    std::vector<double> numbers;  // when !isText
    QStringList texts;            // when isText

    long long size() const { return isText ? texts.size() : static_cast<long long>(numbers.size()); }
};

struct Table {
    QString name;
    QString kind;  // "beacons", "calibration", "report", ...
    QJsonObject attributes;
    Provenance provenance;
    std::vector<TableColumn> columns;

    long long rows() const { return columns.empty() ? 0 : columns.front().size(); }
    int columnIndex(const QString& column) const;  // -1 if absent
    const TableColumn* column(const QString& column) const;
};

}  // namespace athlos
