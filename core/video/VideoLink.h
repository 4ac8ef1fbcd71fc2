#pragma once
// A recording's attached video, stored in the recording's metadata (saved with the project):
//
//   metadata.video = { "path": "clips/run.mp4",            relative to the project file's folder
//                      "absolute_path": "/data/clips/run.mp4",   fallback when the project moved
//                      "offset_s": 12.345,
//                      "fps_override": 240 }              optional (slow-motion files)
//
// Time convention: t_recording = t_video + offset. A video frame shown at video time tv belongs to
// recording time tv + offset; the cursor at recording time t shows the video frame at t − offset.
#include "core/util/Expected.h"

#include <QString>
#include <optional>

namespace athlos {

class Project;
struct Recording;

struct VideoLink {
    QString storedPath;      // as stored (relative to the project folder when possible)
    QString absolutePath;    // where it was when attached
    double offset = 0;       // s, t_recording = t_video + offset
    double fpsOverride = 0;  // > 0: use instead of the file's frame rate

    double recordingTime(double videoTime) const { return videoTime + offset; }
    double videoTime(double recordingTime) const { return recordingTime - offset; }

    // The offset that makes a video event at videoTime coincide with the same event at
    // recordingTime in the signals (e.g. a clap seen in the video and its acceleration spike).
    static double offsetFromEvent(double videoTime, double recordingTime) { return recordingTime - videoTime; }

    // The link of recording, or nothing.
    static std::optional<VideoLink> of(const Recording& recording);
    static std::optional<VideoLink> of(const Project& project, const QString& recording);
    // The first recording (by name) that has a video, or empty.
    static QString firstLinkedRecording(const Project& project);

    // Opens the file (the link is only made for a readable video) and stores the link in the
    // recording's metadata, replacing an earlier one. Marks the project modified.
    static Expected<VideoLink> attach(Project& project, const QString& recording, const QString& file,
                                      double offset = 0, double fpsOverride = 0);
    // Removes the link; false if there was none.
    static bool detach(Project& project, const QString& recording);
    // Changes the offset of an existing link; error if the recording has no video.
    static Status setOffset(Project& project, const QString& recording, double offset);

    // The file on disk: the stored path relative to the project's folder, else the absolute
    // path. A moved or missing video is an error naming both places; the link stays as it is.
    static Expected<QString> resolve(const Project& project, const QString& recording);
};

}  // namespace athlos
