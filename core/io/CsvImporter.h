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
// read() names each item by its default name only ("imu"); importFile() puts it under the target.
#include "core/io/Importer.h"

namespace athlos {

class CsvImporter final : public Importer {
public:
    QString format() const override { return QStringLiteral("csv"); }
    QString description() const override;
    QStringList extensions() const override { return {"csv", "txt", "tsv"}; }
    bool canRead(const QString& file, const QByteArray& head) const override;
    Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                const Progress& progress) const override;
};

// The SI unit a mapped column of no kind rule is stored in ("deg" → "rad"; magnetic fields in uT as
// everywhere), or empty for an unknown unit.
QString siUnitOf(const QString& unit);
// The kind the column names suggest (see above), or empty.
QString inferCsvKind(const QStringList& names);
// Names of the header cells after options' mapping (skipped columns left out, the time column as 't').
QStringList mappedColumnNames(const QStringList& headerCells, const ImportOptions& options);

// Where the time stamps of parsed samples came from, for messages.
struct TimeOrigin {
    QString file;
    int column = 1;                 // 1-based column of t
    QString columnName = QStringLiteral("t");
    std::vector<long long> lines;   // line of each sample
};

// Makes times increasing according to mode (ImportOptions::timeRepair):
//   reject: error naming the first offending line and both times;
//   sort:   stable sort by time; exact duplicate samples are dropped with a warning, samples with
//           equal times but different values are an error (unless allowEqualTimes);
//   drop:   drops every sample whose time is not after the last kept one, with a warning.
// allowEqualTimes accepts equal consecutive times (long-format rows such as TDoA's).
// Warnings are appended to warnings.
Status repairTimeOrder(StreamData& data, TimeOrigin& origin, const QString& mode, bool allowEqualTimes,
                       QStringList& warnings);

}  // namespace athlos
