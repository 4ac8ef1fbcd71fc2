#include "core/model/Project.h"

#include "core/store/ProjectFile.h"
#include "core/store/ProjectLock.h"
#include "core/util/Version.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QRandomGenerator>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace athlos {
namespace {

QString nowUtc() { return QDateTime::currentDateTimeUtc().toString(Qt::ISODate); }

// fsync a file or folder so that a rename that follows is durable (a crash after save() returns
// never shows the old file, nor an empty new one).
bool syncPath(const QString& path) {
    const int fd = ::open(QFile::encodeName(path).constData(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool ok = ::fsync(fd) == 0;
    ::close(fd);
    return ok;
}

}  // namespace

bool ItemPath::isValid() const {
    auto ok = [](const QString& name) {
        return !name.isEmpty() && name != u"." && name != u".." && !name.contains(QLatin1Char('/'));
    };
    return ok(recording) && ok(item);
}

ItemPath ItemPath::parse(const QString& path) {
    const int slash = path.indexOf(QLatin1Char('/'));
    if (slash < 0) return {path, {}};
    return {path.left(slash), path.mid(slash + 1)};
}

Project::Project(QString path) : path_(std::move(path)) {}
Project::~Project() = default;

std::unique_ptr<Project> Project::create(const QString& path, const QString& sport) {
    std::unique_ptr<Project> project(new Project(QFileInfo(path).absoluteFilePath()));
    project->meta_.formatVersion = kFormatVersion;
    project->meta_.appVersion = appVersion();
    project->meta_.created = nowUtc();
    project->meta_.modified = project->meta_.created;
    project->meta_.sport = sport;
    project->modified_ = true;
    return project;
}

Expected<std::unique_ptr<Project>> Project::open(const QString& path) {
    std::unique_ptr<Project> project(new Project(QFileInfo(path).absoluteFilePath()));
    if (Status status = ProjectFile::read(project->path_, *project); !status) return status.error();
    project->modified_ = false;
    return project;
}

Expected<std::unique_ptr<Project>> Project::openForChange(const QString& path) {
    auto lock = ProjectLock::acquire(path);
    if (!lock) return lock.error();
    auto project = open(path);
    if (!project) {
        // What the lock did about stale saves stays worth knowing even when the project is refused.
        if (!(*lock)->notes().isEmpty())
            return makeError(project.message() + QStringLiteral(" (") + (*lock)->notes().join(QStringLiteral("; ")) +
                             QLatin1Char(')'));
        return project.error();
    }
    (*project)->notes_ = (*lock)->notes();
    (*project)->lock_ = std::move(lock).value();
    return project;
}

Status Project::lockForChange() {
    if (holdsLock()) return {};
    auto lock = ProjectLock::acquire(path_);
    if (!lock) return lock.error();
    notes_ = (*lock)->notes();
    lock_ = std::move(lock).value();
    return {};
}

bool Project::holdsLock() const { return lock_ && lock_->projectPath() == path_; }

Status Project::save(const Progress& progress) { return saveAs(path_, progress); }

Status Project::saveAs(const QString& path, const Progress& progress) {
    // Saving through a symlink replaces the link's target, not the link.
    const QFileInfo given(path);
    const QFileInfo target(given.isSymLink() ? given.symLinkTarget() : given.absoluteFilePath());
    const QString absolute = target.absoluteFilePath();
    const QDir dir = target.absoluteDir();
    if (!dir.exists())
        return makeError(QStringLiteral("cannot save '%1': folder '%2' does not exist").arg(path, dir.path()));

    // The temporary file lives in the same folder so that rename() is atomic (same file system).
    const QString tmp = dir.filePath(QStringLiteral(".%1.tmp-%2")
                                         .arg(target.fileName())
                                         .arg(QRandomGenerator::global()->generate64(), 16, 16, QLatin1Char('0')));
    // Every save holds the target's write lock: this project's own, or one taken for the save.
    std::unique_ptr<ProjectLock> saveLock;
    if (!lock_ || lock_->projectPath() != absolute) {
        auto acquired = ProjectLock::acquire(absolute, ProjectLock::StaleSaves::Leave);
        if (!acquired) return makeError(QStringLiteral("cannot save '%1': %2").arg(path, acquired.message()));
        saveLock = std::move(acquired).value();
    }
    const ProjectMeta previous = meta_;
    meta_.appVersion = appVersion();
    meta_.modified = nowUtc();
    if (meta_.created.isEmpty()) meta_.created = meta_.modified;

    Status written = ProjectFile::write(*this, tmp, progress);
    if (!written && written.message() != u"cancelled")
        written = makeError(QStringLiteral("cannot save '%1': %2").arg(path, written.message()));
    // Keep the permissions of the file being replaced (a shared, group-writable project stays so).
    if (written && target.exists()) QFile::setPermissions(tmp, QFile::permissions(absolute));
    if (written && !syncPath(tmp))
        written = makeError(QStringLiteral("cannot save '%1': flushing '%2' failed: %3")
                                .arg(path, tmp, QString::fromLocal8Bit(std::strerror(errno))));
    if (written && ::rename(QFile::encodeName(tmp).constData(), QFile::encodeName(absolute).constData()) != 0)
        written =
            makeError(QStringLiteral("cannot save '%1': %2").arg(path, QString::fromLocal8Bit(std::strerror(errno))));
    if (!written) {
        QFile::remove(tmp);
        meta_ = previous;
        return written;
    }
    syncPath(dir.absolutePath());
    path_ = given.isSymLink() ? given.absoluteFilePath() : absolute;
    meta_.formatVersion = kFormatVersion;                // a version-1 project is upgraded by its first save
    if (lock_ && saveLock) lock_ = std::move(saveLock);  // Save As: the held lock moves to the new file
    ProjectFile::rebind(*this, absolute);
    modified_ = false;
    return {};
}

QStringList Project::recordingNames() const {
    QStringList names;
    for (const auto& [name, rec] : recordings_) names << name;
    return names;
}

Recording* Project::recording(const QString& name) {
    auto it = recordings_.find(name);
    return it == recordings_.end() ? nullptr : &it->second;
}

const Recording* Project::recording(const QString& name) const {
    auto it = recordings_.find(name);
    return it == recordings_.end() ? nullptr : &it->second;
}

const TrainedModel* Project::model(const QString& name) const {
    auto it = models_.find(name);
    return it == models_.end() ? nullptr : &it->second;
}

Recording& Project::ensureRecording(const QString& name) {
    auto& rec = recordings_[name];
    if (rec.name.isEmpty()) {
        rec.name = name;
        modified_ = true;
    }
    return rec;
}

bool Project::removeRecording(const QString& name) {
    const bool removed = recordings_.erase(name) > 0;
    modified_ |= removed;
    return removed;
}

const Stream* Project::stream(const QString& path) const {
    const auto p = ItemPath::parse(path);
    const Recording* rec = recording(p.recording);
    if (!rec) return nullptr;
    auto it = rec->streams.find(p.item);
    return it == rec->streams.end() ? nullptr : &it->second;
}

Stream* Project::stream(const QString& path) { return const_cast<Stream*>(std::as_const(*this).stream(path)); }

const Table* Project::table(const QString& path) const {
    const auto p = ItemPath::parse(path);
    const Recording* rec = recording(p.recording);
    if (!rec) return nullptr;
    auto it = rec->tables.find(p.item);
    return it == rec->tables.end() ? nullptr : &it->second;
}

Table* Project::table(const QString& path) { return const_cast<Table*>(std::as_const(*this).table(path)); }

void Project::putStream(const QString& path, Stream stream) {
    const auto p = ItemPath::parse(path);
    Recording& rec = ensureRecording(p.recording);
    rec.tables.erase(p.item);
    stream.info().name = p.item;
    rec.streams.insert_or_assign(p.item, std::move(stream));
    modified_ = true;
}

void Project::putTable(const QString& path, Table table) {
    const auto p = ItemPath::parse(path);
    Recording& rec = ensureRecording(p.recording);
    rec.streams.erase(p.item);
    table.name = p.item;
    rec.tables.insert_or_assign(p.item, std::move(table));
    modified_ = true;
}

bool Project::removeItem(const QString& path) {
    const auto p = ItemPath::parse(path);
    Recording* rec = recording(p.recording);
    if (!rec) return false;
    const bool removed = rec->streams.erase(p.item) + rec->tables.erase(p.item) > 0;
    modified_ |= removed;
    return removed;
}

QStringList Project::streamPaths() const {
    QStringList paths;
    for (const auto& [name, rec] : recordings_)
        for (const auto& [item, s] : rec.streams) paths << name + QLatin1Char('/') + item;
    return paths;
}

QStringList Project::tablePaths() const {
    QStringList paths;
    for (const auto& [name, rec] : recordings_)
        for (const auto& [item, t] : rec.tables) paths << name + QLatin1Char('/') + item;
    return paths;
}

}  // namespace athlos
