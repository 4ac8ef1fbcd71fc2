#include "core/video/FrameCodePattern.h"

#include <QCoreApplication>
#include <opencv2/core.hpp>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/videoio.hpp>

namespace athlos {

namespace {

constexpr int kGrid = 4;  // 4×4 blocks = 16 bits

}  // namespace

Status writeFrameCodeVideo(const QString& path, const FrameCodeVideo& spec) {
    const QByteArray f = spec.fourcc.toLatin1();
    if (f.size() != 4)
        return makeError(
            QCoreApplication::translate("athlos::VideoReader", "FourCC '%1' is not 4 characters").arg(spec.fourcc));
    quietFfmpeg();
    const auto previousLevel = cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
    cv::VideoWriter writer(path.toStdString(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc(f[0], f[1], f[2], f[3]),
                           spec.fps, cv::Size(spec.width, spec.height));
    cv::utils::logging::setLogLevel(previousLevel);
    if (!writer.isOpened())
        return makeError(QCoreApplication::translate("athlos::VideoReader", "'%1': no FFmpeg encoder for FourCC '%2'")
                             .arg(path, spec.fourcc));
    const int bw = spec.width / kGrid, bh = spec.height / kGrid;
    for (long long i = 0; i < spec.frames; ++i) {
        cv::Mat image(spec.height, spec.width, CV_8UC3);
        for (int b = 0; b < kGrid * kGrid; ++b) {
            const bool bit = (i >> (kGrid * kGrid - 1 - b)) & 1;
            // Light blocks warm, dark blocks blue-ish: readable by eye in a screenshot too.
            const cv::Scalar colour = bit ? cv::Scalar(60, 200, 240) : cv::Scalar(70, 25, 20);
            image(cv::Rect((b % kGrid) * bw, (b / kGrid) * bh, bw, bh)).setTo(colour);
        }
        writer.write(image);
    }
    writer.release();
    return {};
}

long long decodeFrameCode(const unsigned char* pixels, int width, int height, int channels, int bytesPerLine) {
    if (!pixels || width < kGrid * 4 || height < kGrid * 4 || (channels != 1 && channels != 3)) return -1;
    const int bw = width / kGrid, bh = height / kGrid;
    long long index = 0;
    for (int b = 0; b < kGrid * kGrid; ++b) {
        // The mean brightness of the inner half of the block: edges ring after compression.
        const int x0 = (b % kGrid) * bw + bw / 4, y0 = (b / kGrid) * bh + bh / 4;
        double sum = 0;
        int n = 0;
        for (int y = y0; y < y0 + bh / 2; ++y)
            for (int x = x0; x < x0 + bw / 2; ++x) {
                const unsigned char* p = pixels + std::size_t(y) * bytesPerLine + std::size_t(x) * channels;
                for (int c = 0; c < channels; ++c) sum += p[c];
                n += channels;
            }
        const double mean = sum / n;
        if (mean > 90 && mean < 110) return -1;  // neither light (~167) nor dark (~38): not the pattern
        index = (index << 1) | (mean > 100 ? 1 : 0);
    }
    return index;
}

long long decodeFrameCode(const VideoFrame& frame) {
    return decodeFrameCode(frame.bgr.get(), frame.width, frame.height, 3, frame.width * 3);
}

}  // namespace athlos
