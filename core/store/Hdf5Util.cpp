#include "core/store/Hdf5Util.h"

#include <QFile>
#include <QJsonDocument>
#include <QSet>
#include <algorithm>
#include <limits>
#include <string>

namespace athlos::h5 {
namespace {

// Speed matters more than the last percent: after shuffle, level 1 stores noisy sensor data within
// ~1 % of the size level 6 gives (measured: 39.1 % vs 38.5 % of raw); higher levels only cost time.
constexpr unsigned kDeflateLevel = 1;
constexpr hsize_t kChunkBytes = hsize_t(1) << 20;  // ~1 MiB chunks: fits HDF5's default chunk cache
constexpr hsize_t kBlockBytes = hsize_t(8) << 20;  // rows per write call: progress/cancel granularity

QByteArray utf8(const QString& s) { return s.toUtf8(); }

herr_t innermost(unsigned n, const H5E_error2_t* error, void* out) {
    if (n == 0 && error && error->desc) *static_cast<QString*>(out) = QString::fromUtf8(error->desc).trimmed();
    return 0;
}

void check(herr_t status, const QString& what) {
    if (status < 0) fail(what);
}

Handle checked(hid_t id, Handle::Closer closer, const QString& what) {
    if (id < 0) fail(what);
    return Handle(id, closer);
}

// Link names are flagged UTF-8 so that other tools (h5py, HDFView) show them correctly.
Handle utf8Links() {
    Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
    H5Pset_char_encoding(lcpl, H5T_CSET_UTF8);
    return lcpl;
}

// Variable-length strings (format version 1) live in HDF5's global heap, whose reader crashes on
// damaged files (H5HG_read); they are only read, never written.
Handle variableStringType(H5T_cset_t cset) {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, cset);
    return type;
}

// Format version 2 writes fixed-length, NUL-padded UTF-8 strings of `bytes` bytes (at least 1).
Handle fixedStringType(std::size_t bytes) {
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type, std::max<std::size_t>(bytes, 1));
    H5Tset_strpad(type, H5T_STR_NULLPAD);
    H5Tset_cset(type, H5T_CSET_UTF8);
    return type;
}

// Bytes of `count` elements of `width` bytes, refused when the file cannot hold them: a damaged
// size must not turn into a huge allocation. Compressed data may expand (deflate at most ~1032:1).
std::size_t checkedBytes(hid_t object, hsize_t count, std::size_t width, bool compressed, const QString& what) {
    const hid_t fileId = H5Iget_file_id(object);
    hsize_t fileSize = 0;
    if (fileId >= 0) {
        H5Fget_filesize(fileId, &fileSize);
        H5Fclose(fileId);
    }
    const long double bytes = static_cast<long double>(count) * static_cast<long double>(width);
    const long double limit = static_cast<long double>(fileSize) * (compressed ? 1100.0L : 1.0L) + 4096.0L;
    if (width == 0 || bytes > limit || bytes > static_cast<long double>(std::numeric_limits<std::ptrdiff_t>::max() / 2))
        throw Failure{QStringLiteral("%1 claims %2 bytes in a file of %3 bytes (damaged sizes)")
                          .arg(what)
                          .arg(double(bytes), 0, 'g', 6)
                          .arg(fileSize)};
    return static_cast<std::size_t>(bytes);
}

bool isCompressed(hid_t dataset) {
    Handle dcpl(H5Dget_create_plist(dataset), H5Pclose);
    if (!dcpl.valid()) return true;
    const int filters = H5Pget_nfilters(dcpl);
    for (int i = 0; i < filters; ++i) {
        unsigned flags = 0;
        size_t elements = 0;
        unsigned config = 0;
        if (H5Pget_filter2(dcpl, unsigned(i), &flags, &elements, nullptr, 0, nullptr, &config) == H5Z_FILTER_DEFLATE)
            return true;
    }
    return false;
}

