// Standalone HDF5 export of one stream or table: the same datasets as inside a project, with the
// metadata on the root group so that h5py/MATLAB users need no Athlos knowledge:
//   stream: /t (N), /data (N×C); attrs format="athlos-stream", name, kind, frame, column_names,
//           units (string arrays), columns/attributes/provenance (JSON), rows, t_begin, t_end, content_hash
//   table:  one dataset per column; attrs format="athlos-table", name, kind, columns/attributes/provenance
#include "core/io/Exporter.h"

#include "core/store/Hdf5Util.h"
#include "core/util/Version.h"

#include <QDir>
#include <QFile>
#include <functional>
#include <new>

namespace athlos {
namespace {

constexpr int kExportFormatVersion = 1;

// Writes file with body under the HDF5 lock; a failed export leaves no half-written file.
Status writeExport(const QString& what, const QString& file, const std::function<void(hid_t)>& body) {
    auto guard = h5::lock();
    bool created = false;
    try {
        h5::Handle handle = h5::createFile(file);
        created = true;
        h5::writeString(handle, "app_version", appVersion());
        h5::writeInt(handle, "format_version", kExportFormatVersion);
        body(handle);
        handle.close(QStringLiteral("cannot finish writing the file"));
        return {};
    } catch (const h5::Failure& failure) {
        if (created) QFile::remove(file);
        return makeError(
            QStringLiteral("cannot export %1 to '%2': %3").arg(what, QDir::toNativeSeparators(file), failure.message));
    } catch (const std::bad_alloc&) {
        if (created) QFile::remove(file);
        return makeError(
            QStringLiteral("cannot export %1 to '%2': out of memory").arg(what, QDir::toNativeSeparators(file)));
    }
}

}  // namespace

Status exportStreamHdf5(const Stream& stream, const QString& file) {
    const QString what = QStringLiteral("stream '%1'").arg(stream.name());
    // Load outside the HDF5 lock: the stream's loader takes it itself.
    auto data = stream.data();
    if (!data) return makeError(QStringLiteral("cannot export %1: %2").arg(what, data.message()));
    const StreamData& samples = **data;
    const StreamInfo& info = stream.info();
    if (samples.columns != static_cast<int>(info.columns.size()))
        return makeError(QStringLiteral("cannot export %1: %2 columns of samples but %3 named")
                             .arg(what)
                             .arg(samples.columns)
                             .arg(info.columns.size()));

    return writeExport(what, file, [&](hid_t root) {
        QStringList names, units;
        QJsonArray described;
        for (const Column& c : info.columns) {
            names << c.name;
            units << c.unit;
            described.append(QJsonObject{{QStringLiteral("name"), c.name}, {QStringLiteral("unit"), c.unit}});
        }
        h5::writeString(root, "format", QStringLiteral("athlos-stream"));
        h5::writeString(root, "name", info.name);
        h5::writeString(root, "kind", info.kind);
        h5::writeString(root, "frame", info.frame);
        h5::writeStrings(root, "column_names", names);
        h5::writeStrings(root, "units", units);
        h5::writeJson(root, "columns", described);
        h5::writeJson(root, "attributes", info.attributes);
        h5::writeJson(root, "provenance", info.provenance.toJson());
        h5::writeInt(root, "rows", static_cast<long long>(samples.rows()));
        h5::writeDouble(root, "t_begin", samples.t.empty() ? 0.0 : samples.t.front());
        h5::writeDouble(root, "t_end", samples.t.empty() ? 0.0 : samples.t.back());
        h5::writeString(root, "content_hash",
                        QString::fromLatin1(info.contentHash.isEmpty() ? samples.contentHash() : info.contentHash));
        h5::writeSamples(root, samples);
    });
}

Status exportTableHdf5(const Table& table, const QString& file) {
    return writeExport(QStringLiteral("table '%1'").arg(table.name), file, [&](hid_t root) {
        h5::writeString(root, "format", QStringLiteral("athlos-table"));
        h5::writeString(root, "name", table.name);
        h5::writeString(root, "kind", table.kind);
        h5::writeJson(root, "attributes", table.attributes);
        h5::writeJson(root, "provenance", table.provenance.toJson());
        h5::writeTableColumns(root, table);
    });
}

}  // namespace athlos
