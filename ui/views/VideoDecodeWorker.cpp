#include "ui/views/VideoDecodeWorker.h"

namespace athlos::ui {

VideoDecodeWorker::VideoDecodeWorker(std::unique_ptr<VideoReader> reader, Callback callback)
    : reader_(std::move(reader)), callback_(std::move(callback)), thread_([this] { run(); }) {}

VideoDecodeWorker::~VideoDecodeWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        pending_.reset();
    }
    wake_.notify_all();
    thread_.join();
}

void VideoDecodeWorker::request(quint64 serial, long long index) {
    {
        std::lock_guard lock(mutex_);
        pending_ = Request{serial, index};
    }
    wake_.notify_one();
}

void VideoDecodeWorker::run() {
    for (;;) {
        Request request;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stop_ || pending_.has_value(); });
            if (stop_) return;
            request = *pending_;
            pending_.reset();
        }
        auto frame = reader_->frameAt(request.index);
        seeks_ = reader_->seekCount();
        if (!frame) {
            callback_(request.serial, request.index, {}, frame.message());
            continue;
        }
        // The reader's buffer is packed BGR; the copy detaches the image from it.
        const QImage image =
            QImage(frame->bgr.get(), frame->width, frame->height, frame->width * 3, QImage::Format_BGR888)
                .convertToFormat(QImage::Format_RGB32);
        callback_(request.serial, request.index, image, {});
    }
}

}  // namespace athlos::ui
