#include "core/video/VideoContainerProbe.h"

#include <QByteArray>
#include <QFile>
#include <QStringList>

namespace athlos {

namespace {

constexpr qint64 kWindow = 4 << 20;  // head and tail of the file: where headers and 'moov' live

QString printable(const QByteArray& bytes) {
    QString s;
    for (char c : bytes)
        if (c >= 32 && c < 127) s += QLatin1Char(c);
    return s.trimmed();
}

// AVI: the BITMAPINFOHEADER in 'strf' after a 'vids' stream header holds biCompression.
QString aviCodec(const QByteArray& head) {
    const qsizetype vids = head.indexOf("vids");
    if (vids < 0) return {};
    const qsizetype strf = head.indexOf("strf", vids);
    if (strf >= 0 && strf + 28 <= head.size()) {
        const QString c = printable(head.mid(strf + 24, 4));
        if (!c.isEmpty()) return c;
    }
    return vids + 8 <= head.size() ? printable(head.mid(vids + 4, 4)) : QString();
}

// ISO BMFF / QuickTime: each 'stsd' box lists sample entries; the first entry's format is the
// codec. Audio tracks have their own 'stsd'; skip the audio formats.
QString mp4Codec(const QByteArray& bytes) {
    static const QStringList audio = {"mp4a", "ac-3", "ec-3", "Opus", "alac", "twos",
                                      "sowt", "lpcm", "fLaC", "samr", ".mp3"};
    for (qsizetype at = bytes.indexOf("stsd"); at >= 0; at = bytes.indexOf("stsd", at + 4)) {
        if (at + 20 > bytes.size()) break;
        const QString format = printable(bytes.mid(at + 16, 4));
        if (format.size() == 4 && !audio.contains(format)) return format;
    }
    return {};
}

// Matroska: the CodecID element of a video track is a string "V_…".
QString matroskaCodec(const QByteArray& bytes) {
    const qsizetype at = bytes.indexOf("V_");
    if (at < 0) return {};
    qsizetype end = at;
    while (end < bytes.size() && end - at < 32 && bytes[end] >= 33 && bytes[end] < 127) ++end;
    return QString::fromLatin1(bytes.mid(at, end - at));
}

}  // namespace

ContainerProbe probeContainer(const QString& path) {
    ContainerProbe probe;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return probe;
    QByteArray bytes = file.read(kWindow);
    if (file.size() > 2 * kWindow && file.seek(file.size() - kWindow))
        bytes += file.read(kWindow);
    else if (file.size() > kWindow)
        bytes += file.readAll();
    if (bytes.size() < 12) return probe;

    if (bytes.startsWith("RIFF") && bytes.mid(8, 4) == "AVI ") {
        probe = {true, QStringLiteral("AVI"), aviCodec(bytes)};
    } else if (bytes.mid(4, 4) == "ftyp" || bytes.mid(4, 4) == "moov" || bytes.mid(4, 4) == "mdat" ||
               bytes.mid(4, 4) == "wide" || bytes.mid(4, 4) == "free") {
        probe = {true, QStringLiteral("MP4/QuickTime"), mp4Codec(bytes)};
    } else if (bytes.startsWith("\x1A\x45\xDF\xA3")) {
        probe = {true, QStringLiteral("Matroska/WebM"), matroskaCodec(bytes)};
    } else if (bytes.startsWith(QByteArray("\x00\x00\x01\xBA", 4)) || bytes.startsWith("G")) {
        // MPEG program stream, or a transport stream (sync byte 'G' every 188 bytes).
        const bool ts = bytes[0] == 'G' && bytes.size() > 376 && bytes[188] == 'G' && bytes[376] == 'G';
        if (ts || bytes[0] == 0) probe = {true, ts ? QStringLiteral("MPEG-TS") : QStringLiteral("MPEG-PS"), {}};
    } else if (bytes.startsWith("FLV")) {
        probe = {true, QStringLiteral("FLV"), {}};
    } else if (bytes.startsWith(QByteArray("\x30\x26\xB2\x75", 4))) {
        probe = {true, QStringLiteral("ASF/WMV"), {}};
    }
    return probe;
}

}  // namespace athlos
