#pragma once
// Tests that read the recordings in shared/data (ATHLOS_SHARED_DATA_DIR, set by tests/CMakeLists.txt)
// are skipped, naming the missing file, when that folder is not there, rather than failing on it.
// (The CLI scripts do the same with need_shared in tests/cli/lib/common.bash.)
#include <QFileInfo>
#include <QString>
#include <gtest/gtest.h>

#define ATHLOS_SKIP_WITHOUT_SHARED(path) \
    if (!QFileInfo::exists(path)) GTEST_SKIP() << "shared recording not found: " << qPrintable(QString(path))
