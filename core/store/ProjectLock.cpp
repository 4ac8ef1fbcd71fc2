#include "core/store/ProjectLock.h"

#include "core/store/ProjectFile.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>

namespace athlos {

ProjectLock::ProjectLock(QString projectPath, std::unique_ptr<QLockFile> file)
    : projectPath_(std::move(projectPath)), file_(std::move(file)) {}

ProjectLock::~ProjectLock() {
    if (file_) file_->unlock();
}

QString ProjectLock::lockPathFor(const QString& projectPath) {
    const QFileInfo info(projectPath);
    return info.absoluteDir().filePath(QStringLiteral(".%1.lock").arg(info.fileName()));
}

QStringList ProjectLock::staleSavesOf(const QString& projectPath) {
    const QFileInfo info(projectPath);
    const QDir dir = info.absoluteDir();
    QStringList found;
    const QStringList names = dir.entryList({QStringLiteral(".%1.tmp-*").arg(info.fileName())},
                                            QDir::Files | QDir::Hidden | QDir::System, QDir::Name);
    for (const QString& name : names) found << dir.filePath(name);
    return found;
}

Expected<std::unique_ptr<ProjectLock>> ProjectLock::acquire(const QString& projectPath, StaleSaves staleSaves) {
    const QString path = QFileInfo(projectPath).absoluteFilePath();
    auto file = std::make_unique<QLockFile>(lockPathFor(path));
    // A GUI may hold its project for hours: only a dead holder (PID check) makes a lock stale.
    file->setStaleLockTime(0);
    if (!file->tryLock(0)) {
        if (file->error() == QLockFile::LockFailedError) {
            qint64 pid = 0;
            QString host, program;
            file->getLockInfo(&pid, &host, &program);
            return makeError(
                QStringLiteral("project '%1' is being changed by another Athlos process (%2, pid %3%4); "
                               "nothing was changed here: try again when it has finished, or close the project there")
                    .arg(QDir::toNativeSeparators(projectPath), program.isEmpty() ? QStringLiteral("athlos") : program)
                    .arg(pid)
                    .arg(host.isEmpty() ? QString() : QStringLiteral(" on ") + host));
        }
        return makeError(QStringLiteral("cannot lock project '%1': cannot create '%2' (is the folder writable?)")
                             .arg(QDir::toNativeSeparators(projectPath), QDir::toNativeSeparators(lockPathFor(path))));
    }
    std::unique_ptr<ProjectLock> lock(new ProjectLock(path, std::move(file)));
    if (staleSaves == StaleSaves::Handle) lock->handleStaleSaves();
    return lock;
}

void ProjectLock::handleStaleSaves() {
    const QFileInfo project(projectPath_);
    for (const QString& tmp : staleSavesOf(projectPath_)) {
        const QString shown = QFileInfo(tmp).fileName();
        Status complete = ProjectFile::check(tmp);
        if (complete) {
            const QString stamp = QFileInfo(tmp).lastModified().toUTC().toString(QStringLiteral("yyyyMMdd-HHmmss"));
            QString target = project.absoluteDir().filePath(
                QStringLiteral("%1.recovered-%2.%3").arg(project.completeBaseName(), stamp, project.suffix()));
            for (int i = 2; QFileInfo::exists(target); ++i)
                target = project.absoluteDir().filePath(QStringLiteral("%1.recovered-%2-%3.%4")
                                                            .arg(project.completeBaseName(), stamp)
                                                            .arg(i)
                                                            .arg(project.suffix()));
            if (QFile::rename(tmp, target))
                notes_
                    << QStringLiteral(
                           "a save of '%1' was interrupted after it had written a complete file; it was kept as '%2' "
                           "(the project itself is as it was last saved)")
                           .arg(project.fileName(), QFileInfo(target).fileName());
            else
                notes_ << QStringLiteral(
                              "a save of '%1' was interrupted; its complete temporary file '%2' could not be renamed")
                              .arg(project.fileName(), shown);
        } else if (QFile::remove(tmp)) {
            notes_ << QStringLiteral(
                          "removed '%1', an unfinished save of '%2' by a process that was stopped while saving "
                          "(the project is as it was last saved)")
                          .arg(shown, project.fileName());
        } else {
            notes_ << QStringLiteral("'%1' is an unfinished save of '%2' and could not be removed")
                          .arg(shown, project.fileName());
        }
    }
}

}  // namespace athlos
