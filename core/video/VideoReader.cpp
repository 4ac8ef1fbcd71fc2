#include "core/video/VideoReader.h"

#include "core/util/IsolatedRun.h"

#include "core/video/VideoContainerProbe.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace athlos {

namespace {

QString fourccText(double value) {
    const auto f = static_cast<unsigned>(static_cast<long long>(value));
    QString s;
    for (int k = 0; k < 4; ++k) {
        const char c = char((f >> (8 * k)) & 0xFF);
        if (c >= 32 && c < 127) s += QLatin1Char(c);
    }
    return s.trimmed();
}

}  // namespace

void quietFfmpeg() {
    // OpenCV sets FFmpeg's log level from this variable when it first loads FFmpeg (default:
    // errors, e.g. "moov atom not found" for a damaged file). Our errors already say what went
    // wrong in one line, so FFmpeg stays quiet unless the user asked for its messages.
    if (!qEnvironmentVariableIsSet("OPENCV_FFMPEG_LOGLEVEL") && !qEnvironmentVariableIsSet("OPENCV_FFMPEG_DEBUG"))
        qputenv("OPENCV_FFMPEG_LOGLEVEL", "-8");  // AV_LOG_QUIET
}

VideoReader::~VideoReader() = default;

Expected<std::unique_ptr<VideoReader>> VideoReader::open(const QString& path, const Params& params) {
    const QFileInfo fileInfo(path);
    if (!fileInfo.exists())
        return makeError(QCoreApplication::translate("athlos::VideoReader", "video '%1' does not exist").arg(path));
    if (!fileInfo.isFile() || !fileInfo.isReadable())
        return makeError(
            QCoreApplication::translate("athlos::VideoReader", "video '%1' is not a readable file").arg(path));
    // FFmpeg's demuxers and decoders parse untrusted bytes: a damaged file is first opened, and its
    // first, middle and last frames decoded, in a child process, so a crash or hang there is a
    // refusal here. Then the same open runs in this process.
    Status checked = runIsolated(
        QCoreApplication::translate("athlos::VideoReader", "video '%1'").arg(path),
        [&]() -> Status {
            auto reader = openUnchecked(path, params);
            if (!reader) return reader.error();
            // Only a crash or a hang matters here: the frame count of some containers is an
            // estimate, so a frame that cannot be decoded is the reader's business later.
            const long long frames = (*reader)->info().frames;
            for (const long long index : {frames / 2, frames - 1}) (void)(*reader)->frameAt(index);
            return {};
        },
        IsolatedRunParams{isolatedTimeoutFor(fileInfo.size(), std::chrono::seconds(30)), 0});
    if (!checked) return checked.error();
    return openUnchecked(path, params);
}