// H5Treclaim is declared by 1.10.8's headers but not exported by its library.
void reclaimStrings(hid_t type, hid_t space, void* buffer) {
#if H5_VERSION_GE(1, 12, 0)
    H5Treclaim(type, space, H5P_DEFAULT, buffer);
#else
    H5Dvlen_reclaim(type, space, H5P_DEFAULT, buffer);
#endif
}

bool isValidName(const QString& name) {
    return !name.isEmpty() && !name.contains(QLatin1Char('/')) && name != QLatin1String(".");
}

void requireValidName(hid_t parent, const QString& name) {
    if (!isValidName(name))
        throw Failure{QStringLiteral("invalid name '%1' in %2 (names must be non-empty and contain no '/')")
                          .arg(name, objectPath(parent))};
}

// HDF5 1.10 locks files with flock(); on file systems without it (some NFS/SMB mounts) opening
// would fail, so locking is kept where it works and skipped where it cannot.
Handle fileAccess() {
    Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
#if H5_VERSION_GE(1, 10, 7)
    H5Pset_file_locking(fapl, true, true);
#endif
    return fapl;
}

Handle scalarSpace() { return checked(H5Screate(H5S_SCALAR), H5Sclose, QStringLiteral("cannot create a dataspace")); }

Handle simpleSpace(int rank, const hsize_t* dims) {
    return checked(H5Screate_simple(rank, dims, nullptr), H5Sclose, QStringLiteral("cannot create a dataspace"));
}

QString attributeName(hid_t object, const char* name) {
    return QStringLiteral("attribute '%1' of %2").arg(QString::fromUtf8(name), objectPath(object));
}

