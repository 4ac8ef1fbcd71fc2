#pragma once
// Private helpers of the HDF5 store (ProjectFile, Hdf5Exporter): RAII handles, one global lock,
// attribute and dataset I/O. Failures throw h5::Failure inside the store; the public functions
// catch it at their boundary and turn it into an athlos::Error that names the file.
#include "core/model/StreamData.h"
#include "core/model/Table.h"

#include <hdf5.h>

#include <QByteArray>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <functional>
#include <mutex>
#include <utility>
#include <vector>

namespace athlos::h5 {

struct Failure {
    QString message;  // names the HDF5 object; the caller prefixes the file
};

// Every HDF5 call happens under this lock: the library may be built without thread safety and the
// GUI loads streams from worker threads. Recursive because progress callbacks may re-enter.
// Taking it also turns off HDF5's automatic error printing for the calling thread.
std::unique_lock<std::recursive_mutex> lock();

// Throws Failure("<what> (HDF5: <innermost library message>)").
[[noreturn]] void fail(const QString& what);
// The innermost message of the current HDF5 error stack (empty if none); clears the stack.
QString libraryMessage();

class Handle {
public:
    using Closer = herr_t (*)(hid_t);
    Handle() = default;
    Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
    Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, -1)), closer_(other.closer_) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, -1);
            closer_ = other.closer_;
        }
        return *this;
    }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { reset(); }

    operator hid_t() const { return id_; }
    bool valid() const { return id_ >= 0; }
    void reset() {
        if (id_ >= 0 && closer_) closer_(id_);
        id_ = -1;
    }
    // Closes now and reports failure (closing a file flushes it, so this can fail).
    void close(const QString& what);

private:
    hid_t id_ = -1;
    Closer closer_ = nullptr;
};

// Name of an open object inside its file, e.g. "/recordings/run1/imu".
QString objectPath(hid_t object);
QString childPath(hid_t parent, const QString& name);

Handle createFile(const QString& path);           // truncates; file format of HDF5 1.8 or later
Handle tryOpenFileReadOnly(const QString& path);  // invalid on failure; see libraryMessage()
Handle openFileReadOnly(const QString& path);
Handle createGroup(hid_t parent, const QString& name);
Handle openGroup(hid_t parent, const QString& name);  // a child name or an absolute path
Handle openDataset(hid_t parent, const QString& name);
bool hasChild(hid_t parent, const QString& name);
QStringList childNames(hid_t group);  // sorted by name
void copyObject(hid_t sourceParent, const QString& sourceName, hid_t targetParent, const QString& targetName);
std::vector<hsize_t> extent(hid_t dataset);

// Attributes (scalar; strings are variable-length UTF-8).
bool hasAttribute(hid_t object, const char* name);
void writeString(hid_t object, const char* name, const QString& value);
void writeStrings(hid_t object, const char* name, const QStringList& values);  // 1-D array
void writeInt(hid_t object, const char* name, long long value);
void writeDouble(hid_t object, const char* name, double value);
void writeJson(hid_t object, const char* name, const QJsonObject& value);
void writeJson(hid_t object, const char* name, const QJsonArray& value);
QString readString(hid_t object, const char* name);  // variable or fixed length
long long readInt(hid_t object, const char* name);
double readDouble(hid_t object, const char* name);
QJsonObject readJsonObject(hid_t object, const char* name);  // {} if the attribute is absent
QJsonArray readJsonArray(hid_t object, const char* name);    // [] if the attribute is absent

// Small 1-D datasets (tables, annotations): contiguous, uncompressed.
void writeNumberColumn(hid_t parent, const QString& name, const std::vector<double>& values);
void writeTextColumn(hid_t parent, const QString& name, const QStringList& values);
std::vector<double> readNumberColumn(hid_t parent, const QString& name);
// One text (e.g. a serialized model) as a scalar fixed-length UTF-8 string dataset. Reading
// refuses a text longer than maxBytes, or larger than the file can hold, before allocating.
void writeText(hid_t parent, const QString& name, const QByteArray& text);
QByteArray readText(hid_t parent, const QString& name, long long maxBytes);
QStringList readTextColumn(hid_t parent, const QString& name);

// Stream samples as datasets t (N) and data (N×C), chunked, shuffled and deflated. advance(rows)
// is called after each written block and may throw to abort (cancellation).
void writeSamples(hid_t group, const StreamData& data, const std::function<void(long long rows)>& advance = {});
// Reads t and data of group; refuses if their row counts differ or data has not `columns` columns
// (columns < 0: any).
StreamData readSamples(hid_t group, int columns);
// Checks t/data extents against rows × columns without reading samples.
void checkSampleExtents(hid_t group, long long rows, int columns);

// Table columns as one dataset each, described by a "columns" attribute on group.
void writeTableColumns(hid_t group, const Table& table);
std::vector<TableColumn> readTableColumns(hid_t group);

}  // namespace athlos::h5
