#pragma once
// Time as it appears in real files, and the absolute start every stream keeps.
//
// A stream's `t` is in seconds; its attribute `t0_utc` (ISO 8601, "2024-05-01T13:45:01.25Z") is the
// UTC instant of t = 0 when the file tells it. Importers read time cells in one of these formats
// (ImportOptions::timeUnit, "--time-column COL:FORMAT", or the unit in the header cell):
//   s, ms, us (µs), ns, min, h, d     a duration since some start; t as given (converted to s)
//   uptime, uptime_ms, _us, _ns        device uptime (time since the device started), t as given
//   unix, unix_ms, unix_us, unix_ns    Unix epoch (also epoch_…); t from the first sample, t0_utc set
//   iso                                ISO 8601 date-time: 2024-05-01T13:45:01.250Z, "2024-05-01 13:45:01",
//                                      with an offset (+02:00) or none (taken as UTC, with a warning)
//   hh:mm:ss, hh:mm:ss.fff (clock)     clock time; the date from a date column of the file, the format
//                                      or ImportOptions::date; without one, t0 is a time of day only.
//                                      Times that jump back by more than 12 h roll over to the next day.
//   excel                              Excel serial days (1900 system: 25569 = 1970-01-01)
// Absolute instants are kept as integer nanoseconds since the Unix epoch, so nanosecond stamps
// (ROS) survive.
#include "core/util/Expected.h"

#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <string_view>
#include <utility>
#include <vector>

namespace athlos {

enum class TimeKind { Duration, Uptime, Unix, Iso, Clock, Excel };

struct TimeFormat {
    TimeKind kind = TimeKind::Duration;
    double scale = 1.0;  // Duration, Uptime, Unix: seconds per unit of the cells
    QString name;        // canonical spelling: "ms", "unix_ns", "iso", "hh:mm:ss", ...

    // Cells hold text (not numbers).
    bool textual() const { return kind == TimeKind::Iso || kind == TimeKind::Clock; }
    // Cells are instants (t is measured from the first sample and t0_utc is known, or for clock
    // times without a date, t0 is a time of day).
    bool absolute() const {
        return kind == TimeKind::Unix || kind == TimeKind::Iso || kind == TimeKind::Clock || kind == TimeKind::Excel;
    }
};

// The format of spec (case-insensitive for the names; "" = seconds). The error lists the accepted ones.
Expected<TimeFormat> parseTimeFormat(const QString& spec);
// Splits "COL[:FORMAT]" (the --time-column option) at the first ':' that a known format follows, so
// "Time:hh:mm:ss" is column "Time" in format "hh:mm:ss". Error if there is a ':' but no known format.
Expected<std::pair<QString, QString>> splitTimeColumnSpec(const QString& spec);
// "s, ms, ..., excel", for messages and help.
QString timeFormatNames();

// The format a time cell is written in, guessed from the cell alone (a file's first time stamp,
// when neither the header nor the user says): "hh:mm:ss" for clock times, "iso" for ISO 8601
// date-times, "unix" / "unix_ms" / "unix_us" / "unix_ns" for numbers that are instants between
// 2000-01-01 and 2100-01-01 in that unit (no recording lasts 30 years, so such a number is no
// duration), else "" (a duration in seconds).
QString guessTimeFormat(const QString& cell);

constexpr qint64 kNsPerSecond = 1000000000LL;
constexpr qint64 kNsPerDay = 86400LL * kNsPerSecond;

// Days since 1970-01-01 of a proleptic Gregorian date, and back.
qint64 daysFromCivil(int year, int month, int day);
void civilFromDays(qint64 days, int& year, int& month, int& day);

// "hh:mm:ss[.fff]" (h may be one digit, fraction of any length, '.' or ',') → ns since midnight.
bool parseClockTime(std::string_view text, qint64& nsOfDay);
// "YYYY-MM-DD" → days since 1970-01-01.
bool parseIsoDate(std::string_view text, qint64& days);
// "YYYY-MM-DD[T| ]hh:mm[:ss[.f]][Z|±hh[:mm]]" → ns since the Unix epoch (UTC); hasZone tells whether
// the text said Z or an offset.
bool parseIsoDateTime(std::string_view text, qint64& ns, bool& hasZone);
// A number of the cell: an integer exactly (ns stamps need 64 bits), otherwise a double.
// scaleNs: nanoseconds per unit. false if the text is not a number or out of range.
bool parseScaledInstant(std::string_view text, double scaleNs, qint64& ns);

// ISO 8601 UTC with only the needed fraction digits (groups of 3): "2024-12-18T05:58:05.317590607Z".
QString formatUtc(qint64 ns);
// "hh:mm:ss[.fff]" of a time of day.
QString formatTimeOfDay(qint64 nsOfDay);
// An ISO 8601 date-time (the --start option); no zone = UTC.
Expected<qint64> parseUtc(const QString& text);

// Where t = 0 is in absolute time.
struct TimeBase {
    bool known = false;          // t0Ns is an instant: ns since the Unix epoch (UTC)
    bool timeOfDayOnly = false;  // t0Ns is ns since midnight of a day the file does not tell
    qint64 t0Ns = 0;
};
// Writes "t0_utc" (or "t0_time_of_day") and "time_format" into a stream's attributes.
void writeTimeAttributes(QJsonObject& attributes, const TimeBase& base, const QString& formatName);
// Shifts t so that it starts at 0 and moves t0 with it (absolute formats, after a sort).
void startAtZero(std::vector<double>& t, TimeBase& base);

// A warning if the typical spacing of times (median of the positive steps, in s) implies an
// absurd sampling rate for the stated time format (above 20 kHz, or one sample per hour or less),
// else empty. what names the file and column.
QString samplingRateWarning(const std::vector<double>& t, const QString& formatName, const QString& what);

}  // namespace athlos