void writeAttribute(hid_t object, const char* name, hid_t fileType, hid_t memType, hid_t space, const void* buffer) {
    Handle attribute(H5Acreate2(object, name, fileType, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    if (!attribute.valid() || H5Awrite(attribute, memType, buffer) < 0)
        fail(QStringLiteral("cannot write ") + attributeName(object, name));
}

Handle openAttribute(hid_t object, const char* name, H5T_class_t expected1, H5T_class_t expected2 = H5T_NO_CLASS) {
    if (!hasAttribute(object, name)) throw Failure{QStringLiteral("missing ") + attributeName(object, name)};
    Handle attribute = checked(H5Aopen(object, name, H5P_DEFAULT), H5Aclose,
                               QStringLiteral("cannot open ") + attributeName(object, name));
    Handle type(H5Aget_type(attribute), H5Tclose);
    Handle space(H5Aget_space(attribute), H5Sclose);
    const H5T_class_t cls = type.valid() ? H5Tget_class(type) : H5T_NO_CLASS;
    if ((cls != expected1 && cls != expected2) || !space.valid() || H5Sget_simple_extent_npoints(space) != 1)
        throw Failure{attributeName(object, name) + QStringLiteral(" has an unexpected type or size")};
    return attribute;
}

QJsonDocument readJsonDocument(hid_t object, const char* name) {
    const QString text = readString(object, name);
    QJsonParseError error;
    QJsonDocument doc = QJsonDocument::fromJson(text.toUtf8(), &error);
    if (error.error != QJsonParseError::NoError)
        throw Failure{
            attributeName(object, name) +
            QStringLiteral(" is not valid JSON (%1 at offset %2)").arg(error.errorString()).arg(error.offset)};
    return doc;
}

Handle createDataset(hid_t parent, const QString& name, hid_t type, hid_t space, hid_t dcpl = H5P_DEFAULT) {
    requireValidName(parent, name);
    return checked(H5Dcreate2(parent, utf8(name).constData(), type, space, utf8Links(), dcpl, H5P_DEFAULT), H5Dclose,
                   QStringLiteral("cannot create dataset ") + childPath(parent, name));
}

// An empty dataset gets no chunks and no filters: HDF5 needs chunk dimensions > 0.
Handle createSampleDataset(hid_t parent, const char* name, int rank, const hsize_t* dims, const hsize_t* chunk) {
    Handle space = simpleSpace(rank, dims);
    Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    const bool empty = std::any_of(dims, dims + rank, [](hsize_t d) { return d == 0; });
    // Fletcher32 last: its checksum covers the stored (compressed) bytes, so a damaged chunk is
    // reported before it reaches the decompressor.
    if (!empty && (H5Pset_chunk(dcpl, rank, chunk) < 0 || H5Pset_shuffle(dcpl) < 0 ||
                   H5Pset_deflate(dcpl, kDeflateLevel) < 0 || H5Pset_fletcher32(dcpl) < 0))
        fail(QStringLiteral("cannot set up compression for ") + childPath(parent, QString::fromLatin1(name)));
    return createDataset(parent, QString::fromLatin1(name), H5T_IEEE_F64LE, space, dcpl);
}

// Table and annotation columns: chunked only to carry a Fletcher32 checksum (they are small).
Handle createColumnDataset(hid_t parent, const QString& name, hid_t type, hsize_t size) {
    Handle space = simpleSpace(1, &size);
    Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    const hsize_t chunk = std::clamp<hsize_t>(size, 1, 65536);
    if (size > 0 && (H5Pset_chunk(dcpl, 1, &chunk) < 0 || H5Pset_fletcher32(dcpl) < 0))
        fail(QStringLiteral("cannot set up checksums for ") + childPath(parent, name));
    return createDataset(parent, name, type, space, dcpl);
}

void writeRows(hid_t dataset, const double* values, hsize_t row, hsize_t count, hsize_t columns, int rank) {
    Handle fileSpace(H5Dget_space(dataset), H5Sclose);
    const hsize_t start[2] = {row, 0};
    const hsize_t size[2] = {count, columns};
    Handle memSpace(H5Screate_simple(rank, size, nullptr), H5Sclose);
    if (!fileSpace.valid() || !memSpace.valid() ||
        H5Sselect_hyperslab(fileSpace, H5S_SELECT_SET, start, nullptr, size, nullptr) < 0 ||
        H5Dwrite(dataset, H5T_NATIVE_DOUBLE, memSpace, fileSpace, H5P_DEFAULT, values) < 0)
        fail(QStringLiteral("cannot write %1 (rows %2..%3)").arg(objectPath(dataset)).arg(row).arg(row + count));
}

struct SampleSets {
    Handle t, data;
    hsize_t rows = 0, columns = 0;
};

SampleSets openSamples(hid_t group, int columns) {
    SampleSets s{openDataset(group, QStringLiteral("t")), openDataset(group, QStringLiteral("data"))};
    const auto te = extent(s.t), de = extent(s.data);
    const QString where = objectPath(group);
    if (te.size() != 1) throw Failure{where + QStringLiteral("/t is not one-dimensional")};
    if (de.size() != 2) throw Failure{where + QStringLiteral("/data is not two-dimensional")};
    if (de[0] != te[0])
        throw Failure{
            QStringLiteral("%1 is inconsistent: data has %2 rows but t has %3").arg(where).arg(de[0]).arg(te[0])};
    if (columns >= 0 && de[1] != hsize_t(columns))
        throw Failure{QStringLiteral("%1 is inconsistent: data has %2 columns but the stream names %3")
                          .arg(where)
                          .arg(de[1])
                          .arg(columns)};
    s.rows = te[0];
    s.columns = de[1];
    return s;
}

}  // namespace

std::unique_lock<std::recursive_mutex> lock() {
    static std::recursive_mutex mutex;
    std::unique_lock guard(mutex);
    // The error stack (and its auto-print setting) is per thread in thread-safe builds.
    thread_local const bool silenced = H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0;
    (void)silenced;
    return guard;
}

QString libraryMessage() {
    QString message;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, &message);
    H5Eclear2(H5E_DEFAULT);
    return message;
}

void fail(const QString& what) {
    const QString detail = libraryMessage();
    throw Failure{detail.isEmpty() ? what : QStringLiteral("%1 (HDF5: %2)").arg(what, detail)};
}

