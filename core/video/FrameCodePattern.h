#pragma once
// A test pattern that carries each frame's index in the picture: 16 bits as a 4×4 grid of dark
// and light blocks (most significant bit top left), robust to lossy compression. Writing such a
// video and decoding the index back from what a seek returns is how frame-accurate seeking is
// tested and measured (tests, bench, the CLI test's sample video).
#include "core/util/Expected.h"
#include "core/video/VideoReader.h"

#include <QString>

namespace athlos {

struct FrameCodeVideo {
    QString fourcc = QStringLiteral("MJPG");  // e.g. "MJPG" (.avi), "mp4v" or "avc1" (.mp4), "FFV1"
    double fps = 25;
    long long frames = 100;
    int width = 160, height = 120;  // multiples of 16 keep every encoder happy
};

// Writes the pattern with OpenCV's FFmpeg writer; error if no encoder for the FourCC.
Status writeFrameCodeVideo(const QString& path, const FrameCodeVideo& spec);
// The index encoded in frame, or -1 if the picture is not the pattern.
long long decodeFrameCode(const VideoFrame& frame);
// Same, from a packed 8-bit gray/BGR/RGB picture (channels 1 or 3): lets the UI test read the
// image it actually shows.
long long decodeFrameCode(const unsigned char* pixels, int width, int height, int channels, int bytesPerLine);

}  // namespace athlos
