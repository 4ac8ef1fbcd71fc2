#include "core/model/SummaryTable.h"

#include <limits>

namespace athlos {

SummaryTable::SummaryTable() {
    merged_.name = QStringLiteral("summary");
    merged_.kind = QStringLiteral("summary");
    merged_.columns.push_back({QStringLiteral("project"), {}, true, {}, {}});
    merged_.columns.push_back({QStringLiteral("recording"), {}, true, {}, {}});
}

Status SummaryTable::add(const QString& project, const QString& recording, const Table& table) {
    const long long rows = table.rows();
    for (const TableColumn& col : table.columns) {
        if (col.size() != rows)
            return makeError(QStringLiteral("%1: %2/%3: column '%4' has %5 rows, the first column %6")
                                 .arg(project, recording, table.name, col.name)
                                 .arg(col.size())
                                 .arg(rows));
        const TableColumn* existing = merged_.column(col.name);
        if (existing && (existing->isText != col.isText || existing->unit != col.unit))
            return makeError(
                QStringLiteral("%1: %2/%3: column '%4' is %5 here but %6 in an earlier table")
                    .arg(project, recording, table.name, col.name,
                         col.isText ? QStringLiteral("text") : QStringLiteral("'%1'").arg(col.unit),
                         existing->isText ? QStringLiteral("text") : QStringLiteral("'%1'").arg(existing->unit)));
    }
    const long long before = merged_.rows();
    for (const TableColumn& col : table.columns) {
        if (merged_.column(col.name)) continue;
        TableColumn fresh{col.name, col.unit, col.isText, {}, {}};
        if (col.isText)
            for (long long r = 0; r < before; ++r) fresh.texts.append(QString());
        else
            fresh.numbers.assign(std::size_t(before), std::numeric_limits<double>::quiet_NaN());
        merged_.columns.push_back(std::move(fresh));
    }
    for (std::size_t c = 0; c < merged_.columns.size(); ++c) {
        TableColumn& out = merged_.columns[c];
        const TableColumn* in = c == 0 ? nullptr : c == 1 ? nullptr : table.column(out.name);
        for (long long r = 0; r < rows; ++r) {
            if (c == 0) {
                out.texts.append(project);
            } else if (c == 1) {
                out.texts.append(recording);
            } else if (out.isText) {
                out.texts.append(in ? in->texts.at(qsizetype(r)) : QString());
            } else {
                out.numbers.push_back(in ? in->numbers[std::size_t(r)] : std::numeric_limits<double>::quiet_NaN());
            }
        }
    }
    ++sources_;
    return {};
}

}  // namespace athlos
