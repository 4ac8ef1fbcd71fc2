#pragma once
// Beacon tables (kind "beacons": id text, x, y, z in m) ↔ BeaconLayout, and matching the beacon ids
// of a TDoA stream against a table.
//
// Reference node rule: a row whose id is "ref" or "reference" (case-insensitive) is the reference
// node, not a beacon; otherwise the table attribute "reference_node" = [x, y, z] (m); otherwise the
// origin of the LPS frame (thesis §3.1.2: r = [0 0 0]ᵀ). Tables written by this family keep the
// rule: lps-align writes a "ref" row when the reference node leaves the origin.
//
// Id matching (stream id → table row): the exact id text first; then equal numeric values ("01" and
// "1"); then the trailing number of the table id when unique ("B07" ← 7). Unknown ids are an error.
#include "core/model/Table.h"
#include "core/util/Expected.h"
#include "plugins/lps/Tdoa.h"

namespace athlos::lps {

// The beacons of a table; errors name the table path and the offending row or column.
// `minimum` beacons are required for `use` (TDoA fixes need 4; ranges 3).
Expected<BeaconLayout> layoutFromTable(const Table& table, const QString& path, int minimum = 4,
                                       const QString& use = QStringLiteral("TDoA positioning"));

// A "beacons" table (id, x, y, z in m). Writes a "ref" row when the reference node is not the origin.
Table tableFromLayout(const BeaconLayout& layout, const QString& name = QStringLiteral("beacons"));

// Index into layout.ids for a stream's id text, or -1.
int matchBeaconId(const BeaconLayout& layout, const QString& id);

bool isReferenceId(const QString& id);

}  // namespace athlos::lps