void Handle::close(const QString& what) {
    const hid_t id = std::exchange(id_, -1);
    if (id >= 0 && closer_ && closer_(id) < 0) fail(what);
}

QString objectPath(hid_t object) {
    // Callers build failure messages with this, and C++ leaves the order of argument evaluation
    // open: `check(H5Dread(...), "cannot read " + objectPath(d))` may call H5Iget_name after the
    // failed read (clang does), and every API call clears the error stack. Keep the stack intact so
    // fail() still reports HDF5's reason (e.g. a checksum mismatch).
    const hid_t pending = H5Eget_current_stack();
    const ssize_t size = H5Iget_name(object, nullptr, 0);
    std::string name(std::size_t(std::max<ssize_t>(size, 0)) + 1, '\0');
    if (size > 0) H5Iget_name(object, name.data(), name.size());
    if (pending >= 0) H5Eset_current_stack(pending);
    if (size <= 0) return QStringLiteral("(unnamed object)");
    return QString::fromUtf8(name.c_str());
}

QString childPath(hid_t parent, const QString& name) {
    const QString base = objectPath(parent);
    return base.endsWith(QLatin1Char('/')) ? base + name : base + QLatin1Char('/') + name;
}

Handle createFile(const QString& path) {
    Handle fapl = fileAccess();
    // HDF5 1.10 file format (format_version 2): superblock version 3 and version-2 object headers,
    // which carry checksums, so damaged metadata is detected instead of being parsed. Readable by
    // HDF5 1.10 and later (h5py, HDFView, MATLAB R2021b+).
    H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_LATEST);
    return checked(H5Fcreate(QFile::encodeName(path).constData(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose,
                   QStringLiteral("cannot create the file"));
}

Handle tryOpenFileReadOnly(const QString& path) {
    return Handle(H5Fopen(QFile::encodeName(path).constData(), H5F_ACC_RDONLY, fileAccess()), H5Fclose);
}

Handle openFileReadOnly(const QString& path) {
    Handle file = tryOpenFileReadOnly(path);
    if (!file.valid()) fail(QStringLiteral("cannot open the file"));
    return file;
}

Handle createGroup(hid_t parent, const QString& name) {
    requireValidName(parent, name);
    return checked(H5Gcreate2(parent, utf8(name).constData(), utf8Links(), H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
                   QStringLiteral("cannot create group ") + childPath(parent, name));
}

Handle openGroup(hid_t parent, const QString& name) {
    // An absolute path ("/recordings/run1/imu") is opened as is; HDF5 names the missing part.
    const QString shown = name.startsWith(QLatin1Char('/')) ? name : childPath(parent, name);
    if (isValidName(name) && !hasChild(parent, name)) throw Failure{QStringLiteral("missing group ") + shown};
    return checked(H5Gopen2(parent, utf8(name).constData(), H5P_DEFAULT), H5Gclose,
                   QStringLiteral("cannot open group ") + shown);
}

Handle openDataset(hid_t parent, const QString& name) {
    if (!hasChild(parent, name)) throw Failure{QStringLiteral("missing dataset ") + childPath(parent, name)};
    return checked(H5Dopen2(parent, utf8(name).constData(), H5P_DEFAULT), H5Dclose,
                   QStringLiteral("cannot open dataset ") + childPath(parent, name));
}

bool hasChild(hid_t parent, const QString& name) {
    if (!isValidName(name)) return false;
    const htri_t exists = H5Lexists(parent, utf8(name).constData(), H5P_DEFAULT);
    if (exists < 0) fail(QStringLiteral("cannot look up ") + childPath(parent, name));
    return exists > 0;
}

QStringList childNames(hid_t group) {
    QStringList names;
    auto collect = [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
        static_cast<QStringList*>(out)->append(QString::fromUtf8(name));
        return 0;
    };
    check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names),
          QStringLiteral("cannot list ") + objectPath(group));
    return names;
}

