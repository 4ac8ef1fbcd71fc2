#include "core/model/Stream.h"

#include <QStringList>

namespace athlos {

int StreamInfo::columnIndex(const QString& column) const {
    for (std::size_t i = 0; i < columns.size(); ++i)
        if (columns[i].name == column) return static_cast<int>(i);
    return -1;
}

QStringList StreamInfo::columnNames() const {
    QStringList names;
    for (const auto& c : columns) names << c.name;
    return names;
}

Stream::Stream(StreamInfo info, StreamData data) : info_(std::move(info)) { setData(std::move(data)); }

Stream::Stream(StreamInfo info, FileSource source, Loader loader)
    : info_(std::move(info)), source_(std::move(source)), loader_(std::move(loader)) {}

bool Stream::isLoaded() const {
    std::lock_guard lock(*mutex_);
    return data_ != nullptr;
}

Expected<std::shared_ptr<const StreamData>> Stream::data() const {
    std::lock_guard lock(*mutex_);
    if (data_) return data_;
    if (!loader_) return makeError(QStringLiteral("stream '%1' has no samples").arg(info_.name));
    auto loaded = loader_();
    if (!loaded) return loaded.error();
    if (loaded->columns != static_cast<int>(info_.columns.size()))
        return makeError(QStringLiteral("stream '%1': stored data has %2 columns, metadata names %3")
                             .arg(info_.name)
                             .arg(loaded->columns)
                             .arg(info_.columns.size()));
    data_ = std::make_shared<const StreamData>(std::move(loaded).value());
    return data_;
}

void Stream::setData(StreamData data) {
    info_.rows = static_cast<long long>(data.rows());
    info_.tBegin = data.t.empty() ? 0.0 : data.t.front();
    info_.tEnd = data.t.empty() ? 0.0 : data.t.back();
    info_.contentHash = data.contentHash();
    std::lock_guard lock(*mutex_);
    data_ = std::make_shared<const StreamData>(std::move(data));
    source_.reset();
    loader_ = nullptr;
}

void Stream::rebind(FileSource source, Loader loader) {
    std::lock_guard lock(*mutex_);
    source_ = std::move(source);
    loader_ = std::move(loader);
}

}  // namespace athlos
