#pragma once
// One writer per project file. A process that changes a project (the GUI for as long as it has the
// project open, `athlos import/run/pipeline/video`, a batch task) holds a lock file
// ".<name>.lock" beside it (QLockFile: PID, host and program, so a lock left by a killed
// process is recognised as stale and taken over). A second writer is refused with a message that
// names the holder; readers (`info`, `export`) need no lock.
//
// Taking the lock also deals with what a killed save left behind: every save holds the lock, so a
// ".<name>.tmp-…" file found by the new holder is stale. A complete one (killed between writing
// and renaming) is kept as "<name>.recovered-<UTC time>.athlos"; an incomplete one is removed.
// Each case is reported in notes().
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <memory>

class QLockFile;

namespace athlos {

class ProjectLock {
public:
    ~ProjectLock();
    ProjectLock(const ProjectLock&) = delete;
    ProjectLock& operator=(const ProjectLock&) = delete;

    enum class StaleSaves { Handle, Leave };
    // Takes the lock of the project file at path (which need not exist yet).
    static Expected<std::unique_ptr<ProjectLock>> acquire(const QString& projectPath,
                                                          StaleSaves staleSaves = StaleSaves::Handle);

    const QString& projectPath() const { return projectPath_; }
    // What was done about stale temporary files, one sentence each.
    const QStringList& notes() const { return notes_; }

    // ".<name>.lock" beside the project file.
    static QString lockPathFor(const QString& projectPath);
    // The ".<name>.tmp-…" files beside the project file.
    static QStringList staleSavesOf(const QString& projectPath);

private:
    ProjectLock(QString projectPath, std::unique_ptr<QLockFile> file);
    void handleStaleSaves();

    QString projectPath_;
    std::unique_ptr<QLockFile> file_;
    QStringList notes_;
};

}  // namespace athlos
