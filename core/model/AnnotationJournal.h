#pragma once
// Crash safety for annotation work: every edit is appended as one JSON line to
// "<project>.journal" and synced to disk before the GUI shows it, so a kill -9 between two
// (atomic) project saves loses nothing. A successful save discards the journal; a journal found
// on open holds edits the file does not have yet, to be replayed.
#include "core/model/AnnotationEdit.h"
#include "core/util/Expected.h"

#include <QByteArray>
#include <QFile>
#include <QString>
#include <vector>

namespace athlos {

class Project;

class AnnotationJournal {
public:
    static QString pathFor(const QString& projectPath) { return projectPath + QStringLiteral(".journal"); }
    // A non-empty journal at least as new as the project file: edits that were not saved.
    static bool hasPendingEdits(const QString& projectPath);
    // Digest of a project's annotation state (classes and every recording's annotations). A journal
    // starts with the digest of the state its first edit applies to, so a journal that predates the
    // file's last save (killed between the save's rename and the journal's removal, where file times
    // can be equal) is recognised by content, not by time stamps.
    static QByteArray stateDigest(const Project& project);
    // Whether project (as opened from disk) is the state the journal's edits start from. True for a
    // journal without a digest (older versions); false when the edits are already in the file.
    static bool belongsTo(const Project& project);
    // The edits of a journal file. A torn last line (crash while writing) is ignored.
    static Expected<std::vector<AnnotationEdit>> read(const QString& journalPath);
    // Applies the journal of project.path() to project; returns how many edits were applied.
    // Stops at the first edit that does not fit (and says which line).
    static Expected<int> replay(Project& project);

    explicit AnnotationJournal(QString projectPath = {});
    ~AnnotationJournal();
    AnnotationJournal(const AnnotationJournal&) = delete;
    AnnotationJournal& operator=(const AnnotationJournal&) = delete;

    // Follows the project to another path (Save As); the old journal is left for discard().
    void setProjectPath(const QString& projectPath);
    QString path() const { return file_.fileName(); }
    // One line, flushed and fsync'd. The first edit of a journal file also writes the digest of
    // base (the state the edit applies to) when given.
    Status append(const AnnotationEdit& edit, const Project* base = nullptr);
    // The same with the base state's digest computed beforehand (the project has changed since,
    // e.g. by a processor run).
    Status append(const AnnotationEdit& edit, const QByteArray& baseDigest);
    // After a successful save: the file has everything.
    void discard();

private:
    QFile file_;
};

}  // namespace athlos
