#include "core/io/NmeaImporter.h"

#include <QFile>
#include <QFileInfo>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

namespace athlos {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kKnot = 1852.0 / 3600.0;  // m/s

struct Epoch {
    double lat = kNaN, lon = kNaN, alt = kNaN, speed = kNaN, course = kNaN, hdop = kNaN, sats = kNaN;
    bool invalid = false;  // a sentence said "no fix"
};

// XOR of the characters between '$' and '*' (NMEA-0183 checksum).
int checksum(const QByteArray& body) {
    int sum = 0;
    for (char ch : body) sum ^= static_cast<unsigned char>(ch);
    return sum;
}

// ddmm.mmmm / dddmm.mmmm with hemisphere → signed degrees.
bool angle(const QByteArray& value, const QByteArray& hemisphere, double& out) {
    bool ok = false;
    const double v = value.toDouble(&ok);
    if (!ok) return false;
    const double deg = std::floor(v / 100.0);
    out = deg + (v - 100.0 * deg) / 60.0;
    if (hemisphere == "S" || hemisphere == "W") out = -out;
    else if (hemisphere != "N" && hemisphere != "E") return false;
    return true;
}

bool timeOfDay(const QByteArray& value, double& out) {
    if (value.size() < 6) return false;
    bool okH = false, okM = false, okS = false;
    const int h = value.left(2).toInt(&okH), m = value.mid(2, 2).toInt(&okM);
    const double s = value.mid(4).toDouble(&okS);
    if (!okH || !okM || !okS || h > 23 || m > 59 || s >= 61.0) return false;
    out = 3600.0 * h + 60.0 * m + s;
    return true;
}

}  // namespace

QString NmeaImporter::description() const {
    return QStringLiteral("NMEA-0183 GNSS log (RMC, GGA, VTG sentences) → gnss stream lat, lon, alt, vn, ve, vd");
}

bool NmeaImporter::canRead(const QString&, const QByteArray& head) const {
    const QByteArray t = head.trimmed();
    return t.startsWith('$') && (t.contains("GGA,") || t.contains("RMC,") || t.contains("VTG,"));
}

Expected<ImportResult> NmeaImporter::read(const QString& file, const ImportOptions&, const Progress& progress) const {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) return makeError(QStringLiteral("%1: cannot open: %2").arg(file, f.errorString()));
    progress.report(0.0, QStringLiteral("reading NMEA"));
    auto result = parse(f.readAll(), file);
    progress.report(1.0);
    return result;
}

