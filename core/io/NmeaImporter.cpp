#include "core/io/NmeaImporter.h"

#include "core/io/TimeFormats.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

namespace athlos {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kKnot = 1852.0 / 3600.0;  // m/s

constexpr qint64 kDayMs = 86400000;
constexpr qint64 kHalfDayMs = kDayMs / 2;
constexpr qint64 kNoDate = std::numeric_limits<qint64>::min();

struct Epoch {
    double lat = kNaN, lon = kNaN, alt = kNaN, speed = kNaN, course = kNaN, hdop = kNaN, sats = kNaN;
    int quality = -1;      // GGA fix quality
    bool invalid = false;  // a sentence said "no fix"
};

// RMC date ddmmyy → days since 1970-01-01 (years 80–99 are 19xx, as NMEA-0183 intends), or kNoDate.
qint64 rmcDate(const QByteArray& value) {
    if (value.size() != 6) return kNoDate;
    bool okD = false, okM = false, okY = false;
    const int d = value.left(2).toInt(&okD), m = value.mid(2, 2).toInt(&okM), y = value.mid(4, 2).toInt(&okY);
    if (!okD || !okM || !okY || m < 1 || m > 12 || d < 1 || d > 31) return kNoDate;
    return daysFromCivil(y >= 80 ? 1900 + y : 2000 + y, m, d);
}

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
    if (hemisphere == "S" || hemisphere == "W")
        out = -out;
    else if (hemisphere != "N" && hemisphere != "E")
        return false;
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
    // Sentences anywhere in the head: logs start with comments, a logger's banner or binary noise.
    static const QRegularExpression sentence(QStringLiteral("\\$[A-Z]{2}(GGA|RMC|VTG),"));
    return sentence.match(QString::fromLatin1(head)).hasMatch();
}

Expected<ImportResult> NmeaImporter::read(const QString& file, const ImportOptions& options,
                                          const Progress& progress) const {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("%1: cannot open: %2").arg(file, f.errorString()));
    progress.report(0.0, QStringLiteral("reading NMEA"));
    auto result = parse(f.readAll(), file, options);
    progress.report(1.0);
    return result;
}

