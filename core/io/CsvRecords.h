#pragma once
// CSV import, part 2 of 3: record parsing. Turns the data records after a planned header
// (CsvColumns.h) into samples (time series) or table columns; every cell error names the file,
// line and column.
#include "core/io/CsvColumns.h"
#include "core/io/CsvReader.h"
#include "core/model/StreamData.h"
#include "core/model/Table.h"
#include "core/util/Progress.h"

#include <string>
#include <vector>

namespace athlos::csv {

// What the time column said about absolute time.
// The labels of the label column (Role::Label), one per record ("" = none), in record order.
using ParsedLabels = std::vector<std::string>;

struct ParsedTime {
    TimeBase base;             // t = 0 is the first record's time for absolute formats
    bool missingZone = false;  // ISO date-times without Z or an offset (taken as UTC)
};

// Parses the data records of a time series into data (t and the non-skipped columns in order); the
// line of each record goes to lines; Id columns store an index into ids (text as in the file).
// mapped is the file the reader reads (for progress and reservation).
Status parseStreamRecords(CsvReader& reader, const MappedFile& mapped, const QString& file, const Header& header,
                          const Progress& progress, StreamData& data, std::vector<long long>& lines,
                          std::vector<std::string>& ids, ParsedTime& time, ParsedLabels* labels = nullptr);

// Parses the data records of a table into table's columns (one per non-skipped file column).
Status parseTableRecords(CsvReader& reader, const QString& file, const Header& header, Table& table);

}  // namespace athlos::csv