Expected<std::unique_ptr<VideoReader>> VideoReader::openUnchecked(const QString& path, const Params& params) {
    const QFileInfo fileInfo(path);

    quietFfmpeg();
    // OpenCV reports a failed open on stderr as well; the error below says it in one line.
    const auto previousLevel = cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    std::unique_ptr<VideoReader> reader(new VideoReader);
    reader->params_ = params;
    reader->capture_ = std::make_unique<cv::VideoCapture>();
    bool opened = false;
    try {
        opened = reader->capture_->open(path.toStdString(), cv::CAP_FFMPEG);
    } catch (const cv::Exception&) {
        opened = false;
    }
    cv::utils::logging::setLogLevel(previousLevel);

    const ContainerProbe probe = probeContainer(path);
    if (!opened) {
        if (!probe.isVideoContainer)
            return makeError(QCoreApplication::translate(
                                 "athlos::VideoReader",
                                 "'%1' is not a video file (no known container format; FFmpeg cannot open it)")
                                 .arg(path));
        if (!probe.codec.isEmpty())
            return makeError(QCoreApplication::translate(
                                 "athlos::VideoReader",
                                 "'%1': this FFmpeg build has no decoder for the video codec '%2' (%3); convert the "
                                 "video, e.g. to H.264 or MJPEG")
                                 .arg(path, probe.codec, probe.container));
        return makeError(
            QCoreApplication::translate("athlos::VideoReader",
                                        "'%1': FFmpeg cannot open this %2 file (damaged, or no decoder for its codec)")
                .arg(path, probe.container));
    }

    VideoInfo& info = reader->info_;
    info.file = fileInfo.absoluteFilePath();
    info.codec = fourccText(reader->capture_->get(cv::CAP_PROP_FOURCC));
    if (info.codec.isEmpty()) info.codec = probe.codec;
    reader->streamFps_ = reader->capture_->get(cv::CAP_PROP_FPS);
    info.fps = params.fpsOverride > 0 ? params.fpsOverride : reader->streamFps_;
    info.frames = static_cast<long long>(std::llround(reader->capture_->get(cv::CAP_PROP_FRAME_COUNT)));
    info.width = int(reader->capture_->get(cv::CAP_PROP_FRAME_WIDTH));
    info.height = int(reader->capture_->get(cv::CAP_PROP_FRAME_HEIGHT));
    if (!(reader->streamFps_ > 0) || !std::isfinite(reader->streamFps_))
        return makeError(
            QCoreApplication::translate("athlos::VideoReader", "'%1': the video stream has no frame rate").arg(path));
    if (info.frames <= 0)
        return makeError(QCoreApplication::translate("athlos::VideoReader", "'%1': the video has no frames").arg(path));
    if (info.width <= 0 || info.height <= 0 || info.width > kMaxFrameSide || info.height > kMaxFrameSide)
        return makeError(
            QCoreApplication::translate("athlos::VideoReader", "'%1': frame size %2×%3 is outside 1…%4 pixels per side")
                .arg(path)
                .arg(info.width)
                .arg(info.height)
                .arg(kMaxFrameSide));
    if (info.frames > kMaxFrames)
        return makeError(QCoreApplication::translate("athlos::VideoReader",
                                                     "'%1': %2 frames is more than a recording can have (limit %3)")
                             .arg(path)
                             .arg(info.frames)
                             .arg(kMaxFrames));
    // The first frame must decode: a stream FFmpeg can open but not decode fails here.
    if (!reader->grab())
        return makeError(QCoreApplication::translate(
                             "athlos::VideoReader",
                             "'%1': the first frame of the '%2' video stream cannot be decoded (no working decoder in "
                             "this FFmpeg build, or a damaged file)")
                             .arg(path, info.codec));
    reader->current_ = 0;
    return reader;
}

long long VideoReader::indexAtTime(double seconds) const {
    if (!std::isfinite(seconds) || seconds < 0) return -1;
    // A tolerance of 1e-6 frame: a time computed as index / fps maps back to that index.
    const auto index = static_cast<long long>(std::floor(seconds * info_.fps + 1e-6));
    return index < info_.frames ? index : -1;
}

bool VideoReader::grab() {
    try {
        if (!capture_->grab()) return false;
    } catch (const cv::Exception&) {
        return false;
    }
    ++decoded_;
    return true;
}

long long VideoReader::grabbedIndex() const {
    // The presentation time of the grabbed frame (FFmpeg's best-effort timestamp relative to the
    // stream start), which is independent of OpenCV's own frame counter.
    const double ms = capture_->get(cv::CAP_PROP_POS_MSEC);
    return static_cast<long long>(std::llround(ms * 1e-3 * streamFps_));
}