void copyObject(hid_t sourceParent, const QString& sourceName, hid_t targetParent, const QString& targetName) {
    requireValidName(targetParent, targetName);
    check(H5Ocopy(sourceParent, utf8(sourceName).constData(), targetParent, utf8(targetName).constData(), H5P_DEFAULT,
                  utf8Links()),
          QStringLiteral("cannot copy %1 to %2")
              .arg(childPath(sourceParent, sourceName), childPath(targetParent, targetName)));
}

std::vector<hsize_t> extent(hid_t dataset) {
    Handle space =
        checked(H5Dget_space(dataset), H5Sclose, QStringLiteral("cannot read the shape of ") + objectPath(dataset));
    const int rank = H5Sget_simple_extent_ndims(space);
    if (rank < 0) fail(QStringLiteral("cannot read the shape of ") + objectPath(dataset));
    std::vector<hsize_t> dims(std::size_t(rank), 0);
    if (rank > 0) H5Sget_simple_extent_dims(space, dims.data(), nullptr);
    return dims;
}

bool hasAttribute(hid_t object, const char* name) {
    const htri_t exists = H5Aexists(object, name);
    if (exists < 0) fail(QStringLiteral("cannot look up ") + attributeName(object, name));
    return exists > 0;
}

void writeString(hid_t object, const char* name, const QString& value) {
    const QByteArray bytes = value.toUtf8();
    Handle type = fixedStringType(std::size_t(bytes.size()));
    std::string buffer(std::max<std::size_t>(std::size_t(bytes.size()), 1), '\0');
    std::copy(bytes.begin(), bytes.end(), buffer.begin());
    writeAttribute(object, name, type, type, scalarSpace(), buffer.data());
}

namespace {

// Strings as one fixed-length HDF5 string array: every element padded with NULs to the longest
// (UTF-8 bytes, at least 1).
struct FixedStrings {
    std::vector<char> buffer;
    std::size_t width = 1;
};

FixedStrings packFixedStrings(const QStringList& values) {
    std::vector<QByteArray> bytes;
    FixedStrings packed;
    for (const auto& v : values) {
        bytes.push_back(v.toUtf8());
        packed.width = std::max(packed.width, std::size_t(bytes.back().size()));
    }
    packed.buffer.assign(bytes.size() * packed.width, '\0');
    for (std::size_t i = 0; i < bytes.size(); ++i)
        std::copy(bytes[i].begin(), bytes[i].end(), packed.buffer.begin() + std::ptrdiff_t(i * packed.width));
    return packed;
}

}  // namespace

void writeStrings(hid_t object, const char* name, const QStringList& values) {
    const FixedStrings packed = packFixedStrings(values);
    const hsize_t size = hsize_t(values.size());
    Handle type = fixedStringType(packed.width);
    writeAttribute(object, name, type, type, simpleSpace(1, &size), packed.buffer.data());
}

void writeInt(hid_t object, const char* name, long long value) {
    writeAttribute(object, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, scalarSpace(), &value);
}

void writeDouble(hid_t object, const char* name, double value) {
    writeAttribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, scalarSpace(), &value);
}

void writeJson(hid_t object, const char* name, const QJsonObject& value) {
    writeString(object, name, QString::fromUtf8(QJsonDocument(value).toJson(QJsonDocument::Compact)));
}

void writeJson(hid_t object, const char* name, const QJsonArray& value) {
    writeString(object, name, QString::fromUtf8(QJsonDocument(value).toJson(QJsonDocument::Compact)));
}

QString readString(hid_t object, const char* name) {
    Handle attribute = openAttribute(object, name, H5T_STRING);
    Handle fileType(H5Aget_type(attribute), H5Tclose);
    const QString what = QStringLiteral("cannot read ") + attributeName(object, name);
    if (H5Tis_variable_str(fileType) > 0) {
        Handle memType = variableStringType(H5Tget_cset(fileType));
        char* data = nullptr;
        check(H5Aread(attribute, memType, &data), what);
        const QString value = QString::fromUtf8(data);
        H5free_memory(data);
        return value;
    }
    const std::size_t width = checkedBytes(object, 1, H5Tget_size(fileType), false, attributeName(object, name));
    std::string data(width + 1, '\0');
    Handle memType(H5Tcopy(fileType), H5Tclose);
    check(H5Aread(attribute, memType, data.data()), what);
    return QString::fromUtf8(data.c_str());
}

