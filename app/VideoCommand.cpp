// athlos video <project> <recording> <file> [--offset S] [--fps F] | --detach | --info [--seek-test N]
#include "VideoCommand.h"

#include "CommandParser.h"
#include "Commands.h"

#include "core/model/Project.h"
#include "core/video/FrameCodePattern.h"
#include "core/video/VideoLink.h"
#include "core/video/VideoReader.h"

#include <QElapsedTimer>
#include <cmath>
#include <cstdio>
#include <optional>
#include <random>

namespace athlos::cli {

namespace {

std::optional<double> number(const QString& text) {
    bool ok = false;
    const double value = text.toDouble(&ok);
    return ok && std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

// Random seeks and a sequential run, timed: what scrubbing and playback cost for this file.
void seekTest(VideoReader& reader, int count) {
    const long long frames = reader.info().frames;
    std::mt19937 rng(1);
    std::uniform_int_distribution<long long> any(0, frames - 1);
    double total = 0, worst = 0;
    int done = 0;
    for (int k = 0; k < count; ++k) {
        QElapsedTimer clock;
        clock.start();
        if (!reader.frameAt(any(rng))) break;
        const double ms = double(clock.nsecsElapsed()) * 1e-6;
        total += ms;
        worst = std::max(worst, ms);
        ++done;
    }
    const long long start = std::max<long long>(0, frames / 2 - 50), end = std::min(frames, start + 100);
    (void)reader.frameAt(start);
    QElapsedTimer clock;
    clock.start();
    for (long long i = start + 1; i < end; ++i)
        if (!reader.frameAt(i)) break;
    const double sequential = end - start > 1 ? double(clock.nsecsElapsed()) * 1e-6 / double(end - start - 1) : 0.0;
    std::printf("seek test:  %d random frames, mean %.2f ms, max %.2f ms per frame; sequential %.2f ms per frame\n",
                done, done ? total / done : 0.0, worst, sequential);
}

}  // namespace

int cmdVideo(const QStringList& args) {
    CommandParser p(
        QStringLiteral("video <project> <recording> [<file>] [--offset S] [--fps F] [--detach] [--info]"),
        QStringLiteral("Attach a video file to a recording (checked by opening it), change its offset, detach "
                       "it, or describe it. Time convention: t_recording = t_video + offset. The path is "
                       "stored relative to the project's folder when possible. The project is saved "
                       "atomically."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addPositional(QStringLiteral("recording"), QStringLiteral("Name of the recording."));
    p.addPositional(QStringLiteral("file"), QStringLiteral("Video file to attach (mp4, mov, avi, mkv…)."));
    p.addOption({QStringLiteral("offset"),
                 QStringLiteral("Offset in seconds: t_recording = t_video + offset (default 0, or "
                                "the current one)."),
                 QStringLiteral("S")});
    p.addOption({QStringLiteral("fps"), QStringLiteral("Frame rate to use instead of the file's (slow-motion clips)."),
                 QStringLiteral("F")});
    p.addOption({QStringLiteral("detach"), QStringLiteral("Remove the recording's video link.")});
    p.addOption({QStringLiteral("info"), QStringLiteral("Print file, codec, fps, frames, duration and offset.")});
    p.addOption({QStringLiteral("seek-test"),
                 QStringLiteral("With --info: time N random frame seeks and sequential "
                                "decoding."),
                 QStringLiteral("N")});
    p.addOption({QStringLiteral("write-pattern"),
                 QStringLiteral("Instead: write a test video whose frames show their own "
                                "index as 4×4 binary blocks (MJPG in .avi; --fps, "
                                "--frames) to check frame-accurate display."),
                 QStringLiteral("file")});
    p.addOption({QStringLiteral("frames"), QStringLiteral("With --write-pattern: number of frames (default 300)."),
                 QStringLiteral("N")});
    if (auto code = p.parse(args, 0, 3)) return *code;
    const QCommandLineParser& o = p.parser();
    if (o.isSet(QStringLiteral("write-pattern"))) {
        if (!p.positional().isEmpty()) return fail(QStringLiteral("--write-pattern takes no project"), Usage);
        FrameCodeVideo spec;
        spec.width = 640;
        spec.height = 480;
        bool ok = true;
        if (o.isSet(QStringLiteral("frames"))) spec.frames = o.value(QStringLiteral("frames")).toLongLong(&ok);
        if (!ok || spec.frames <= 0 || spec.frames > 65536)
            return fail(QStringLiteral("--frames '%1': expected 1..65536").arg(o.value(QStringLiteral("frames"))),
                        Usage);
        if (o.isSet(QStringLiteral("fps"))) {
            const auto fps = number(o.value(QStringLiteral("fps")));
            if (!fps || *fps <= 0)
                return fail(
                    QStringLiteral("--fps '%1': expected a positive frame rate").arg(o.value(QStringLiteral("fps"))),
                    Usage);
            spec.fps = *fps;
        }
        if (Status s = writeFrameCodeVideo(o.value(QStringLiteral("write-pattern")), spec); !s)
            return fail(s.message());
        return Ok;
    }
    if (p.positional().size() < 2)
        return fail(QStringLiteral("usage: athlos video <project> <recording> … (see --help)"), Usage);
    const QString projectPath = p.positional()[0];
    const QString recording = p.positional()[1];
    const QString file = p.positional().size() > 2 ? p.positional()[2] : QString();
    const bool detach = o.isSet(QStringLiteral("detach")), info = o.isSet(QStringLiteral("info"));
    if (int(detach) + int(info) + int(!file.isEmpty()) > 1)
        return fail(QStringLiteral("give either a <file>, --detach or --info (see: athlos video --help)"), Usage);
    std::optional<double> offset, fps;
    if (o.isSet(QStringLiteral("offset"))) {
        offset = number(o.value(QStringLiteral("offset")));
        if (!offset)
            return fail(QStringLiteral("--offset '%1': expected seconds").arg(o.value(QStringLiteral("offset"))),
                        Usage);
    }
    if (o.isSet(QStringLiteral("fps"))) {
        fps = number(o.value(QStringLiteral("fps")));
        if (!fps || *fps <= 0)
            return fail(
                QStringLiteral("--fps '%1': expected a positive frame rate").arg(o.value(QStringLiteral("fps"))),
                Usage);
    }
    int seekCount = 0;
    if (o.isSet(QStringLiteral("seek-test"))) {
        bool ok = false;
        seekCount = o.value(QStringLiteral("seek-test")).toInt(&ok);
        if (!ok || seekCount <= 0 || !info)
            return fail(QStringLiteral("--seek-test N: a positive count, with --info"), Usage);
    }
    if ((detach || info) && (offset || fps))
        return fail(QStringLiteral("--offset and --fps go with a <file> or alone"), Usage);

    auto project = info ? Project::open(projectPath) : openForChange(projectPath);
    if (!project) return fail(project.message());
    Project& pr = **project;
    if (!pr.recording(recording))
        return fail(QStringLiteral("no recording '%1' in '%2' (recordings: %3)")
                        .arg(recording, projectPath, pr.recordingNames().join(QStringLiteral(", "))));
    const auto link = VideoLink::of(pr, recording);

    if (info) {
        if (!link) return fail(QStringLiteral("recording '%1' has no video").arg(recording));
        auto path = VideoLink::resolve(pr, recording);
        if (!path) return fail(path.message());
        VideoReader::Params params;
        params.fpsOverride = link->fpsOverride;
        auto reader = VideoReader::open(*path, params);
        if (!reader) return fail(reader.message());
        const VideoInfo& vi = (*reader)->info();
        std::printf(
            "recording:  %s\nfile:       %s\nstored as:  %s\ncodec:      %s\nsize:       %dx%d\nfps:        %.6g%s\n"
            "frames:     %lld\nduration:   %.3f s\noffset:     %.3f s (t_recording = t_video + offset)\n"
            "covers:     %.3f .. %.3f s of the recording\n",
            qUtf8Printable(recording), qUtf8Printable(*path), qUtf8Printable(link->storedPath),
            qUtf8Printable(vi.codec), vi.width, vi.height, vi.fps, link->fpsOverride > 0 ? " (override)" : "",
            vi.frames, vi.duration(), link->offset, link->recordingTime(0), link->recordingTime(vi.duration()));
        if (seekCount > 0) seekTest(**reader, seekCount);
        return Ok;
    }
    if (detach) {
        if (!VideoLink::detach(pr, recording))
            return fail(QStringLiteral("recording '%1' has no video").arg(recording));
    } else if (!file.isEmpty()) {
        auto attached =
            VideoLink::attach(pr, recording, file, offset.value_or(link ? link->offset : 0.0), fps.value_or(0.0));
        if (!attached) return fail(attached.message());
    } else if (offset) {
        if (Status s = VideoLink::setOffset(pr, recording, *offset); !s) return fail(s.message());
    } else {
        return fail(QStringLiteral("usage: athlos video <project> <recording> <file> | --detach | --info | --offset S"),
                    Usage);
    }
    if (Status s = pr.save(); !s) return fail(s.message());
    return Ok;
}

}  // namespace athlos::cli
