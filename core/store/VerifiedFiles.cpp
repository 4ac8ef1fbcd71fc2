#include "core/store/VerifiedFiles.h"

#include <QFile>
#include <QHash>
#include <mutex>
#include <sys/stat.h>

namespace athlos::VerifiedFiles {
namespace {

struct Identity {
    dev_t device = 0;
    ino_t inode = 0;
    off_t size = -1;
    long long mtimeNs = 0;
    bool operator==(const Identity&) const = default;
};

bool identify(const QString& path, Identity& out) {
    struct stat st {};
    if (::stat(QFile::encodeName(path).constData(), &st) != 0) return false;
    out = {st.st_dev, st.st_ino, st.st_size,
           static_cast<long long>(st.st_mtim.tv_sec) * 1'000'000'000LL + st.st_mtim.tv_nsec};
    return true;
}

std::mutex& mutex() {
    static std::mutex m;
    return m;
}

QHash<QString, Identity>& known() {
    static QHash<QString, Identity> k;
    return k;
}

}  // namespace

bool contains(const QString& path) {
    Identity now;
    if (!identify(path, now)) return false;
    std::lock_guard guard(mutex());
    const auto it = known().constFind(path);
    return it != known().constEnd() && *it == now;
}

void remember(const QString& path) {
    Identity now;
    if (!identify(path, now)) return;
    std::lock_guard guard(mutex());
    known().insert(path, now);
}

long long sizeOf(const QString& path) {
    Identity now;
    return identify(path, now) ? static_cast<long long>(now.size) : -1;
}

}  // namespace athlos::VerifiedFiles
