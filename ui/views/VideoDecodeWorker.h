#pragma once
// Decodes video frames on its own thread for VideoDock. "Latest request wins": a new request
// replaces one that has not started, so scrubbing never queues up stale frames. Results go to a
// callback on the worker thread (the dock forwards them to the GUI thread).
#include "core/video/VideoReader.h"

#include <QImage>
#include <QString>

#include <atomic>

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

namespace athlos::ui {

class VideoDecodeWorker {
public:
    using Callback = std::function<void(quint64 serial, long long index, const QImage& image, const QString& error)>;

    VideoDecodeWorker(std::unique_ptr<VideoReader> reader, Callback callback);
    ~VideoDecodeWorker();  // stops and joins; no callback after it returns
    VideoDecodeWorker(const VideoDecodeWorker&) = delete;
    VideoDecodeWorker& operator=(const VideoDecodeWorker&) = delete;

    void request(quint64 serial, long long index);
    // Seeks the reader made so far (playback should add none).
    long long seekCount() const { return seeks_.load(); }

private:
    void run();

    std::unique_ptr<VideoReader> reader_;
    Callback callback_;
    std::mutex mutex_;
    std::condition_variable wake_;
    struct Request {
        quint64 serial;
        long long index;
    };
    std::optional<Request> pending_;
    bool stop_ = false;
    std::atomic<long long> seeks_{0};
    std::thread thread_;
};

}  // namespace athlos::ui