Expected<ImportResult> NmeaImporter::parse(const QByteArray& text, const QString& file) {
    ImportResult result;
    std::map<double, Epoch> epochs;  // by time stamp (s since the first day's midnight)
    double dayOffset = 0.0, lastTod = -1.0;
    int lineNo = 0;
    for (QByteArray line : text.split('\n')) {
        ++lineNo;
        line = line.trimmed();
        if (line.isEmpty()) continue;
        if (!line.startsWith('$')) continue;  // not a sentence (comments, binary noise)
        const qsizetype star = line.lastIndexOf('*');
        const QByteArray body = line.mid(1, star < 0 ? -1 : star - 1);
        if (star >= 0) {
            bool ok = false;
            const int stated = line.mid(star + 1, 2).toInt(&ok, 16);
            const int computed = checksum(body);
            if (!ok || stated != computed) {
                result.warnings << QStringLiteral("%1:%2: checksum mismatch (stated %3, computed %4); sentence skipped")
                                       .arg(file).arg(lineNo).arg(QString::fromLatin1(line.mid(star + 1, 2)))
                                       .arg(computed, 2, 16, QLatin1Char('0'));
                continue;
            }
        }
        const QList<QByteArray> f = body.split(',');
        if (f.front().size() < 5) continue;
        const QByteArray type = f.front().right(3);
        if (type != "RMC" && type != "GGA" && type != "VTG") continue;
        const auto field = [&](int i) { return i < f.size() ? f[i] : QByteArray(); };
        const auto fail = [&](const char* what, int i) {
            return makeError(QStringLiteral("%1:%2: %3 sentence: cannot read %4 (field %5: '%6')")
                                 .arg(file).arg(lineNo).arg(QString::fromLatin1(type), QLatin1String(what)).arg(i)
                                 .arg(QString::fromLatin1(field(i))));
        };
        if (type == "VTG") {  // no time of its own: belongs to the latest epoch
            if (lastTod < 0.0 || epochs.empty()) continue;
            Epoch& e = epochs[lastTod + dayOffset];
            bool ok = true;
            if (!field(1).isEmpty()) e.course = field(1).toDouble(&ok);
            if (!ok) return fail("course", 1);
            if (!field(7).isEmpty()) e.speed = field(7).toDouble(&ok) / 3.6;
            else if (!field(5).isEmpty()) e.speed = field(5).toDouble(&ok) * kKnot;
            if (!ok) return fail("speed", 7);
            continue;
        }
        double tod = 0.0;
        if (!timeOfDay(field(1), tod)) {
            if (field(1).isEmpty()) continue;  // receivers print empty sentences before the first fix
            return fail("time hhmmss.ss", 1);
        }
        if (lastTod >= 0.0 && tod < lastTod - 43200.0) dayOffset += 86400.0;  // past midnight
        lastTod = tod;
        Epoch& e = epochs[tod + dayOffset];
        const int latField = type == "RMC" ? 3 : 2;
        if (type == "RMC" && field(2) != "A") e.invalid = true;
        if (type == "GGA") {
            bool ok = false;
            const int quality = field(6).toInt(&ok);
            if (!ok && !field(6).isEmpty()) return fail("fix quality", 6);
            if (quality == 0) e.invalid = true;
        }
        if (e.invalid) continue;
        if (!angle(field(latField), field(latField + 1), e.lat)) return fail("latitude", latField);
        if (!angle(field(latField + 2), field(latField + 3), e.lon)) return fail("longitude", latField + 2);
        bool ok = true;
        if (type == "RMC") {
            if (!field(7).isEmpty()) e.speed = field(7).toDouble(&ok) * kKnot;
            if (!ok) return fail("speed over ground", 7);
            if (!field(8).isEmpty()) e.course = field(8).toDouble(&ok);
            if (!ok) return fail("course", 8);
        } else {
            if (!field(7).isEmpty()) e.sats = field(7).toDouble(&ok);
            if (!ok) return fail("satellites", 7);
            if (!field(8).isEmpty()) e.hdop = field(8).toDouble(&ok);
            if (!ok) return fail("HDOP", 8);
            if (!field(9).isEmpty()) e.alt = field(9).toDouble(&ok);
            if (!ok) return fail("altitude", 9);
        }
    }
    StreamData data;
    data.columns = 8;
    for (const auto& [t, e] : epochs) {
        if (e.invalid || !std::isfinite(e.lat) || !std::isfinite(e.lon)) continue;
        data.t.push_back(t);
        const double c = e.course * std::numbers::pi / 180.0;
        const bool vel = std::isfinite(e.speed) && std::isfinite(e.course);
        const double row[8] = {e.lat, e.lon, e.alt, vel ? e.speed * std::cos(c) : kNaN, vel ? e.speed * std::sin(c) : kNaN,
                               kNaN, e.hdop, e.sats};
        data.values.insert(data.values.end(), row, row + 8);
    }
    if (data.t.empty()) return makeError(QStringLiteral("%1: no RMC/GGA sentence with a valid fix").arg(file));
    StreamInfo info;
    info.kind = QStringLiteral("gnss");
    info.frame = QStringLiteral("WGS84");
    info.columns = {{"lat", "deg"}, {"lon", "deg"}, {"alt", "m"}, {"vn", "m/s"}, {"ve", "m/s"}, {"vd", "m/s"}, {"hdop", "1"}, {"sats", "1"}};
    info.attributes.insert(QStringLiteral("source_format"), QStringLiteral("nmea"));
    result.items.push_back({QStringLiteral("gnss"), Stream(std::move(info), std::move(data))});
    return result;
}

}  // namespace athlos
