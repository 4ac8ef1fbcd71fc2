#pragma once
#include <QString>

namespace athlos {

// Application version (from CMake's project()), written into every provenance record.
QString appVersion();
// One line per library with its version, for "About" and `athlos --version`.
QString libraryVersions();

}  // namespace athlos
