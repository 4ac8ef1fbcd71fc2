#pragma once
// A project: the in-memory working copy of one `.athlos` HDF5 file.
//
// Opening reads the structure and metadata only; stream samples load lazily from the file.
// Every change happens in memory; save() writes a complete new file next to the old one and
// renames it over (atomic). A failed or cancelled operation therefore never touches the file:
// callers simply do not save.
#include "core/model/Recording.h"
#include "core/model/TrainedModel.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <map>
#include <memory>

namespace athlos {

class ProjectLock;

struct ProjectMeta {
    int formatVersion = 1;
    QString appVersion;  // app that last wrote the file
    QString created;     // ISO 8601 UTC
    QString modified;
    QString sport;
    QJsonObject extra;  // free metadata
};

// "rec/stream" split into its parts; a name without '/' has an empty item.
struct ItemPath {
    QString recording;
    QString item;
    static ItemPath parse(const QString& path);
    QString toString() const { return recording + QLatin1Char('/') + item; }
    // Both parts non-empty, not "." or "..", without '/'.
    bool isValid() const;
};

class Project {
public:
    // 2: fixed-length strings, HDF5 1.10 file format (metadata checksums), Fletcher32 on every
    // non-empty dataset. Version-1 files are read and upgraded when saved.
    static constexpr int kFormatVersion = 2;

    // A new, empty project bound to path; nothing is written until save().
    static std::unique_ptr<Project> create(const QString& path, const QString& sport = {});
    // Opens an existing file: structure and metadata only. Refuses newer format versions and
    // damaged files with a message naming the file.
    static Expected<std::unique_ptr<Project>> open(const QString& path);

    // Opens an existing file to change it: takes the project's write lock first (a second writer
    // is refused with a message naming the holder; see ProjectLock), deals with stale temporary
    // files of a killed save (notes()), then opens. The lock is held until the Project is destroyed.
    static Expected<std::unique_ptr<Project>> openForChange(const QString& path);
    // Takes the write lock for this project's path (e.g. for a new project in the GUI).
    Status lockForChange();
    bool holdsLock() const;
    // What opening found and did that the user should know (stale saves recovered or removed).
    const QStringList& notes() const { return notes_; }

    ~Project();
    Project(const Project&) = delete;
    Project& operator=(const Project&) = delete;

    const QString& path() const { return path_; }
    ProjectMeta& meta() { return meta_; }
    const ProjectMeta& meta() const { return meta_; }

    // Atomic save to path() (or to another path, which then becomes path()). Loads any lazy
    // samples it needs from the current file before replacing it.
    Status save(const Progress& progress = {});
    Status saveAs(const QString& path, const Progress& progress = {});
    bool isModified() const { return modified_; }
    void setModified(bool modified = true) { modified_ = modified; }

    // Recordings ------------------------------------------------------------------------
    QStringList recordingNames() const;
    Recording* recording(const QString& name);
    const Recording* recording(const QString& name) const;
    Recording& ensureRecording(const QString& name);
    bool removeRecording(const QString& name);

    // Items addressed as "rec/item" -------------------------------------------------------
    const Stream* stream(const QString& path) const;
    Stream* stream(const QString& path);
    const Table* table(const QString& path) const;
    Table* table(const QString& path);
    // Inserts or replaces; the item's name is taken from path. Marks the project modified.
    void putStream(const QString& path, Stream stream);
    void putTable(const QString& path, Table table);
    bool removeItem(const QString& path);
    // "rec/stream" for every stream and table, sorted.
    QStringList streamPaths() const;
    QStringList tablePaths() const;

    // Venue geometry (tracks, pitches, beacon layouts) as JSON documents, by name.
    std::map<QString, QJsonObject>& geometry() { return geometry_; }
    const std::map<QString, QJsonObject>& geometry() const { return geometry_; }

    // Annotation class set of the project (labels offered by the annotation tool).
    QStringList& annotationClasses() { return annotationClasses_; }
    const QStringList& annotationClasses() const { return annotationClasses_; }

    // Pipelines that were run on this project, in order (each a JSON document with its steps).
    QJsonArray& pipelineHistory() { return pipelineHistory_; }
    const QJsonArray& pipelineHistory() const { return pipelineHistory_; }

    // Trained models (e.g. activity classifiers), by name; always in memory (bounded in size by
    // TrainedModel::kMaxDefinitionBytes), saved with the project.
    std::map<QString, TrainedModel>& models() { return models_; }
    const std::map<QString, TrainedModel>& models() const { return models_; }
    const TrainedModel* model(const QString& name) const;

    // Internal: used by the file store.
    std::map<QString, Recording>& recordings() { return recordings_; }
    const std::map<QString, Recording>& recordings() const { return recordings_; }

private:
    explicit Project(QString path);

    QString path_;
    ProjectMeta meta_;
    std::map<QString, Recording> recordings_;
    std::map<QString, QJsonObject> geometry_;
    QStringList annotationClasses_;
    QJsonArray pipelineHistory_;
    std::map<QString, TrainedModel> models_;
    bool modified_ = false;
    std::unique_ptr<ProjectLock> lock_;
    QStringList notes_;
};

}  // namespace athlos
