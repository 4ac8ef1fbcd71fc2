#pragma once
// CSV import, part 1 of 3: column mapping and kind inference. The header row is planned into one
// ColumnPlan per file column (role, stored name and unit, conversion to SI) after ImportOptions'
// column mapping; the kind is inferred from the (mapped) column names when none is given.
// Parts 2 and 3: CsvRecords.h (record parsing), TimeOrder.h (time-order repair); CsvImporter.cpp
// puts them together.
#include "core/io/CsvReader.h"
#include "core/io/Importer.h"
#include "core/io/TimeFormats.h"
#include "core/model/StreamKinds.h"

#include <QString>
#include <QStringList>
#include <string_view>
#include <vector>

namespace athlos {

// The SI unit a mapped column of no kind rule is stored in ("deg" → "rad"; magnetic fields in uT as
// everywhere), or empty for an unknown unit.
QString siUnitOf(const QString& unit);
// The kind the column names suggest (see CsvImporter.h), or empty.
QString inferCsvKind(const QStringList& names);
// Names of the header cells after options' mapping (skipped columns left out, the time column as 't').
QStringList mappedColumnNames(const QStringList& headerCells, const ImportOptions& options);

namespace csv {

// "file:line:column (column 'name')", the prefix of every cell message.
QString where(const QString& file, long long line, int column, const QString& name);
// The shortest text that reads back as v.
QString shortest(double v);
// A cell's text in quotes for messages, cut after 40 characters.
QString quoted(std::string_view text);

enum class Role { Time, Number, Id, Text, Skip, Date, Label };  // Date: the date of clock times; Label: --labels

// A column stored in the stream (not the time, a skipped column or the date of clock times).
inline bool isDataRole(Role role) {
    return role != Role::Time && role != Role::Skip && role != Role::Date && role != Role::Label;
}

struct ColumnPlan {
    QString name;
    QString source;      // name in the header (before mapping), for messages
    QString unit;        // unit stored with the column
    QString sourceUnit;  // unit in the header, if one was given
    Role role = Role::Number;
    bool convert = false;  // scale/offset differ from identity (kept apart so -0.0 survives)
    double scale = 1.0;
    double offset = 0.0;
};

struct Header {
    std::vector<ColumnPlan> columns;
    long long line = 0;
    int timeColumn = -1;
    TimeFormat timeFormat;  // of the time column
    int dateColumn = -1;    // clock times: the column with their date, if any
    bool haveDate = false;  // clock times: ImportOptions::date given
    qint64 dateDays = 0;    // its days since 1970-01-01
    int labelColumn = -1;   // the column of per-sample labels (ImportOptions::labelColumn), if any
};

// An index column without a name: an empty header cell, or pandas' "Unnamed: 0".
bool isUnnamedColumn(const QString& name);
// The interchange name of a known channel written in another case or spelling ("Lat", "LATITUDE",
// "Longitude", "ACC_X" → lat, lat, lon, acc_x), or empty. The time column is never guessed.
QString knownChannelName(const QString& name);
// A column the kind knows (a unit rule or a required column; id, name, label of tables).
bool isKindColumn(const StreamKind* kind, const QString& name, bool table);

// The known kind of that name, or of that default stream name ("lps", "tdoa"); nullptr if unknown.
const StreamKind* lookupKind(const QString& kind);

// Reads the header row and plans every column. table: a table kind (no time column).
Expected<Header> planHeader(CsvReader& reader, const QString& file, const ImportOptions& options,
                            const QString& kindName, const StreamKind* kind, bool table);

}  // namespace csv
}  // namespace athlos
