#pragma once
// File importers. An import reads a file into new streams/tables in memory; applying it to the
// project is a separate step, so a failed import never changes the project.
#include "core/model/Project.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <memory>
#include <variant>
#include <vector>

namespace athlos {

struct ImportOptions {
    QString format = QStringLiteral("auto");  // auto | csv | broad | gaitmap | ...
    QString kind;                            // csv: imu | lps-position | lps-tdoa | gnss | beacons | ...
    QString target;                          // "rec" (streams named after kind) or "rec/stream"
    QString timeRepair = QStringLiteral("reject");  // reject | sort | drop: non-increasing time stamps
    QString frame;                           // overrides the kind's default frame
    bool overwrite = false;                  // replace existing items of the same name
};

struct ImportedItem {
    QString path;                            // "rec/item"
    std::variant<Stream, Table> item;
};

struct ImportResult {
    std::vector<ImportedItem> items;
    QStringList warnings;                    // e.g. "repaired 3 non-increasing time stamps"
};

class Importer {
public:
    virtual ~Importer() = default;
    virtual QString format() const = 0;       // "csv"
    virtual QString description() const = 0;
    virtual QStringList extensions() const = 0;  // {"csv", "txt"}
    // Auto-detection from the file name and its first bytes.
    virtual bool canRead(const QString& file, const QByteArray& head) const = 0;
    virtual Expected<ImportResult> read(const QString& file, const ImportOptions& options,
                                        const Progress& progress) const = 0;
};

// All importers (csv, broad, gaitmap, and those later issues add).
const std::vector<std::unique_ptr<Importer>>& importers();
const Importer* findImporter(const QString& format);

// Reads file with the importer chosen by options.format (or detected). Names items from
// options.target and the kind. Errors name the file, line and column.
Expected<ImportResult> importFile(const QString& file, const ImportOptions& options, const Progress& progress = {});
// Puts the imported items into the project; refuses existing names unless options.overwrite.
// All-or-nothing: checks every name before inserting any.
Status applyImport(Project& project, ImportResult result, bool overwrite);

}  // namespace athlos
