#pragma once
// File importers. An import reads a file into new streams/tables in memory; applying it to the
// project is a separate step, so a failed import never changes the project.
#include "core/geometry/Geodesy.h"
#include "core/model/Annotation.h"
#include "core/model/Project.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QByteArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <map>
#include <memory>
#include <variant>
#include <vector>

namespace athlos {

// How one source column of a CSV file is imported (ImportOptions::columns).
struct ColumnMapping {
    QString source;     // the column's name in the header, without its unit ("Gyro X" of "Gyro X [deg/s]")
    QString channel;    // name to store it under; empty keeps the source name
    QString unit;       // unit of the values in the file; empty takes the header's (or the kind's) unit.
                        // Values are converted to the kind's SI unit, or to SI if the kind has no rule.
    bool skip = false;  // leave the column out (its cells are not parsed)
};

struct ImportOptions {
    QString format = QStringLiteral("auto");        // auto | csv | broad | gaitmap | ...
    QString kind;                                   // csv: imu | lps-position | lps-tdoa | gnss | beacons | ...
    QString target;                                 // "rec" (streams named after kind) or "rec/stream"
    QString timeRepair = QStringLiteral("reject");  // reject | sort | drop: non-increasing time stamps
    QString frame;                                  // overrides the kind's default frame
    bool overwrite = false;                         // replace existing items of the same name
    // csv: mapping of source columns; columns not listed keep their header name and unit.
    std::vector<ColumnMapping> columns;
    QString timeColumn;                     // csv: source column holding time ("" = the column 't')
    QString timeUnit;                       // csv: unit or time format of that column ("" = from its header,
                                            // else s); see core/io/TimeFormats.h (ms, unix_ns, iso, hh:mm:ss, excel…)
    bool dropUnmapped = false;              // csv: leave out columns neither mapped nor known to the kind
    QString labelColumn;                    // csv: per-sample labels → annotations (runs of equal labels)
    std::map<QString, QString> labelNames;  // csv: label value → name ("0" → "rest"); numbers match numerically
    std::optional<GeodeticOrigin> origin;   // the project's geodetic origin, if it has none yet (Geodesy.h)
    QString date;                           // YYYY-MM-DD: the date of clock times (hh:mm:ss) without one
    QString start;                          // ISO 8601: the UTC instant of t = 0 for relative times
    double rate = 0.0;                      // Hz: the rate of a time column that is a sample index (gaitmap);
                                            // 0 = found from the motion (GaitmapImporter.h)
    QJsonObject metadata;                   // merged into the target recording's metadata (athlete, ...)
};

struct ImportedItem {
    QString path;  // "rec/item"
    std::variant<Stream, Table> item;
};

struct ImportResult {
    std::vector<ImportedItem> items;
    QStringList warnings;                              // e.g. "repaired 3 non-increasing time stamps"
    std::map<QString, QJsonObject> recordingMetadata;  // recording → keys merged into its metadata
    // recording → annotations to add (importers use "" for the target recording). Applying replaces
    // the recording's annotations of the same source and annotator when overwriting.
    std::map<QString, Annotations> annotations;
    std::optional<GeodeticOrigin> origin;  // ImportOptions::origin, applied with the items
};

class Importer {
public:
    virtual ~Importer() = default;
    virtual QString format() const = 0;  // "csv"
    virtual QString description() const = 0;
    virtual QStringList extensions() const = 0;  // {"csv", "txt"}
    // Auto-detection from the file name and its first bytes.
    virtual bool canRead(const QString& file, const QByteArray& head) const = 0;
    virtual Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                        const Progress& progress) const = 0;
    // Takes ImportOptions::columns, timeColumn/timeUnit and dropUnmapped (CSV-based formats).
    virtual bool mapsColumns() const { return false; }
};

// All importers (csv, broad, gaitmap, and those later issues add).
const std::vector<std::unique_ptr<Importer>>& importers();
const Importer* findImporter(const QString& format);

// The importer for format ("auto" or empty: detected from the file name and first bytes).
Expected<const Importer*> chooseImporter(const QString& file, const QString& format);

// Reads file with the importer chosen by options.format (or detected). Names items from
// options.target and the kind. Errors name the file, line and column.
Expected<ImportResult> importFile(const QString& file, const ImportOptions& options, const Progress& progress = {});
// Puts the imported items into the project; refuses existing names unless options.overwrite.
// GNSS streams with lat/lon get x, y[, z] (m) in the project's ENU frame (core/geometry/Geodesy.h);
// the project's origin is set from result.origin or the first fix if it has none.
// All-or-nothing: checks every name before inserting any. recordingMetadata is merged into the
// recordings' metadata (created if needed).
Status applyImport(Project& project, ImportResult result, bool overwrite);

// "0=rest,1=run" (the --label-names option, the import wizard's field) → value → name.
// The error names the pair that is not VALUE=NAME.
Expected<std::map<QString, QString>> parseLabelNames(const QString& text);

}  // namespace athlos
