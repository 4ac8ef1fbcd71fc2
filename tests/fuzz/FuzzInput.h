#pragma once
// Helpers for fuzz targets whose code under test reads a path: the input bytes go to a new file in
// a private folder of the process (in /dev/shm when there is one, so nothing touches a disk), and
// the file is removed when the guard goes out of scope. Every input gets a new name, so a library
// that keeps a file open (HDF5 does when an id leaks) never sees the previous input under it.
#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QString>
#include <QTemporaryDir>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

namespace athlos::fuzz {

inline const QString& scratchDir() {
    static QTemporaryDir dir(
        QDir(QDir(QStringLiteral("/dev/shm")).exists() ? QStringLiteral("/dev/shm") : QDir::tempPath())
            .filePath(QStringLiteral("athlos-fuzz-XXXXXX")));
    static const QString path = [] {
        if (!dir.isValid()) std::abort();  // no place for inputs: nothing can be fuzzed
        return dir.path();
    }();
    return path;
}

inline QByteArray bytes(const uint8_t* data, size_t size) {
    return QByteArray(reinterpret_cast<const char*>(data), qsizetype(size));
}

// One input as a file, removed on destruction: input-<n><suffix> ("input-7.csv") in the scratch
// folder, or at a path of the caller's (InputFile::at).
class InputFile {
public:
    InputFile(const uint8_t* data, size_t size, const QString& suffix)
        : InputFile(scratchDir() + QStringLiteral("/input-%1%2").arg(nextNumber()).arg(suffix), bytes(data, size)) {}
    static InputFile at(const QString& path, const QByteArray& content) { return InputFile(path, content); }
    static unsigned long long nextNumber() {
        static unsigned long long counter = 0;
        return ++counter;
    }
    ~InputFile() { QFile::remove(path_); }
    InputFile(const InputFile&) = delete;
    InputFile& operator=(const InputFile&) = delete;

    const QString& path() const { return path_; }

private:
    InputFile(const QString& path, const QByteArray& content) : path_(path) {
        QFile f(path_);
        if (!f.open(QIODevice::WriteOnly) || f.write(content) != content.size()) std::abort();
    }

    QString path_;
};

}  // namespace athlos::fuzz
