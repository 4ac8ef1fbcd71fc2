#pragma once
// Files this process has already checked in isolation (or written itself), identified by device,
// inode, size and modification time: a file that changed since is checked again.
#include <QString>

namespace athlos::VerifiedFiles {

// True if path is the very file that was remembered (same identity).
bool contains(const QString& path);
void remember(const QString& path);
// Size in bytes, or -1 if the file cannot be stat'ed.
long long sizeOf(const QString& path);

}  // namespace athlos::VerifiedFiles
