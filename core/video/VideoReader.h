#pragma once
// Frame-accurate random access to a video file through OpenCV's FFmpeg backend.
//
// Frame index i is the frame whose presentation time, relative to the first frame, is i / fps
// (constant frame rate). Seeking by CAP_PROP_POS_FRAMES alone can land on a neighbouring frame in
// long-GOP (inter-coded) video, so every seek is verified against the decoded frame's timestamp
// and, if it missed, repeated from an earlier keyframe and decoded forward (see frameAt()).
// Consecutive and short forward requests (playback) never seek: they just decode on.
//
// Use from one thread at a time (a worker thread); calls are serialised by an internal mutex.
#include "core/util/Expected.h"

#include <QString>
#include <memory>
#include <mutex>

namespace cv {
class Mat;
class VideoCapture;
}  // namespace cv

namespace athlos {

struct VideoFrame {
    long long index = -1;
    double time = 0;  // s, presentation time of the frame (index / fps)
    int width = 0, height = 0;
    std::shared_ptr<const unsigned char[]> bgr;  // width*height*3 bytes, BGR, rows packed
    const unsigned char* pixel(int x, int y) const { return bgr.get() + (std::size_t(y) * width + x) * 3; }
};

struct VideoInfo {
    QString file;
    QString codec;   // FourCC as text, e.g. "avc1", "MJPG"
    double fps = 0;  // frames per second (the stream's, or the override)
    long long frames = 0;
    int width = 0, height = 0;
    double duration() const { return fps > 0 ? double(frames) / fps : 0.0; }
};

class VideoReader {
public:
    struct Params {
        double fpsOverride = 0;     // > 0: use instead of the container's frame rate
        int maxForwardDecode = 48;  // decode on instead of seeking when at most this far ahead
    };

    // Limits of what is accepted as a video (a damaged header must not allocate gigabytes).
    static constexpr int kMaxFrameSide = 8192;                  // pixels
    static constexpr long long kMaxFrames = 24LL * 3600 * 240;  // a day at 240 fps

    // Opens path. Errors name the file: missing, not a video, no decoder for the codec (naming the
    // FourCC), zero frames, implausible sizes; a file that crashes or hangs FFmpeg (checked in a
    // child process first) is refused.
    static Expected<std::unique_ptr<VideoReader>> open(const QString& path, const Params& params);
    static Expected<std::unique_ptr<VideoReader>> open(const QString& path) { return open(path, Params{}); }
    ~VideoReader();
    VideoReader(const VideoReader&) = delete;
    VideoReader& operator=(const VideoReader&) = delete;

    const VideoInfo& info() const { return info_; }
    // The frame shown at time t (s, video clock): floor(t * fps); -1 outside [0, duration).
    long long indexAtTime(double seconds) const;

    Expected<VideoFrame> frameAt(long long index);
    Expected<VideoFrame> frameAtTime(double seconds);

    // Statistics for tests and measurements: how many seeks and decoded frames so far.
    long long seekCount() const { return seeks_; }
    long long decodedCount() const { return decoded_; }

private:
    static Expected<std::unique_ptr<VideoReader>> openUnchecked(const QString& path, const Params& params);
    VideoReader() = default;
    // Index of the frame last grabbed, from its timestamp; -1 if unknown.
    long long grabbedIndex() const;
    bool grab();
    Status seekTo(long long index);
    Expected<VideoFrame> retrieve(long long index);

    std::mutex mutex_;
    std::unique_ptr<cv::VideoCapture> capture_;
    Params params_;
    VideoInfo info_;
    double streamFps_ = 0;    // the container's rate: timestamps are converted with it
    long long current_ = -1;  // index of the frame last grabbed (-1: none yet)
    long long seeks_ = 0, decoded_ = 0;
};

// Silences FFmpeg's own log output (before the first capture or writer is opened).
void quietFfmpeg();

}  // namespace athlos
