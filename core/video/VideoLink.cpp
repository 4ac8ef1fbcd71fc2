#include "core/video/VideoLink.h"

#include "core/model/Project.h"
#include "core/video/VideoReader.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonObject>

#include <cmath>

namespace athlos {

namespace {

const QString kKey = QStringLiteral("video");
const QString kPath = QStringLiteral("path");
const QString kAbsolute = QStringLiteral("absolute_path");
const QString kOffset = QStringLiteral("offset_s");
const QString kFps = QStringLiteral("fps_override");

QDir projectFolder(const Project& project) { return QFileInfo(project.path()).absoluteDir(); }

void store(Recording& recording, const VideoLink& link) {
    QJsonObject json{{kPath, link.storedPath}, {kAbsolute, link.absolutePath}, {kOffset, link.offset}};
    if (link.fpsOverride > 0) json[kFps] = link.fpsOverride;
    recording.metadata[kKey] = json;
}

}  // namespace

std::optional<VideoLink> VideoLink::of(const Recording& recording) {
    const QJsonObject json = recording.metadata.value(kKey).toObject();
    if (json.value(kPath).toString().isEmpty()) return std::nullopt;
    VideoLink link;
    link.storedPath = json.value(kPath).toString();
    link.absolutePath = json.value(kAbsolute).toString();
    link.offset = json.value(kOffset).toDouble();
    link.fpsOverride = json.value(kFps).toDouble();
    return link;
}

std::optional<VideoLink> VideoLink::of(const Project& project, const QString& recording) {
    const Recording* rec = project.recording(recording);
    return rec ? of(*rec) : std::nullopt;
}

QString VideoLink::firstLinkedRecording(const Project& project) {
    for (const auto& [name, recording] : project.recordings())
        if (of(recording)) return name;
    return {};
}

Expected<VideoLink> VideoLink::attach(Project& project, const QString& recording, const QString& file, double offset,
                                      double fpsOverride) {
    Recording* rec = project.recording(recording);
    if (!rec)
        return makeError(
            QCoreApplication::translate("athlos::VideoLink", "no recording '%1' in the project").arg(recording));
    if (!std::isfinite(offset))
        return makeError(
            QCoreApplication::translate("athlos::VideoLink", "video offset must be a finite number of seconds"));
    if (!(fpsOverride >= 0) || !std::isfinite(fpsOverride))
        return makeError(QCoreApplication::translate("athlos::VideoLink",
                                                     "video fps override must be positive (or 0 for the file's rate)"));
    VideoReader::Params params;
    params.fpsOverride = fpsOverride;
    auto reader = VideoReader::open(file, params);
    if (!reader) return reader.error();

    VideoLink link;
    link.absolutePath = QFileInfo(file).absoluteFilePath();
    // Relative to the project's folder, so the project and its videos can move together; a path
    // that leaves the folder's file system root (other drive) stays absolute.
    const QString relative = projectFolder(project).relativeFilePath(link.absolutePath);
    link.storedPath = QDir::isRelativePath(relative) ? relative : link.absolutePath;
    link.offset = offset;
    link.fpsOverride = fpsOverride;
    store(*rec, link);
    project.setModified();
    return link;
}

bool VideoLink::detach(Project& project, const QString& recording) {
    Recording* rec = project.recording(recording);
    if (!rec || !rec->metadata.contains(kKey)) return false;
    rec->metadata.remove(kKey);
    project.setModified();
    return true;
}

Status VideoLink::setOffset(Project& project, const QString& recording, double offset) {
    Recording* rec = project.recording(recording);
    auto link = rec ? of(*rec) : std::nullopt;
    if (!link)
        return makeError(
            QCoreApplication::translate("athlos::VideoLink", "recording '%1' has no video").arg(recording));
    if (!std::isfinite(offset))
        return makeError(
            QCoreApplication::translate("athlos::VideoLink", "video offset must be a finite number of seconds"));
    link->offset = offset;
    store(*rec, *link);
    project.setModified();
    return {};
}

Expected<QString> VideoLink::resolve(const Project& project, const QString& recording) {
    const auto link = of(project, recording);
    if (!link)
        return makeError(
            QCoreApplication::translate("athlos::VideoLink", "recording '%1' has no video").arg(recording));
    const QString fromProject = QDir::isAbsolutePath(link->storedPath)
                                    ? link->storedPath
                                    : QDir::cleanPath(projectFolder(project).absoluteFilePath(link->storedPath));
    if (QFileInfo(fromProject).isFile()) return fromProject;
    if (!link->absolutePath.isEmpty() && QFileInfo(link->absolutePath).isFile()) return link->absolutePath;
    if (link->absolutePath.isEmpty() || link->absolutePath == fromProject)
        return makeError(
            QCoreApplication::translate(
                "athlos::VideoLink", "the video of recording '%1' is missing: '%2' (moved or deleted? attach it again)")
                .arg(recording, fromProject));
    return makeError(QCoreApplication::translate(
                         "athlos::VideoLink",
                         "the video of recording '%1' is missing: neither '%2' nor '%3' exists (moved or deleted? "
                         "attach it again)")
                         .arg(recording, fromProject, link->absolutePath));
}

}  // namespace athlos
