#pragma once
// CSV importer for the interchange convention (ARCHITECTURE.md, "CSV interchange").
//
// - Header row of column names; a cell may carry a unit, "gyr_x [deg/s]" or "acc_x(g)". Columns the
//   kind knows (StreamKinds) are converted to its SI unit; a unit of another quantity is an error.
//   Without a unit the kind's unit is assumed. Columns the kind does not know keep their unit.
// - `t` in seconds (another time unit in the header is converted). Delimiter ',', ';' or tab,
//   detected from the header.
// - Empty cells: NaN in data columns, an error in `t`. "nan" is NaN too; infinities are errors.
// - The kind comes from ImportOptions::kind, or, if empty, from the columns (acc_/gyr_/mag_ → imu,
//   beacon+dt → lps-tdoa, id+x+y without t → beacons, qw.. → orientation, lat+lon → gnss,
//   x+y → lps-position).
// - lps-tdoa: the long interchange form t,beacon,dt (t repeats, one row per instant and beacon)
//   becomes the wide stream of core/io/TdoaLayout.h (dt_<id> per beacon, ids as text in
//   attributes["beacon_ids"]); time repair acts on the rows, where equal times are in order.
// - beacons (id,x,y,z) becomes a Table; columns id, name and label are text.
//
// - ImportOptions::columns renames, re-units or skips source columns before all of the above; a
//   mapped unit of a column the kind has no rule for is converted to SI (deg → rad, g → m/s^2).
//   timeColumn/timeUnit name the time column when it is not 't' in seconds.
//
// The parts: CsvColumns.h (column mapping, kind inference), CsvRecords.h (record parsing),
// TimeOrder.h (time-order repair).
//
// read() names each item by its default name only ("imu"); importFile() puts it under the target.
#include "core/io/CsvColumns.h"  // siUnitOf, inferCsvKind, mappedColumnNames
#include "core/io/Importer.h"
#include "core/io/TimeOrder.h"  // repairTimeOrder

namespace athlos {

class CsvImporter final : public Importer {
public:
    QString format() const override { return QStringLiteral("csv"); }
    QString description() const override;
    QStringList extensions() const override { return {"csv", "txt", "tsv"}; }
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
    bool mapsColumns() const override { return true; }
};

}  // namespace athlos
