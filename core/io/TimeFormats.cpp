#include "core/io/TimeFormats.h"

#include "core/util/Units.h"

#include <QRegularExpression>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace athlos {
namespace {

bool digits(std::string_view s, size_t at, size_t count, int& out) {
    if (at + count > s.size()) return false;
    out = 0;
    for (size_t i = at; i < at + count; ++i) {
        if (s[i] < '0' || s[i] > '9') return false;
        out = out * 10 + (s[i] - '0');
    }
    return true;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

// Parses "[.|,]fff…" at s[at…]; advances at; ns out.
bool fraction(std::string_view s, size_t& at, qint64& ns) {
    ns = 0;
    if (at >= s.size() || (s[at] != '.' && s[at] != ',')) return true;
    ++at;
    qint64 scale = kNsPerSecond / 10;
    const size_t begin = at;
    while (at < s.size() && s[at] >= '0' && s[at] <= '9') {
        ns += (s[at] - '0') * scale;
        scale /= 10;
        ++at;
    }
    return at > begin;
}

int daysInMonth(int year, int month) {
    static const int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
    return month == 2 && leap ? 29 : kDays[month - 1];
}

struct Named {
    const char* name;
    TimeKind kind;
    double scale;
};

const Named kNamed[] = {
    {"uptime", TimeKind::Uptime, 1.0},        {"uptime_s", TimeKind::Uptime, 1.0},
    {"uptime_ms", TimeKind::Uptime, 1e-3},    {"uptime_us", TimeKind::Uptime, 1e-6},
    {"uptime_ns", TimeKind::Uptime, 1e-9},    {"unix", TimeKind::Unix, 1.0},
    {"unix_s", TimeKind::Unix, 1.0},          {"unix_ms", TimeKind::Unix, 1e-3},
    {"unix_us", TimeKind::Unix, 1e-6},        {"unix_ns", TimeKind::Unix, 1e-9},
    {"epoch", TimeKind::Unix, 1.0},           {"epoch_s", TimeKind::Unix, 1.0},
    {"epoch_ms", TimeKind::Unix, 1e-3},       {"epoch_us", TimeKind::Unix, 1e-6},
    {"epoch_ns", TimeKind::Unix, 1e-9},       {"iso", TimeKind::Iso, 1.0},
    {"iso8601", TimeKind::Iso, 1.0},          {"datetime", TimeKind::Iso, 1.0},
    {"clock", TimeKind::Clock, 1.0},          {"excel", TimeKind::Excel, 86400.0},
    {"excel_days", TimeKind::Excel, 86400.0},
};

}  // namespace

QString timeFormatNames() {
    return QStringLiteral(
        "s, ms, us, ns, min, h, d; uptime, uptime_ms, uptime_us, uptime_ns; unix, unix_ms, unix_us, "
        "unix_ns (or epoch_...); iso; hh:mm:ss, hh:mm:ss.fff (clock); excel");
}

QString guessTimeFormat(const QString& cell) {
    const QString c = cell.trimmed();
    static const QRegularExpression clock(QStringLiteral("^\\d{1,2}:\\d{2}:\\d{2}([.,]\\d+)?$"));
    static const QRegularExpression iso(QStringLiteral("^\\d{4}-\\d{2}-\\d{2}[T ]\\d{2}:\\d{2}"));
    if (clock.match(c).hasMatch()) return QStringLiteral("hh:mm:ss");
    if (iso.match(c).hasMatch()) return QStringLiteral("iso");
    bool ok = false;
    const double v = c.toDouble(&ok);
    if (!ok || !std::isfinite(v)) return {};
    // 2000-01-01 and 2100-01-01 in s since the Unix epoch.
    constexpr double kFrom = 946684800.0, kTo = 4102444800.0;
    const std::pair<double, const char*> units[] = {
        {1.0, "unix"}, {1e3, "unix_ms"}, {1e6, "unix_us"}, {1e9, "unix_ns"}};
    for (const auto& [perSecond, name] : units)
        if (v >= kFrom * perSecond && v < kTo * perSecond) return QLatin1String(name);
    return {};
}

Expected<TimeFormat> parseTimeFormat(const QString& spec) {
    const QString s = spec.trimmed();
    if (s.isEmpty()) return TimeFormat{TimeKind::Duration, 1.0, QStringLiteral("s")};
    const QString lower = s.toLower();
    // Clock patterns: hh:mm:ss with an optional fraction of f, z or s letters.
    static const QRegularExpression clock(QStringLiteral("^h{1,2}:mm:ss([.,][fzs]+)?$"));
    if (clock.match(lower).hasMatch() || lower == QLatin1String("clock"))
        return TimeFormat{TimeKind::Clock, 1.0, lower == QLatin1String("clock") ? QStringLiteral("hh:mm:ss") : lower};
    for (const Named& n : kNamed) {
        QString name = QLatin1String(n.name);
        QString alt = name;
        alt.replace(QLatin1String("_us"), QStringLiteral("_\u00B5s"));
        if (lower == name || lower == alt) return TimeFormat{n.kind, n.scale, name};
    }
    const QString unit = canonicalUnit(s);
    if (const auto c = conversionTo(unit, QStringLiteral("s")); c && c->offset == 0.0)
        return TimeFormat{TimeKind::Duration, c->scale, unit};
    return makeError(QStringLiteral("unknown time format '%1' (accepted: %2)").arg(spec, timeFormatNames()));
}

Expected<std::pair<QString, QString>> splitTimeColumnSpec(const QString& spec) {
    for (qsizetype colon = spec.indexOf(QLatin1Char(':')); colon >= 0;
         colon = spec.indexOf(QLatin1Char(':'), colon + 1)) {
        const QString format = spec.mid(colon + 1).trimmed();
        if (!format.isEmpty() && parseTimeFormat(format)) return std::pair{spec.left(colon).trimmed(), format};
    }
    if (const qsizetype colon = spec.indexOf(QLatin1Char(':')); colon >= 0)
        return makeError(QStringLiteral("unknown time format '%1' (accepted: %2)")
                             .arg(spec.mid(colon + 1).trimmed(), timeFormatNames()));
    return std::pair{spec.trimmed(), QString()};
}

qint64 daysFromCivil(int y, int m, int d) {
    // H. Hinnant, "chrono-Compatible Low-Level Date Algorithms".
    y -= m <= 2;
    const qint64 era = (y >= 0 ? y : y - 399) / 400;
    const unsigned yoe = unsigned(y - era * 400);
    const unsigned doy = (153 * unsigned(m + (m > 2 ? -3 : 9)) + 2) / 5 + unsigned(d) - 1;
    const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + qint64(doe) - 719468;
}

void civilFromDays(qint64 z, int& year, int& month, int& day) {
    z += 719468;
    const qint64 era = (z >= 0 ? z : z - 146096) / 146097;
    const unsigned doe = unsigned(z - era * 146097);
    const unsigned yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const qint64 y = qint64(yoe) + era * 400;
    const unsigned doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const unsigned mp = (5 * doy + 2) / 153;
    day = int(doy - (153 * mp + 2) / 5 + 1);
    month = int(mp < 10 ? mp + 3 : mp - 9);
    year = int(y + (month <= 2));
}

bool parseClockTime(std::string_view text, qint64& nsOfDay) {
    const std::string_view s = trim(text);
    int h = 0, m = 0, sec = 0;
    size_t at = 0;
    if (digits(s, 0, 2, h))
        at = 2;
    else if (digits(s, 0, 1, h))
        at = 1;
    else
        return false;
    if (at >= s.size() || s[at] != ':' || !digits(s, at + 1, 2, m)) return false;
    at += 3;
    if (at >= s.size() || s[at] != ':' || !digits(s, at + 1, 2, sec)) return false;
    at += 3;
    qint64 frac = 0;
    if (!fraction(s, at, frac) || at != s.size()) return false;
    if (h > 23 || m > 59 || sec > 60) return false;
    nsOfDay = (qint64(h) * 3600 + m * 60 + sec) * kNsPerSecond + frac;
    return true;
}

bool parseIsoDate(std::string_view text, qint64& days) {
    const std::string_view s = trim(text);
    int y = 0, mo = 0, d = 0;
    if (s.size() != 10 || !digits(s, 0, 4, y) || s[4] != '-' || !digits(s, 5, 2, mo) || s[7] != '-' ||
        !digits(s, 8, 2, d))
        return false;
    if (mo < 1 || mo > 12 || d < 1 || d > daysInMonth(y, mo)) return false;
    days = daysFromCivil(y, mo, d);
    return true;
}

bool parseIsoDateTime(std::string_view text, qint64& ns, bool& hasZone) {
    const std::string_view s = trim(text);
    qint64 days = 0;
    if (s.size() < 16 || !parseIsoDate(s.substr(0, 10), days) || (s[10] != 'T' && s[10] != ' ' && s[10] != 't'))
        return false;
    int h = 0, m = 0, sec = 0;
    if (!digits(s, 11, 2, h) || s[13] != ':' || !digits(s, 14, 2, m)) return false;
    size_t at = 16;
    qint64 frac = 0;
    if (at < s.size() && s[at] == ':') {
        if (!digits(s, at + 1, 2, sec)) return false;
        at += 3;
        if (!fraction(s, at, frac)) return false;
    }
    if (h > 23 || m > 59 || sec > 60) return false;
    qint64 offsetMinutes = 0;
    hasZone = false;
    if (at < s.size()) {
        if (s[at] == 'Z' || s[at] == 'z') {
            hasZone = true;
            ++at;
        } else if (s[at] == '+' || s[at] == '-') {
            const int sign = s[at] == '-' ? -1 : 1;
            int oh = 0, om = 0;
            if (!digits(s, at + 1, 2, oh)) return false;
            at += 3;
            if (at < s.size() && s[at] == ':') ++at;
            if (at < s.size()) {
                if (!digits(s, at, 2, om)) return false;
                at += 2;
            }
            offsetMinutes = sign * (oh * 60 + om);
            hasZone = true;
        }
    }
    if (at != s.size()) return false;
    ns = days * kNsPerDay + (qint64(h) * 3600 + m * 60 + sec - offsetMinutes * 60) * kNsPerSecond + frac;
    return true;
}

bool parseScaledInstant(std::string_view text, double scaleNs, qint64& ns) {
    const std::string_view s = trim(text);
    if (s.empty()) return false;
    const char* b = s.data();
    const char* e = b + s.size();
    if (*b == '+') ++b;
    long long integer = 0;
    if (auto [q, ec] = std::from_chars(b, e, integer); ec == std::errc() && q == e) {
        const double whole = double(integer) * scaleNs;
        if (std::abs(whole) > 9.0e18) return false;
        if (scaleNs >= 1.0 && scaleNs == std::floor(scaleNs)) {
            ns = integer * qint64(scaleNs);  // exact for ns, us, ms and s stamps
            return true;
        }
        ns = qint64(std::llround(whole));
        return true;
    }
    // A decimal without exponent: exact for integer scales (1.25 s → 1 250 000 000 ns, no rounding).
    if (const char* dot = std::find(b, e, '.');
        dot != e && scaleNs >= 1.0 && scaleNs == std::floor(scaleNs) && scaleNs < 1e15) {
        long long whole = 0;
        const bool negative = *b == '-';
        const auto [qi, eci] = std::from_chars(b, dot, whole);
        bool digitsOnly = dot + 1 < e && (qi == dot || (dot == b + (negative ? 1 : 0)));
        if (eci != std::errc() && !(dot == b || (negative && dot == b + 1))) digitsOnly = false;
        __int128 fraction = 0, denominator = 1;
        for (const char* q = dot + 1; digitsOnly && q < e; ++q) {
            if (*q < '0' || *q > '9' || denominator > __int128(1000000000000000000LL))
                digitsOnly = false;
            else
                fraction = fraction * 10 + (*q - '0'), denominator *= 10;
        }
        if (digitsOnly) {
            const __int128 scale = __int128(qint64(scaleNs));
            __int128 total =
                __int128(whole < 0 ? -whole : whole) * scale + (fraction * scale * 2 + denominator) / (denominator * 2);
            if (negative) total = -total;
            if (total > __int128(9000000000000000000LL) || total < -__int128(9000000000000000000LL)) return false;
            ns = qint64(total);
            return true;
        }
    }
    double v = 0.0;
    if (auto [q, ec] = std::from_chars(b, e, v); ec != std::errc() || q != e || !std::isfinite(v)) return false;
    const double scaled = v * scaleNs;
    if (std::abs(scaled) > 9.0e18) return false;
    ns = qint64(std::llround(scaled));
    return true;
}

QString formatTimeOfDay(qint64 nsOfDay) {
    const qint64 secs = nsOfDay / kNsPerSecond;
    qint64 frac = nsOfDay % kNsPerSecond;
    QString text = QStringLiteral("%1:%2:%3")
                       .arg(secs / 3600, 2, 10, QLatin1Char('0'))
                       .arg(secs / 60 % 60, 2, 10, QLatin1Char('0'))
                       .arg(secs % 60, 2, 10, QLatin1Char('0'));
    if (frac != 0) {
        int width = 9;
        while (width > 3 && frac % 1000 == 0) {
            frac /= 1000;
            width -= 3;
        }
        text += QLatin1Char('.') + QStringLiteral("%1").arg(frac, width, 10, QLatin1Char('0'));
    }
    return text;
}

QString formatUtc(qint64 ns) {
    qint64 days = ns / kNsPerDay;
    qint64 rest = ns % kNsPerDay;
    if (rest < 0) {
        rest += kNsPerDay;
        --days;
    }
    int y = 0, m = 0, d = 0;
    civilFromDays(days, y, m, d);
    return QStringLiteral("%1-%2-%3T")
               .arg(y, 4, 10, QLatin1Char('0'))
               .arg(m, 2, 10, QLatin1Char('0'))
               .arg(d, 2, 10, QLatin1Char('0')) +
           formatTimeOfDay(rest) + QLatin1Char('Z');
}

Expected<qint64> parseUtc(const QString& text) {
    const QByteArray utf8 = text.trimmed().toUtf8();
    qint64 ns = 0;
    bool zone = false;
    if (parseIsoDateTime(std::string_view(utf8.constData(), size_t(utf8.size())), ns, zone)) return ns;
    qint64 days = 0;
    if (parseIsoDate(std::string_view(utf8.constData(), size_t(utf8.size())), days)) return days * kNsPerDay;
    return makeError(
        QStringLiteral("'%1' is not an ISO 8601 date-time (YYYY-MM-DDThh:mm:ss[.fff][Z|+hh:mm])").arg(text));
}

void writeTimeAttributes(QJsonObject& attributes, const TimeBase& base, const QString& formatName) {
    if (base.known)
        attributes.insert(QStringLiteral("t0_utc"), formatUtc(base.t0Ns));
    else if (base.timeOfDayOnly)
        attributes.insert(QStringLiteral("t0_time_of_day"), formatTimeOfDay(base.t0Ns));
    if (!formatName.isEmpty()) attributes.insert(QStringLiteral("time_format"), formatName);
}

void startAtZero(std::vector<double>& t, TimeBase& base) {
    if (t.empty() || t.front() == 0.0) return;
    const double first = t.front();
    base.t0Ns += qint64(std::llround(first * 1e9));
    for (double& v : t) v -= first;
}

QString samplingRateWarning(const std::vector<double>& t, const QString& formatName, const QString& what) {
    std::vector<double> steps;
    steps.reserve(std::min<size_t>(t.size(), 100001));
    for (size_t i = 1; i < t.size() && steps.size() < 100000; ++i)
        if (const double d = t[i] - t[i - 1]; d > 0.0) steps.push_back(d);
    if (steps.size() < 2) return {};
    auto mid = steps.begin() + ptrdiff_t(steps.size() / 2);
    std::nth_element(steps.begin(), mid, steps.end());
    const double step = *mid;
    constexpr double kMaxRate = 20000.0;  // Hz: above any sports sensor (EMG stays below 10 kHz)
    constexpr double kMaxStep = 3600.0;   // s: one sample an hour is no recording
    if (1.0 / step > kMaxRate)
        return QStringLiteral(
                   "%1: with time format '%2' the samples are %3 s apart (%4 kHz); is the time format right?")
            .arg(what, formatName, QString::number(step, 'g', 3), QString::number(1e-3 / step, 'g', 3));
    if (step >= kMaxStep)
        return QStringLiteral("%1: with time format '%2' the samples are %3 s apart (%4 h); is the time format right?")
            .arg(what, formatName, QString::number(step, 'g', 3), QString::number(step / 3600.0, 'g', 3));
    return {};
}

}  // namespace athlos
