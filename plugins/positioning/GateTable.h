#pragma once
// The gates table of the anchor smoother: one row per gate in course order, columns id (text),
// east, north, up (m, the gates' earth frame — surveyed, from GNSS, or averaged over runs).
#include "core/model/Table.h"
#include "core/util/Expected.h"
#include "plugins/positioning/GateRunSimulator.h"

#include <vector>

namespace athlos::positioning {

// Errors name the table (`path`) and the column or row: missing/text columns, non-finite values,
// duplicate ids, fewer than two gates.
Expected<std::vector<Gate>> gatesFromTable(const Table& table, const QString& path);

// A gates table (kind "gates") from gate positions.
Table gatesTable(const std::vector<Gate>& gates);

}  // namespace athlos::positioning
