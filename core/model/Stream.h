#pragma once
// A typed time series inside a recording. Metadata is always in memory; samples are loaded lazily
// from the project file on first access (opening a project never reads samples).
#include "core/model/Column.h"
#include "core/model/Provenance.h"
#include "core/model/StreamData.h"
#include "core/util/Expected.h"

#include <QJsonObject>
#include <QString>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>

namespace athlos {

struct StreamInfo {
    QString name;   // stream name inside its recording
    QString kind;   // "imu", "lps-position", "lps-tdoa", "gnss", "orientation", "reference", ...
    QString frame;  // "sensor", "ENU", "lps", "track", ...
    Columns columns;
    QJsonObject attributes;  // free metadata, e.g. {"sampling_rate": 285.71, "device": "..."}
    Provenance provenance;
    long long rows = 0;
    double tBegin = 0.0;  // first and last time stamp (s), known without reading samples
    double tEnd = 0.0;
    QByteArray contentHash;

    int columnIndex(const QString& column) const;  // -1 if absent
    QStringList columnNames() const;
};

// Where unloaded samples live: an HDF5 file and the group of the stream inside it. Lets a save
// copy untouched streams file-to-file (H5Ocopy) instead of decoding and re-encoding them.
struct FileSource {
    QString file;
    QString group;  // e.g. "/recordings/run1/imu"
};

class Stream {
public:
    using Loader = std::function<Expected<StreamData>()>;

    Stream() = default;
    // A stream whose samples are already in memory. Fills rows, tBegin/tEnd and contentHash.
    Stream(StreamInfo info, StreamData data);
    // A stream backed by a file (the project file); info must already be complete.
    Stream(StreamInfo info, FileSource source, Loader loader);

    const StreamInfo& info() const { return info_; }
    StreamInfo& info() { return info_; }
    const QString& name() const { return info_.name; }
    const QString& kind() const { return info_.kind; }

    bool isLoaded() const;
    // The samples, loading them on first use. Thread-safe.
    Expected<std::shared_ptr<const StreamData>> data() const;

    // Replaces the samples (e.g. after an edit); updates rows, time span and hash, and detaches
    // the stream from its file.
    void setData(StreamData data);

    // The file the samples can be read from, if any (absent for streams created in memory).
    const std::optional<FileSource>& fileSource() const { return source_; }
    // After a save: the samples now live at another place. Keeps already loaded samples.
    void rebind(FileSource source, Loader loader);

private:
    StreamInfo info_;
    std::optional<FileSource> source_;
    Loader loader_;
    mutable std::shared_ptr<const StreamData> data_;
    mutable std::shared_ptr<std::mutex> mutex_ = std::make_shared<std::mutex>();
};

}  // namespace athlos
