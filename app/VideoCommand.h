#pragma once
// athlos video: attach a video to a recording, detach it, or describe it.
#include <QStringList>

namespace athlos::cli {

int cmdVideo(const QStringList& args);

}  // namespace athlos::cli
