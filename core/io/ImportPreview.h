#pragma once
// What an import would do, before it does it: the detected format and kind, the first rows as text,
// each column with the channel and unit it would become (from header units such as "acc_x [g]",
// common export spellings such as "GyroX" or "Time (ms)", and the known formats), and a dry run
// that parses the whole file without touching a project. The import wizard is built on it.
#include "core/io/Importer.h"

#include <QString>
#include <QStringList>
#include <vector>

namespace athlos {

struct PreviewColumn {
    QString header;      // the header cell as written: "Gyro X [deg/s]"
    QString source;      // its name without unit: "Gyro X"
    QString unit;        // unit of the values in the file (header or format), may be empty
    QString channel;     // the channel it becomes: "gyr_x"; "t" for time; empty if not recognised
    QString storedUnit;  // SI unit it is stored in ("rad/s"), empty if unknown
    bool time = false;
};

struct ImportPreview {
    QString file;
    QString format;            // "csv", "gaitmap", "broad", "nmea"
    QString kind;              // detected kind, empty if the columns do not tell
    bool mappable = false;     // csv: ImportOptions::columns can rename, re-unit and skip the columns
    long long headerLine = 0;  // csv: line of the header row
    std::vector<PreviewColumn> columns;
    std::vector<QStringList> rows;  // the first rows, one text cell per column
    QStringList items;              // formats with fixed streams: the items the import makes ("left-foot", ...)
};

// Reads the head of file (csv) or imports it in memory (other formats) to describe it.
// format: "auto" or a format name; kind: forced kind or empty to detect.
Expected<ImportPreview> previewFile(const QString& file, const QString& format = QStringLiteral("auto"),
                                    int maxRows = 20, const QString& kind = {});

// The channel a column name stands for in common exports ("AccX", "acc-y", "Gyroscope Z",
// "timestamp", "Latitude"), or empty. Interchange names map to themselves.
QString detectChannel(const QString& name);

// The unit a channel is stored in when its values are in unit (the kind's SI unit, or SI for a
// channel the kind has no rule for; empty unit: as the kind says, or none). Error for an unknown unit
// or one of another quantity.
Expected<QString> storedUnitFor(const QString& kind, const QString& channel, const QString& unit, bool time = false);

// Options that import the file as the preview describes it: format, kind, and a column mapping for
// every recognised column whose name or unit differs from the interchange convention.
ImportOptions suggestedOptions(const ImportPreview& preview);

// A dry run: the full parse of importFile() without applying anything.
struct ImportCheck {
    QString file;
    QStringList errors;  // "imu.csv:58:3 (column 'acc_y'): 'abc' is not a number"
    QStringList warnings;
    QStringList items;  // "rec/stream" paths the import would create
    long long samples = 0;
    bool cancelled = false;
};
ImportCheck checkImport(const QString& file, const ImportOptions& options, const Progress& progress = {});

}  // namespace athlos