long long readInt(hid_t object, const char* name) {
    Handle attribute = openAttribute(object, name, H5T_INTEGER);
    long long value = 0;
    check(H5Aread(attribute, H5T_NATIVE_LLONG, &value), QStringLiteral("cannot read ") + attributeName(object, name));
    return value;
}

double readDouble(hid_t object, const char* name) {
    Handle attribute = openAttribute(object, name, H5T_FLOAT, H5T_INTEGER);
    double value = 0;
    check(H5Aread(attribute, H5T_NATIVE_DOUBLE, &value), QStringLiteral("cannot read ") + attributeName(object, name));
    return value;
}

QJsonObject readJsonObject(hid_t object, const char* name) {
    if (!hasAttribute(object, name)) return {};
    const QJsonDocument doc = readJsonDocument(object, name);
    if (!doc.isObject()) throw Failure{attributeName(object, name) + QStringLiteral(" is not a JSON object")};
    return doc.object();
}

QJsonArray readJsonArray(hid_t object, const char* name) {
    if (!hasAttribute(object, name)) return {};
    const QJsonDocument doc = readJsonDocument(object, name);
    if (!doc.isArray()) throw Failure{attributeName(object, name) + QStringLiteral(" is not a JSON array")};
    return doc.array();
}

void writeNumberColumn(hid_t parent, const QString& name, const std::vector<double>& values) {
    const hsize_t size = values.size();
    Handle dataset = createColumnDataset(parent, name, H5T_IEEE_F64LE, size);
    if (size > 0)
        check(H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
              QStringLiteral("cannot write ") + childPath(parent, name));
}

void writeTextColumn(hid_t parent, const QString& name, const QStringList& values) {
    const FixedStrings packed = packFixedStrings(values);
    const hsize_t size = hsize_t(values.size());
    Handle type = fixedStringType(packed.width);
    Handle dataset = createColumnDataset(parent, name, type, size);
    if (size > 0)
        check(H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, packed.buffer.data()),
              QStringLiteral("cannot write ") + childPath(parent, name));
}