Expected<ImportResult> NmeaImporter::parse(const QByteArray& text, const QString& file, const ImportOptions& options) {
    ImportResult result;
    // Epochs by time in ms since midnight of the first fix's day (day index × 86 400 000 + time of day).
    std::map<qint64, Epoch> epochs;
    qint64 dayOffset = 0, lastFixTod = -1, lastKey = -1;
    qint64 firstDate = kNoDate, firstDateDay = 0;  // the first RMC date and the day index it had
    int lineNo = 0;
    qsizetype lineStart = 0;
    while (lineStart < text.size()) {
        qsizetype lineEnd = text.indexOf('\n', lineStart);
        if (lineEnd < 0) lineEnd = text.size();
        const QByteArray raw = text.mid(lineStart, lineEnd - lineStart);
        lineStart = lineEnd + 1;
        ++lineNo;
        // A sentence starts at '$'; anything before it (binary noise, a logger's prefix) is ignored.
        const qsizetype dollar = raw.indexOf('$');
        if (dollar < 0) continue;
        const QByteArray line = raw.mid(dollar).trimmed();
        const qsizetype star = line.lastIndexOf('*');
        const QByteArray body = line.mid(1, star < 0 ? -1 : star - 1);
        if (star >= 0) {
            bool ok = false;
            const int stated = line.mid(star + 1, 2).toInt(&ok, 16);
            const int computed = checksum(body);
            if (!ok || stated != computed) {
                result.warnings << QStringLiteral(
                                       "%1:%2:%3: checksum mismatch (stated '%4', computed %5); sentence skipped")
                                       .arg(file)
                                       .arg(lineNo)
                                       .arg(dollar + star + 2)
                                       .arg(QString::fromLatin1(line.mid(star + 1, 2)))
                                       .arg(computed, 2, 16, QLatin1Char('0'));
                continue;
            }
        }
        const QList<QByteArray> f = body.split(',');
        if (f.front().size() < 5) continue;
        const QByteArray type = f.front().right(3);
        if (type != "RMC" && type != "GGA" && type != "VTG") continue;
        const auto field = [&](int i) { return i < f.size() ? f[i] : QByteArray(); };
        const auto column = [&](int i) {  // 1-based column of field i in the file's line
            qsizetype at = dollar + 2;    // '$' is column dollar + 1, field 0 starts after it
            for (int k = 0; k < i && k < f.size(); ++k) at += f[k].size() + 1;
            return at;
        };
        const auto fail = [&](const char* what, int i) {
            return makeError(QStringLiteral("%1:%2:%3: %4 sentence: cannot read %5 (field %6: '%7')")
                                 .arg(file)
                                 .arg(lineNo)
                                 .arg(column(i))
                                 .arg(QString::fromLatin1(type), QLatin1String(what))
                                 .arg(i)
                                 .arg(QString::fromLatin1(field(i))));
        };
        if (type == "VTG") {  // no time of its own: belongs to the latest epoch
            if (lastKey < 0) continue;
            Epoch& e = epochs[lastKey];
            bool ok = true;
            if (!field(1).isEmpty()) e.course = field(1).toDouble(&ok);
            if (!ok) return fail("course", 1);
            if (!field(7).isEmpty())
                e.speed = field(7).toDouble(&ok) / 3.6;
            else if (!field(5).isEmpty())
                e.speed = field(5).toDouble(&ok) * kKnot;
            if (!ok) return fail("speed", 7);
            continue;
        }
        double todSeconds = 0.0;
        if (!timeOfDay(field(1), todSeconds)) {
            if (field(1).isEmpty()) continue;  // receivers print empty sentences before the first fix
            return fail("time hhmmss.ss", 1);
        }
        const qint64 tod = std::llround(todSeconds * 1000.0);
        bool fix = true;
        if (type == "RMC" && field(2) != "A") fix = false;
        int quality = -1;
        if (type == "GGA") {
            bool ok = false;
            quality = field(6).toInt(&ok);
            if (!ok && !field(6).isEmpty()) return fail("fix quality", 6);
            if (quality == 0) fix = false;
        }
        // The day: from the RMC date once one is known, else a time of day that jumps back by more
        // than 12 h since the last fix is past midnight. Sentences without a fix do not move the day
        // (receivers print a stale or default time before their first fix).
        qint64 day = dayOffset;
        qint64 date = kNoDate;
        if (type == "RMC" && fix && !field(9).isEmpty()) {
            date = rmcDate(field(9));
            if (date == kNoDate) return fail("date ddmmyy", 9);
            if (firstDate == kNoDate) {
                if (lastFixTod >= 0 && tod < lastFixTod - kHalfDayMs) day = dayOffset + 1;
                firstDate = date;
                firstDateDay = day;
            } else {
                day = firstDateDay + (date - firstDate);
            }
        } else if (lastFixTod >= 0 && tod < lastFixTod - kHalfDayMs) {
            day = dayOffset + 1;
        }
        const qint64 key = day * kDayMs + tod;
        Epoch& e = epochs[key];
        lastKey = key;
        if (!fix) {
            e.invalid = true;
            continue;
        }
        dayOffset = day;
        lastFixTod = tod;
        if (e.invalid) continue;
        const int latField = type == "RMC" ? 3 : 2;
        if (!angle(field(latField), field(latField + 1), e.lat)) return fail("latitude", latField);
        if (!angle(field(latField + 2), field(latField + 3), e.lon)) return fail("longitude", latField + 2);
        bool ok = true;
        if (type == "RMC") {
            if (!field(7).isEmpty()) e.speed = field(7).toDouble(&ok) * kKnot;
            if (!ok) return fail("speed over ground", 7);
            if (!field(8).isEmpty()) e.course = field(8).toDouble(&ok);
            if (!ok) return fail("course", 8);
        } else {
            e.quality = quality;
            if (!field(7).isEmpty()) e.sats = field(7).toDouble(&ok);
            if (!ok) return fail("satellites", 7);
            if (!field(8).isEmpty()) e.hdop = field(8).toDouble(&ok);
            if (!ok) return fail("HDOP", 8);
            if (!field(9).isEmpty()) e.alt = field(9).toDouble(&ok);
            if (!ok) return fail("altitude", 9);
        }
    }
    constexpr int kColumns = 9;
    StreamData data;
    data.columns = kColumns;
    qint64 firstKey = -1;
    for (const auto& [key, e] : epochs) {
        if (e.invalid || !std::isfinite(e.lat) || !std::isfinite(e.lon)) continue;
        if (firstKey < 0) firstKey = key;
        data.t.push_back(double(key - firstKey) * 1e-3);
        const double c = e.course * std::numbers::pi / 180.0;
        const bool vel = std::isfinite(e.speed) && std::isfinite(e.course);
        const double row[kColumns] = {e.lat,
                                      e.lon,
                                      e.alt,
                                      vel ? e.speed * std::cos(c) : kNaN,
                                      vel ? e.speed * std::sin(c) : kNaN,
                                      kNaN,
                                      e.quality >= 0 ? double(e.quality) : kNaN,
                                      e.sats,
                                      e.hdop};
        data.values.insert(data.values.end(), row, row + kColumns);
    }
    if (data.t.empty()) return makeError(QStringLiteral("%1: no RMC/GGA sentence with a valid fix").arg(file));
    // Absolute start: the RMC date (or the date option) at the first fix.
    TimeBase base;
    if (firstDate != kNoDate) {
        base.known = true;
        base.t0Ns = ((firstDate - firstDateDay) * kDayMs + firstKey) * 1000000LL;
    } else if (!options.date.isEmpty()) {
        const QByteArray d = options.date.trimmed().toUtf8();
        qint64 days = 0;
        if (!parseIsoDate(std::string_view(d.constData(), size_t(d.size())), days))
            return makeError(QStringLiteral("date '%1': expected YYYY-MM-DD").arg(options.date));
        base.known = true;
        base.t0Ns = (days * kDayMs + firstKey) * 1000000LL;
    } else {
        base.timeOfDayOnly = true;
        base.t0Ns = (firstKey % kDayMs) * 1000000LL;
        result.warnings << QStringLiteral(
                               "%1: no RMC sentence with a date; the start is known as a time of day (%2 UTC) "
                               "only (give the date: --date YYYY-MM-DD)")
                               .arg(file, formatTimeOfDay(base.t0Ns));
    }
    StreamInfo info;
    info.kind = QStringLiteral("gnss");
    info.frame = QStringLiteral("WGS84");
    info.columns = {{"lat", "deg"}, {"lon", "deg"}, {"alt", "m"},  {"vn", "m/s"}, {"ve", "m/s"},
                    {"vd", "m/s"},  {"fix", "1"},   {"sats", "1"}, {"hdop", "1"}};
    info.attributes.insert(QStringLiteral("source_format"), QStringLiteral("nmea"));
    info.attributes.insert(QStringLiteral("fix_codes"),
                           QStringLiteral("GGA quality: 1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float, 6 dead reckoning"));
    writeTimeAttributes(info.attributes, base, QStringLiteral("nmea"));
    result.items.push_back({QStringLiteral("gnss"), Stream(std::move(info), std::move(data))});
    return result;
}

}  // namespace athlos
