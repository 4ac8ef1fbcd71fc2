#pragma once
// Tables of one name from many projects and recordings stacked into one (`athlos batch --summary`):
// leading text columns project and recording, then the union of the tables' columns in the order they
// first appear; a column a table lacks is NaN (numbers) or empty (text) in its rows.
#include "core/model/Table.h"
#include "core/util/Expected.h"

#include <QString>

namespace athlos {

class SummaryTable {
public:
    SummaryTable();
    // Appends table's rows. Refuses a column whose type or unit differs from an earlier table's
    // column of that name (the error names the project, the recording and the column).
    Status add(const QString& project, const QString& recording, const Table& table);
    const Table& table() const { return merged_; }
    int sources() const { return sources_; }

private:
    Table merged_;
    int sources_ = 0;
};

}  // namespace athlos
