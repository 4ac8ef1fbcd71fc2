#pragma once
// Imports of more than one file with one command.
//
// importFiles(): several files of one kind into one item. Each file is imported as importFile()
// does; items that end up with the same name are merged:
//   - long-format streams (lps-range, lps-tdoa): the union of the measurements on one time axis
//     (the files' absolute starts t0_utc align them; t = 0 is the earliest start), one column per
//     beacon over all files; the same beacon at the same instant in two files is an error;
//   - other streams: pieces of one recording (a logger that splits files): same columns, times
//     aligned by t0_utc, and they must not overlap;
//   - tables (beacons): the union of the rows; an id in two files must have the same position.
// Without t0_utc on every stream the files are taken to share one clock (with a warning); a mix is
// an error.
//
// importFolder(): one stream per file of a folder (files no importer reads are skipped with a
// warning): <rec>/<file name>. The athlete is the file name, or comes from a roster CSV
// `file,athlete,number,team,position,mass_kg` (file: the name with or without extension; other
// columns optional, extra columns kept as text). The athlete goes onto the streams' attributes:
// athlete, label (= athlete, for the playback), number, team, position, mass_kg.
#include "core/io/Importer.h"

namespace athlos {

Expected<ImportResult> importFiles(const QStringList& files, const ImportOptions& options,
                                   const Progress& progress = {});

// One athlete of a roster.
struct RosterEntry {
    QString file;
    QJsonObject attributes;  // athlete, label, number, team, position, mass_kg, extra columns
};
Expected<std::vector<RosterEntry>> readRoster(const QString& file);

Expected<ImportResult> importFolder(const QString& folder, const ImportOptions& options, const QString& roster = {},
                                    const Progress& progress = {});

}  // namespace athlos