void writeText(hid_t parent, const QString& name, const QByteArray& text) {
    Handle type = fixedStringType(std::max<std::size_t>(1, std::size_t(text.size())));
    Handle space(H5Screate(H5S_SCALAR), H5Sclose);
    if (!space.valid()) fail(QStringLiteral("cannot create a dataspace for ") + childPath(parent, name));
    Handle dataset(H5Dcreate2(parent, name.toUtf8().constData(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
    if (!dataset.valid()) fail(QStringLiteral("cannot create ") + childPath(parent, name));
    QByteArray padded = text;
    if (padded.isEmpty()) padded.append('\0');
    check(H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, padded.constData()),
          QStringLiteral("cannot write ") + childPath(parent, name));
}

QByteArray readText(hid_t parent, const QString& name, long long maxBytes) {
    Handle dataset = openDataset(parent, name);
    Handle fileType(H5Dget_type(dataset), H5Tclose);
    if (!extent(dataset).empty() || H5Tget_class(fileType) != H5T_STRING || H5Tis_variable_str(fileType) > 0)
        throw Failure{childPath(parent, name) + QStringLiteral(" is not a scalar fixed-length text dataset")};
    const std::size_t width = H5Tget_size(fileType);
    if (static_cast<long double>(width) > static_cast<long double>(maxBytes))
        throw Failure{QStringLiteral("%1 holds %2 bytes, more than the limit of %3 bytes")
                          .arg(childPath(parent, name))
                          .arg(qulonglong(width))
                          .arg(maxBytes)};
    QByteArray data(qsizetype(checkedBytes(dataset, 1, width, isCompressed(dataset), childPath(parent, name))),
                    Qt::Uninitialized);
    Handle memType(H5Tcopy(fileType), H5Tclose);
    check(H5Dread(dataset, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()),
          QStringLiteral("cannot read ") + childPath(parent, name));
    const qsizetype end = data.indexOf('\0');
    if (end >= 0) data.truncate(end);
    return data;
}

std::vector<double> readNumberColumn(hid_t parent, const QString& name) {
    Handle dataset = openDataset(parent, name);
    const auto dims = extent(dataset);
    if (dims.size() != 1) throw Failure{childPath(parent, name) + QStringLiteral(" is not one-dimensional")};
    checkedBytes(dataset, dims[0], sizeof(double), isCompressed(dataset), childPath(parent, name));
    std::vector<double> values(dims[0]);
    if (!values.empty())
        check(H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
              QStringLiteral("cannot read ") + childPath(parent, name));
    return values;
}

QStringList readTextColumn(hid_t parent, const QString& name) {
    Handle dataset = openDataset(parent, name);
    const auto dims = extent(dataset);
    Handle fileType(H5Dget_type(dataset), H5Tclose);
    if (dims.size() != 1 || H5Tget_class(fileType) != H5T_STRING)
        throw Failure{childPath(parent, name) + QStringLiteral(" is not a one-dimensional text dataset")};
    QStringList values;
    if (dims[0] == 0) return values;
    const QString what = QStringLiteral("cannot read ") + childPath(parent, name);
    if (H5Tis_variable_str(fileType) > 0) {
        checkedBytes(dataset, dims[0], sizeof(char*), true, childPath(parent, name));
        Handle memType = variableStringType(H5Tget_cset(fileType));
        std::vector<char*> data(dims[0], nullptr);
        check(H5Dread(dataset, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), what);
        for (const char* s : data) values << QString::fromUtf8(s ? s : "");
        Handle space(H5Dget_space(dataset), H5Sclose);
        reclaimStrings(memType, space, data.data());
        return values;
    }
    const std::size_t width = H5Tget_size(fileType);
    std::vector<char> data(checkedBytes(dataset, dims[0], width, isCompressed(dataset), childPath(parent, name)));
    Handle memType(H5Tcopy(fileType), H5Tclose);
    check(H5Dread(dataset, memType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), what);
    for (hsize_t i = 0; i < dims[0]; ++i) {
        const char* s = data.data() + i * width;
        values << QString::fromUtf8(s, qsizetype(std::find(s, s + width, '\0') - s));
    }
    return values;
}

void writeSamples(hid_t group, const StreamData& data, const std::function<void(long long)>& advance) {
    const hsize_t rows = data.rows();
    const hsize_t columns = hsize_t(std::max(data.columns, 0));
    if (data.columns < 0 || data.values.size() != rows * columns)
        throw Failure{QStringLiteral("%1: %2 values do not fill %3 rows × %4 columns")
                          .arg(objectPath(group))
                          .arg(data.values.size())
                          .arg(rows)
                          .arg(data.columns)};
    // t and data share the chunk row count so that each block below covers whole chunks of both.
    const hsize_t chunkRows =
        std::clamp<hsize_t>(kChunkBytes / (8 * std::max<hsize_t>(columns, 1)), 1, std::max<hsize_t>(rows, 1));
    const hsize_t blockRows = chunkRows * std::max<hsize_t>(1, kBlockBytes / (chunkRows * 8 * (columns + 1)));
    const hsize_t tDims[1] = {rows}, tChunk[1] = {chunkRows};
    const hsize_t dDims[2] = {rows, columns}, dChunk[2] = {chunkRows, std::max<hsize_t>(columns, 1)};
    Handle t = createSampleDataset(group, "t", 1, tDims, tChunk);
    Handle values = createSampleDataset(group, "data", 2, dDims, dChunk);
    for (hsize_t row = 0; row < rows; row += blockRows) {
        const hsize_t count = std::min(blockRows, rows - row);
        writeRows(t, data.t.data() + row, row, count, 0, 1);
        if (columns > 0) writeRows(values, data.values.data() + row * columns, row, count, columns, 2);
        if (advance) advance(static_cast<long long>(count));
    }
}

StreamData readSamples(hid_t group, int columns) {
    SampleSets sets = openSamples(group, columns);
    if (sets.columns > hsize_t(std::numeric_limits<int>::max()))
        throw Failure{objectPath(group) + QStringLiteral(" claims an impossible number of columns (damaged sizes)")};
    checkedBytes(sets.t, sets.rows, sizeof(double), isCompressed(sets.t), objectPath(sets.t));
    checkedBytes(sets.data, sets.rows * std::max<hsize_t>(sets.columns, 1), sizeof(double), isCompressed(sets.data),
                 objectPath(sets.data));
    StreamData data(sets.rows, static_cast<int>(sets.columns));
    if (sets.rows > 0)
        check(H5Dread(sets.t, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.t.data()),
              QStringLiteral("cannot read ") + objectPath(sets.t));
    if (!data.values.empty())
        check(H5Dread(sets.data, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.values.data()),
              QStringLiteral("cannot read ") + objectPath(sets.data));
    return data;
}

void checkSampleExtents(hid_t group, long long rows, int columns) {
    const SampleSets sets = openSamples(group, columns);
    if (static_cast<long long>(sets.rows) != rows)
        throw Failure{QStringLiteral("%1 is inconsistent: it has %2 rows but its 'rows' attribute says %3")
                          .arg(objectPath(group))
                          .arg(sets.rows)
                          .arg(rows)};
}

void writeTableColumns(hid_t group, const Table& table) {
    QJsonArray described;
    QSet<QString> used;
    for (std::size_t i = 0; i < table.columns.size(); ++i) {
        const TableColumn& column = table.columns[i];
        if (column.size() != table.rows())
            throw Failure{QStringLiteral("%1: column '%2' has %3 rows, the first column %4")
                              .arg(objectPath(group), column.name)
                              .arg(column.size())
                              .arg(table.rows())};
        // Column names are free text; the dataset falls back to a safe unique name.
        QString dataset = column.name;
        if (!isValidName(dataset) || used.contains(dataset)) dataset = QStringLiteral("column_%1").arg(i);
        while (used.contains(dataset)) dataset += QLatin1Char('_');
        used.insert(dataset);
        if (column.isText)
            writeTextColumn(group, dataset, column.texts);
        else
            writeNumberColumn(group, dataset, column.numbers);
        described.append(
            QJsonObject{{QStringLiteral("name"), column.name},
                        {QStringLiteral("unit"), column.unit},
                        {QStringLiteral("type"), column.isText ? QStringLiteral("text") : QStringLiteral("number")},
                        {QStringLiteral("dataset"), dataset}});
    }
    writeJson(group, "columns", described);
}

std::vector<TableColumn> readTableColumns(hid_t group) {
    std::vector<TableColumn> columns;
    for (const auto& value : readJsonArray(group, "columns")) {
        const QJsonObject o = value.toObject();
        TableColumn column;
        column.name = o.value(QStringLiteral("name")).toString();
        column.unit = o.value(QStringLiteral("unit")).toString();
        column.isText = o.value(QStringLiteral("type")).toString() == QLatin1String("text");
        const QString dataset = o.value(QStringLiteral("dataset")).toString(column.name);
        if (column.isText)
            column.texts = readTextColumn(group, dataset);
        else
            column.numbers = readNumberColumn(group, dataset);
        if (!columns.empty() && column.size() != columns.front().size())
            throw Failure{QStringLiteral("%1 is inconsistent: column '%2' has %3 rows, the first column %4")
                              .arg(objectPath(group), column.name)
                              .arg(column.size())
                              .arg(columns.front().size())};
        columns.push_back(std::move(column));
    }
    return columns;
}

}  // namespace athlos::h5