Status VideoReader::seekTo(long long index) {
    // OpenCV seeks to the keyframe before the target and decodes forward, but with B-frames,
    // edit lists or inexact index tables it may stop a frame early or late. So: seek, check the
    // decoded frame's timestamp, decode forward to the target; if the seek overshot, start again
    // further back (doubling), finally from the very beginning.
    long long backoff = 0;
    for (int attempt = 0; attempt < 8; ++attempt) {
        const long long start = std::max<long long>(0, index - backoff);
        ++seeks_;
        bool ok = false;
        try {
            ok = capture_->set(cv::CAP_PROP_POS_FRAMES, double(start));
        } catch (const cv::Exception&) {
            ok = false;
        }
        // The frames the decoder flushes at the end of the stream carry no timestamp (position
        // 0): a frame whose timestamp does not advance is the one after its predecessor.
        long long k = -1;
        if (ok && grab()) k = grabbedIndex();
        if (k == 0 && start > 0) k = -1;  // landed on a frame without timestamp: position unknown
        if (k >= 0) {
            long long previous = -1;
            while (k < index && grab()) {
                previous = k;
                k = std::max(grabbedIndex(), previous + 1);
            }
            // Exact hit, or (variable frame rate) the first frame at or after the target reached
            // by decoding forward from before it.
            if (k == index || (k > index && previous >= 0 && previous < index)) {
                current_ = index;
                return {};
            }
        }
        if (start == 0) break;
        backoff = backoff == 0 ? std::max(16, params_.maxForwardDecode) : backoff * 2;
    }
    // Last resort: reopen and decode from the first frame, counting frames.
    capture_ = std::make_unique<cv::VideoCapture>();
    if (!capture_->open(info_.file.toStdString(), cv::CAP_FFMPEG))
        return makeError(
            QCoreApplication::translate("athlos::VideoReader", "'%1': cannot reopen the video").arg(info_.file));
    ++seeks_;
    for (long long k = 0; k <= index; ++k)
        if (!grab())
            return makeError(QCoreApplication::translate("athlos::VideoReader", "'%1': frame %2 cannot be decoded")
                                 .arg(info_.file)
                                 .arg(index));
    current_ = index;
    return {};
}

Expected<VideoFrame> VideoReader::retrieve(long long index) {
    cv::Mat mat;
    try {
        if (!capture_->retrieve(mat) || mat.empty() || mat.type() != CV_8UC3)
            return makeError(QCoreApplication::translate("athlos::VideoReader", "'%1': frame %2 cannot be decoded")
                                 .arg(info_.file)
                                 .arg(index));
    } catch (const cv::Exception& e) {
        return makeError(QCoreApplication::translate("athlos::VideoReader", "'%1': frame %2 cannot be decoded: %3")
                             .arg(info_.file)
                             .arg(index)
                             .arg(QString::fromStdString(e.what())));
    }
    VideoFrame frame;
    frame.index = index;
    frame.time = double(index) / info_.fps;
    frame.width = mat.cols;
    frame.height = mat.rows;
    const std::size_t rowBytes = std::size_t(mat.cols) * 3;
    std::shared_ptr<unsigned char[]> pixels(new unsigned char[rowBytes * std::size_t(mat.rows)]);
    for (int y = 0; y < mat.rows; ++y) std::memcpy(pixels.get() + rowBytes * std::size_t(y), mat.ptr(y), rowBytes);
    frame.bgr = std::move(pixels);
    return frame;
}

Expected<VideoFrame> VideoReader::frameAt(long long index) {
    std::lock_guard lock(mutex_);
    if (index < 0 || index >= info_.frames)
        return makeError(
            QCoreApplication::translate("athlos::VideoReader", "'%1': frame %2 is outside the video (0..%3)")
                .arg(info_.file)
                .arg(index)
                .arg(info_.frames - 1));
    if (index == current_) return retrieve(index);
    if (current_ >= 0 && index > current_ && index - current_ <= params_.maxForwardDecode) {
        // Playback and short skips: decode on, no seek.
        while (current_ < index) {
            if (!grab()) {
                current_ = -1;
                return makeError(QCoreApplication::translate("athlos::VideoReader",
                                                             "'%1': frame %2 cannot be decoded (the file ends early)")
                                     .arg(info_.file)
                                     .arg(index));
            }
            ++current_;
        }
        return retrieve(index);
    }
    if (Status status = seekTo(index); !status) {
        current_ = -1;
        return status.error();
    }
    return retrieve(index);
}

Expected<VideoFrame> VideoReader::frameAtTime(double seconds) {
    const long long index = indexAtTime(seconds);
    if (index < 0)
        return makeError(
            QCoreApplication::translate("athlos::VideoReader", "'%1': time %2 s is outside the video (0..%3 s)")
                .arg(info_.file)
                .arg(seconds)
                .arg(info_.duration()));
    return frameAt(index);
}

}  // namespace athlos
