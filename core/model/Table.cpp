#include "core/model/Table.h"

namespace athlos {

int Table::columnIndex(const QString& name) const {
    for (std::size_t i = 0; i < columns.size(); ++i)
        if (columns[i].name == name) return static_cast<int>(i);
    return -1;
}

const TableColumn* Table::column(const QString& name) const {
    const int i = columnIndex(name);
    return i < 0 ? nullptr : &columns[static_cast<std::size_t>(i)];
}

}  // namespace athlos
