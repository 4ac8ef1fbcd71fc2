#pragma once
// A look at a file's container header without FFmpeg: is it a video container at all, and which
// codec does its video track declare? Used only to explain why FFmpeg could not open a file
// ("no decoder for codec X" rather than "cannot open").
#include <QString>

namespace athlos {

struct ContainerProbe {
    bool isVideoContainer = false;
    QString container;  // "AVI", "MP4/QuickTime", "Matroska/WebM", "MPEG", ...
    QString codec;      // FourCC or codec id of the first video track, if found
};

ContainerProbe probeContainer(const QString& path);

}  // namespace athlos
