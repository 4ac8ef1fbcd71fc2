#include "core/store/ProjectFile.h"

#include "core/store/Hdf5Util.h"
#include "core/store/VerifiedFiles.h"
#include "core/util/IsolatedRun.h"
#include "core/util/Version.h"

#include <QDateTime>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <map>
#include <new>

namespace athlos {
namespace {

using h5::Failure;
using h5::Handle;

struct Cancelled {};

QString streamGroup(const QString& recording, const QString& item) {
    return QStringLiteral("/recordings/%1/%2").arg(recording, item);
}

Stream::Loader loaderFor(const QString& file, const QString& group, int columns) {
    return [file, group, columns] { return ProjectFile::loadStream(file, group, columns); };
}

QString optionalString(hid_t object, const char* name) {
    return h5::hasAttribute(object, name) ? h5::readString(object, name) : QString();
}

QString nowUtc() { return QDateTime::currentDateTimeUtc().toString(Qt::ISODate); }

// Reading ---------------------------------------------------------------------------------------

StreamInfo readStreamInfo(hid_t group, const QString& name) {
    StreamInfo info;
    info.name = name;
    info.kind = h5::readString(group, "kind");
    info.frame = optionalString(group, "frame");
    for (const auto& value : h5::readJsonArray(group, "columns")) {
        const QJsonObject column = value.toObject();
        info.columns.push_back(
            {column.value(QStringLiteral("name")).toString(), column.value(QStringLiteral("unit")).toString()});
    }
    info.attributes = h5::readJsonObject(group, "attributes");
    info.provenance = Provenance::fromJson(h5::readJsonObject(group, "provenance"));
    info.rows = h5::readInt(group, "rows");
    info.tBegin = h5::readDouble(group, "t_begin");
    info.tEnd = h5::readDouble(group, "t_end");
    info.contentHash = h5::readString(group, "content_hash").toLatin1();
    // Shapes only (no samples): a damaged file is refused at open, not at some later plot.
    h5::checkSampleExtents(group, info.rows, static_cast<int>(info.columns.size()));
    return info;
}

Table readTable(hid_t group, const QString& name) {
    Table table;
    table.name = name;
    table.kind = optionalString(group, "kind");
    table.attributes = h5::readJsonObject(group, "attributes");
    table.provenance = Provenance::fromJson(h5::readJsonObject(group, "provenance"));
    table.columns = h5::readTableColumns(group);
    return table;
}

Annotations readAnnotations(hid_t group) {
    const QStringList labels = h5::readTextColumn(group, QStringLiteral("label"));
    const QStringList annotators = h5::readTextColumn(group, QStringLiteral("annotator"));
    const QStringList sources = h5::readTextColumn(group, QStringLiteral("source"));
    const auto starts = h5::readNumberColumn(group, QStringLiteral("t_start"));
    const auto ends = h5::readNumberColumn(group, QStringLiteral("t_end"));
    const auto confidences = h5::readNumberColumn(group, QStringLiteral("confidence"));
    const std::size_t n = std::size_t(labels.size());
    if (std::size_t(annotators.size()) != n || std::size_t(sources.size()) != n || starts.size() != n ||
        ends.size() != n || confidences.size() != n)
        throw Failure{h5::objectPath(group) + QStringLiteral(" is inconsistent: its columns differ in length")};
    Annotations annotations(n);
    for (std::size_t i = 0; i < n; ++i)
        annotations[i] = {labels[qsizetype(i)],     starts[i],      ends[i],
                          annotators[qsizetype(i)], confidences[i], sources[qsizetype(i)]};
    return annotations;
}

struct Contents {
    ProjectMeta meta;
    std::map<QString, Recording> recordings;
    std::map<QString, QJsonObject> geometry;
    QStringList annotationClasses;
    QJsonArray pipelines;
    std::map<QString, TrainedModel> models;
};

Contents readContents(hid_t file, const QString& path, int formatVersion) {
    Contents c;
    c.meta.formatVersion = formatVersion;
    c.meta.appVersion = optionalString(file, "app_version");
    c.meta.created = optionalString(file, "created");
    c.meta.modified = optionalString(file, "modified");
    c.meta.sport = optionalString(file, "sport");
    c.meta.extra = h5::readJsonObject(file, "extra");
    for (const auto& value : h5::readJsonArray(file, "annotation_classes")) c.annotationClasses << value.toString();
    c.pipelines = h5::readJsonArray(file, "pipelines");

    if (h5::hasChild(file, QStringLiteral("geometry"))) {
        Handle geometry = h5::openGroup(file, QStringLiteral("geometry"));
        for (const QString& name : h5::childNames(geometry))
            c.geometry[name] = h5::readJsonObject(h5::openGroup(geometry, name), "json");
    }
    if (h5::hasChild(file, QStringLiteral("recordings"))) {
        Handle recordings = h5::openGroup(file, QStringLiteral("recordings"));
        for (const QString& recName : h5::childNames(recordings)) {
            Handle recGroup = h5::openGroup(recordings, recName);
            Recording& rec = c.recordings[recName];
            rec.name = recName;
            rec.metadata = h5::readJsonObject(recGroup, "metadata");
            for (const QString& item : h5::childNames(recGroup)) {
                Handle group = h5::openGroup(recGroup, item);
                const QString type = h5::readString(group, "type");
                if (type == QLatin1String("stream")) {
                    StreamInfo info = readStreamInfo(group, item);
                    const QString where = streamGroup(recName, item);
                    const int columns = static_cast<int>(info.columns.size());
                    rec.streams.emplace(
                        item, Stream(std::move(info), FileSource{path, where}, loaderFor(path, where, columns)));
                } else if (type == QLatin1String("table")) {
                    rec.tables.emplace(item, readTable(group, item));
                } else {
                    throw Failure{QStringLiteral("%1 has unknown type '%2'").arg(h5::objectPath(group), type)};
                }
            }
        }
    }
    if (h5::hasChild(file, QStringLiteral("models"))) {
        Handle models = h5::openGroup(file, QStringLiteral("models"));
        for (const QString& name : h5::childNames(models)) {
            Handle group = h5::openGroup(models, name);
            TrainedModel model;
            model.name = name;
            model.format = h5::readString(group, "format");
            model.description = h5::readJsonObject(group, "description");
            model.definition = h5::readText(group, QStringLiteral("definition"), TrainedModel::kMaxDefinitionBytes);
            c.models.emplace(name, std::move(model));
        }
    }
    if (h5::hasChild(file, QStringLiteral("annotations"))) {
        Handle annotations = h5::openGroup(file, QStringLiteral("annotations"));
        for (const QString& recName : h5::childNames(annotations)) {
            Recording& rec = c.recordings[recName];
            rec.name = recName;
            rec.annotations = readAnnotations(h5::openGroup(annotations, recName));
        }
    }
    return c;
}

// Opens file and reads what ProjectFile::read needs; with allSamples also every stream's samples
// (which verifies their Fletcher32 checksums). The caller holds the HDF5 lock. Throws Failure.
Contents readProject(const QString& file, bool allSamples) {
    const htri_t isHdf5 = H5Fis_hdf5(QFile::encodeName(file).constData());
    if (isHdf5 == 0) throw Failure{QStringLiteral("not an HDF5 file, so not an Athlos project")};
    if (isHdf5 < 0) throw Failure{QStringLiteral("the file cannot be read (HDF5: %1)").arg(h5::libraryMessage())};
    Handle handle = h5::tryOpenFileReadOnly(file);
    if (!handle.valid())
        throw Failure{QStringLiteral("the file is damaged or truncated (HDF5: %1)").arg(h5::libraryMessage())};
    if (!h5::hasAttribute(handle, "format"))
        throw Failure{QStringLiteral("an HDF5 file, but not an Athlos project (it has no 'format' attribute)")};
    if (const QString format = h5::readString(handle, "format"); format != QLatin1String("athlos"))
        throw Failure{QStringLiteral("an HDF5 file, but not an Athlos project (format '%1')").arg(format.left(64))};
    const long long version = h5::readInt(handle, "format_version");
    if (version > Project::kFormatVersion)
        throw Failure{QStringLiteral("it was written by a newer Athlos (format version %1; this build reads up to %2)")
                          .arg(version)
                          .arg(Project::kFormatVersion)};
    if (version < 1) throw Failure{QStringLiteral("invalid format version %1").arg(version)};
    Contents c = readContents(handle, file, static_cast<int>(version));
    if (allSamples) {
        for (const auto& [recName, rec] : c.recordings)
            for (const auto& [name, stream] : rec.streams)
                h5::readSamples(h5::openGroup(handle, streamGroup(recName, name)),
                                static_cast<int>(stream.info().columns.size()));
    }
    return c;
}

// libhdf5 parses damaged metadata without bounds checks (a fuzzed file crashed it in H5HG_read), so
// a file this process has not checked or written is first read completely in a child process;
// only when that succeeds is it opened here. The caller holds the HDF5 lock (so no other thread is
// inside the library when the child is forked).
Status checkInIsolation(const QString& file) {
    if (VerifiedFiles::contains(file)) return {};
    const long long size = VerifiedFiles::sizeOf(file);
    Status status = runIsolated(
        QStringLiteral("the file"),
        [&]() -> Status {
            try {
                readProject(file, true);
                return {};
            } catch (const Failure& failure) {
                return makeError(failure.message);
            }
        },
        IsolatedRunParams{isolatedTimeoutFor(size), 0});
    if (status) VerifiedFiles::remember(file);
    return status;
}

// Writing ---------------------------------------------------------------------------------------

// What write() does with each stream, decided before taking the HDF5 lock: Stream::data() holds the
// stream's mutex while its loader takes the HDF5 lock, so calling it under that lock could deadlock
// against a worker thread that is loading the same stream.
struct StreamPlan {
    QString recording;
    QString name;
    StreamInfo info;
    std::shared_ptr<const StreamData> data;  // write these samples ...
    std::optional<FileSource> source;        // ... or copy the datasets from here, undecoded
};

class Tracker {
public:
    Tracker(const Progress& progress, double totalBytes) : progress_(progress), total_(totalBytes) {}
    void advance(double bytes, const QString& message) {
        done_ += bytes;
        progress_.report(total_ > 0 ? std::min(1.0, done_ / total_) : 1.0, message);
        if (progress_.isCancelled()) throw Cancelled{};
    }

private:
    const Progress& progress_;
    double total_;
    double done_ = 0;
};

double sampleBytes(const StreamInfo& info) { return 8.0 * double(info.rows) * double(info.columns.size() + 1); }

void writeRoot(hid_t file, const Project& project) {
    const ProjectMeta& meta = project.meta();
    const QString now = nowUtc();
    h5::writeString(file, "format", QStringLiteral("athlos"));
    h5::writeInt(file, "format_version", Project::kFormatVersion);
    h5::writeString(file, "app_version", meta.appVersion.isEmpty() ? appVersion() : meta.appVersion);
    h5::writeString(file, "created", meta.created.isEmpty() ? now : meta.created);
    h5::writeString(file, "modified", meta.modified.isEmpty() ? now : meta.modified);
    h5::writeString(file, "sport", meta.sport);
    h5::writeJson(file, "extra", meta.extra);
    h5::writeJson(file, "annotation_classes", QJsonArray::fromStringList(project.annotationClasses()));
    h5::writeJson(file, "pipelines", project.pipelineHistory());
}

void writeItemAttributes(hid_t group, const char* type, const QString& kind, const QJsonObject& attributes,
                         const Provenance& provenance) {
    h5::writeString(group, "type", QString::fromLatin1(type));
    h5::writeString(group, "kind", kind);
    h5::writeJson(group, "attributes", attributes);
    h5::writeJson(group, "provenance", provenance.toJson());
}

void writeAnnotations(hid_t parent, const QString& recording, const Annotations& annotations) {
    QStringList labels, annotators, sources;
    std::vector<double> starts, ends, confidences;
    for (const Annotation& a : annotations) {
        labels << a.label;
        annotators << a.annotator;
        sources << a.source;
        starts.push_back(a.tStart);
        ends.push_back(a.tEnd);
        confidences.push_back(a.confidence);
    }
    Handle group = h5::createGroup(parent, recording);
    h5::writeTextColumn(group, QStringLiteral("label"), labels);
    h5::writeNumberColumn(group, QStringLiteral("t_start"), starts);
    h5::writeNumberColumn(group, QStringLiteral("t_end"), ends);
    h5::writeTextColumn(group, QStringLiteral("annotator"), annotators);
    h5::writeNumberColumn(group, QStringLiteral("confidence"), confidences);
    h5::writeTextColumn(group, QStringLiteral("source"), sources);
}

class SourceFiles {
public:
    hid_t open(const QString& file) {
        auto it = files_.find(file);
        if (it == files_.end()) {
            if (Status checked = checkInIsolation(file); !checked)
                throw Failure{
                    QStringLiteral("cannot read unloaded streams from '%1': %2").arg(file, checked.message())};
            try {
                it = files_.emplace(file, h5::openFileReadOnly(file)).first;
            } catch (const Failure& f) {
                throw Failure{QStringLiteral("cannot read unloaded streams from '%1': %2").arg(file, f.message)};
            }
        }
        return it->second;
    }

private:
    std::map<QString, Handle> files_;
};

void writeStream(hid_t recGroup, const StreamPlan& plan, SourceFiles& sources, Tracker& tracker) {
    const QString message = QStringLiteral("Saving %1/%2").arg(plan.recording, plan.name);
    const int columns = static_cast<int>(plan.info.columns.size());
    StreamInfo info = plan.info;
    if (plan.data) {
        // The samples are the truth; the info may lag behind for streams built by hand.
        const StreamData& d = *plan.data;
        if (d.columns != columns)
            throw Failure{QStringLiteral("stream %1/%2 has %3 columns of samples but names %4")
                              .arg(plan.recording, plan.name)
                              .arg(d.columns)
                              .arg(columns)};
        info.rows = static_cast<long long>(d.rows());
        info.tBegin = d.t.empty() ? 0.0 : d.t.front();
        info.tEnd = d.t.empty() ? 0.0 : d.t.back();
        if (info.contentHash.isEmpty()) info.contentHash = d.contentHash();
    }
    Handle group = h5::createGroup(recGroup, plan.name);
    writeItemAttributes(group, "stream", info.kind, info.attributes, info.provenance);
    h5::writeString(group, "frame", info.frame);
    QJsonArray described;
    for (const Column& c : info.columns)
        described.append(QJsonObject{{QStringLiteral("name"), c.name}, {QStringLiteral("unit"), c.unit}});
    h5::writeJson(group, "columns", described);
    h5::writeInt(group, "rows", info.rows);
    h5::writeDouble(group, "t_begin", info.tBegin);
    h5::writeDouble(group, "t_end", info.tEnd);
    h5::writeString(group, "content_hash", QString::fromLatin1(info.contentHash));

    if (plan.data) {
        const double bytesPerRow = 8.0 * (columns + 1);
        h5::writeSamples(group, *plan.data, [&](long long rows) { tracker.advance(rows * bytesPerRow, message); });
        return;
    }
    // H5Ocopy moves the compressed chunks as they are; it cannot be interrupted, so cancellation is
    // polled between streams here.
    const hid_t sourceFile = sources.open(plan.source->file);
    Handle sourceGroup = h5::openGroup(sourceFile, plan.source->group);
    h5::checkSampleExtents(sourceGroup, info.rows, columns);
    h5::copyObject(sourceGroup, QStringLiteral("t"), group, QStringLiteral("t"));
    h5::copyObject(sourceGroup, QStringLiteral("data"), group, QStringLiteral("data"));
    tracker.advance(sampleBytes(info), message);
}

void writeFile(hid_t file, const Project& project, const std::vector<StreamPlan>& plans, Tracker& tracker) {
    writeRoot(file, project);
    {
        Handle geometry = h5::createGroup(file, QStringLiteral("geometry"));
        for (const auto& [name, json] : project.geometry())
            h5::writeJson(h5::createGroup(geometry, name), "json", json);
    }
    Handle recordings = h5::createGroup(file, QStringLiteral("recordings"));
    Handle annotations = h5::createGroup(file, QStringLiteral("annotations"));
    std::map<QString, Handle> recGroups;
    for (const auto& [recName, rec] : project.recordings()) {
        Handle recGroup = h5::createGroup(recordings, recName);
        h5::writeJson(recGroup, "metadata", rec.metadata);
        for (const auto& [name, table] : rec.tables) {
            Handle group = h5::createGroup(recGroup, name);
            writeItemAttributes(group, "table", table.kind, table.attributes, table.provenance);
            h5::writeTableColumns(group, table);
        }
        if (!rec.annotations.empty()) writeAnnotations(annotations, recName, rec.annotations);
        recGroups.emplace(recName, std::move(recGroup));
    }
    if (!project.models().empty()) {
        Handle models = h5::createGroup(file, QStringLiteral("models"));
        for (const auto& [name, model] : project.models()) {
            Handle group = h5::createGroup(models, name);
            h5::writeString(group, "format", model.format);
            h5::writeJson(group, "description", model.description);
            h5::writeText(group, QStringLiteral("definition"), model.definition);
        }
    }
    SourceFiles sources;
    for (const StreamPlan& plan : plans) writeStream(recGroups.at(plan.recording), plan, sources, tracker);
}

}  // namespace

Status ProjectFile::read(const QString& path, Project& project) {
    const QFileInfo fileInfo(path);
    auto refuse = [&](const QString& why) -> Status {
        return makeError(QStringLiteral("cannot open project '%1': %2").arg(QDir::toNativeSeparators(path), why));
    };
    if (!fileInfo.exists()) return refuse(QStringLiteral("the file does not exist"));
    if (!fileInfo.isFile()) return refuse(QStringLiteral("not a file"));
    const QString file = fileInfo.absoluteFilePath();

    auto guard = h5::lock();
    if (Status checked = checkInIsolation(file); !checked) return refuse(checked.message());
    try {
        Contents c = readProject(file, false);
        project.meta() = std::move(c.meta);
        project.recordings() = std::move(c.recordings);
        project.geometry() = std::move(c.geometry);
        project.annotationClasses() = std::move(c.annotationClasses);
        project.pipelineHistory() = std::move(c.pipelines);
        project.models() = std::move(c.models);
        return {};
    } catch (const Failure& failure) {
        return refuse(failure.message);
    } catch (const std::bad_alloc&) {
        return refuse(QStringLiteral("out of memory (is the file damaged?)"));
    }
}

Status ProjectFile::check(const QString& path) {
    const QString file = QFileInfo(path).absoluteFilePath();
    auto guard = h5::lock();
    if (Status checked = checkInIsolation(file); !checked)
        return makeError(QStringLiteral("'%1': %2").arg(QDir::toNativeSeparators(path), checked.message()));
    return {};
}

Status ProjectFile::write(const Project& project, const QString& path, const Progress& progress) {
    const QString target = QFileInfo(path).absoluteFilePath();
    const QString targetCanonical = QFileInfo(target).canonicalFilePath();  // empty if it does not exist yet
    auto refuse = [&](const QString& why) -> Status {
        return makeError(QStringLiteral("cannot save project to '%1': %2").arg(QDir::toNativeSeparators(path), why));
    };

    std::vector<StreamPlan> plans;
    double totalBytes = 0;
    for (const auto& [recName, rec] : project.recordings()) {
        for (const auto& [name, stream] : rec.streams) {
            StreamPlan plan{recName, name, stream.info(), nullptr, std::nullopt};
            // Streams of a version-1 file are decoded and rewritten, so that they gain checksums.
            if (!stream.isLoaded() && stream.fileSource() && project.meta().formatVersion >= 2) {
                plan.source = stream.fileSource();
                if (!targetCanonical.isEmpty() && QFileInfo(plan.source->file).canonicalFilePath() == targetCanonical)
                    return refuse(QStringLiteral("stream %1/%2 is read from that very file; save to another file")
                                      .arg(recName, name));
            } else {
                auto data = stream.data();
                if (!data) return refuse(QStringLiteral("stream %1/%2: %3").arg(recName, name, data.message()));
                plan.data = std::move(data).value();
            }
            totalBytes += sampleBytes(plan.info);
            plans.push_back(std::move(plan));
        }
    }

    auto guard = h5::lock();
    bool created = false;
    try {
        if (progress.isCancelled()) throw Cancelled{};
        Tracker tracker(progress, totalBytes);
        Handle file = h5::createFile(target);
        created = true;
        writeFile(file, project, plans, tracker);
        file.close(QStringLiteral("cannot finish writing the file"));
        progress.report(1.0, QStringLiteral("Saved"));
        return {};
    } catch (const Cancelled&) {
        if (created) QFile::remove(target);
        return makeError(QStringLiteral("cancelled"));
    } catch (const Failure& failure) {
        if (created) QFile::remove(target);
        return refuse(failure.message);
    } catch (const std::exception& e) {
        if (created) QFile::remove(target);
        return refuse(QString::fromLocal8Bit(e.what()));
    }
}

void ProjectFile::rebind(Project& project, const QString& path) {
    const QString file = QFileInfo(path).absoluteFilePath();
    VerifiedFiles::remember(file);  // written by this process
    for (auto& [recName, rec] : project.recordings()) {
        for (auto& [name, stream] : rec.streams) {
            const QString group = streamGroup(recName, name);
            stream.rebind(FileSource{file, group},
                          loaderFor(file, group, static_cast<int>(stream.info().columns.size())));
        }
    }
}

Expected<StreamData> ProjectFile::loadStream(const QString& file, const QString& group, int columns) {
    auto guard = h5::lock();
    if (Status checked = checkInIsolation(file); !checked)
        return makeError(QStringLiteral("cannot load %1 from '%2': %3")
                             .arg(group, QDir::toNativeSeparators(file), checked.message()));
    try {
        Handle handle = h5::openFileReadOnly(file);
        Handle streamGroup = h5::openGroup(handle, group);
        return h5::readSamples(streamGroup, columns);
    } catch (const Failure& failure) {
        return makeError(
            QStringLiteral("cannot load %1 from '%2': %3").arg(group, QDir::toNativeSeparators(file), failure.message));
    } catch (const std::bad_alloc&) {
        return makeError(
            QStringLiteral("cannot load %1 from '%2': out of memory").arg(group, QDir::toNativeSeparators(file)));
    }
}

}  // namespace athlos
