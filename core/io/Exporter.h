#pragma once
// Export of streams and tables. CSV follows the interchange convention (header row, `t` first,
// shortest round-trip number formatting so export → import reproduces values bit for bit).
// HDF5 export writes a self-describing standalone file (t, data, columns, units, provenance).
#include "core/model/Stream.h"
#include "core/model/Table.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QString>

namespace athlos {

Status exportStreamCsv(const Stream& stream, const QString& file, const Progress& progress = {});
Status exportTableCsv(const Table& table, const QString& file);
Status exportStreamHdf5(const Stream& stream, const QString& file);
Status exportTableHdf5(const Table& table, const QString& file);

}  // namespace athlos
