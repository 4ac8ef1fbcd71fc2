// Time as it appears in real files: the formats, the absolute start (t0_utc), clock times with and
// without a date, nanosecond epochs, Excel days, device uptime, the --time-column split and the
// sampling-rate warning; every error names the file, line and column.
#include "TestFiles.h"
#include "core/io/CsvImporter.h"
#include "core/io/Importer.h"
#include "core/io/TimeFormats.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;

namespace {

qint64 isoNs(const char* text) {
    qint64 ns = 0;
    bool zone = false;
    EXPECT_TRUE(parseIsoDateTime(text, ns, zone)) << text;
    return ns;
}

void expectTimes(const std::vector<double>& t, const std::vector<double>& expected) {
    ASSERT_EQ(t.size(), expected.size());
    for (size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], expected[i], 1e-12) << "sample " << i;
}

class TimeImport : public ::testing::Test {
protected:
    Expected<ImportResult> import(const QByteArray& content, const QString& timeColumn, const QString& format,
                                  const QString& kind = QStringLiteral("imu")) {
        ImportOptions options;
        options.format = QStringLiteral("csv");
        options.kind = kind;
        options.target = QStringLiteral("rec");
        options.timeColumn = timeColumn;
        options.timeUnit = format;
        options.date = date;
        options.start = start;
        return importFile(test::writeFile(dir_, QStringLiteral("f.csv"), content), options);
    }
    static const Stream& stream(const ImportResult& r) { return std::get<Stream>(r.items.at(0).item); }
    static std::vector<double> times(const ImportResult& r) { return (*stream(r).data())->t; }
    static QString attribute(const ImportResult& r, const char* key) {
        return stream(r).info().attributes.value(QLatin1String(key)).toString();
    }
    QString date, start;

private:
    QTemporaryDir dir_;
};

}  // namespace

TEST(TimeFormats, NamesAndErrors) {
    EXPECT_EQ(parseTimeFormat("")->kind, TimeKind::Duration);
    EXPECT_EQ(parseTimeFormat("ms")->scale, 1e-3);
    EXPECT_EQ(parseTimeFormat("\u00B5s")->scale, 1e-6);
    EXPECT_EQ(parseTimeFormat("d")->scale, 86400.0);
    EXPECT_EQ(parseTimeFormat("min")->scale, 60.0);
    EXPECT_EQ(parseTimeFormat("HH:mm:ss.SSS")->kind, TimeKind::Clock);
    EXPECT_EQ(parseTimeFormat("hh:mm:ss")->kind, TimeKind::Clock);
    EXPECT_EQ(parseTimeFormat("unix_ns")->scale, 1e-9);
    EXPECT_EQ(parseTimeFormat("epoch_ms")->kind, TimeKind::Unix);
    EXPECT_EQ(parseTimeFormat("ISO")->kind, TimeKind::Iso);
    EXPECT_EQ(parseTimeFormat("excel")->kind, TimeKind::Excel);
    EXPECT_EQ(parseTimeFormat("uptime_ms")->kind, TimeKind::Uptime);
    const auto bad = parseTimeFormat("fortnights");
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("unknown time format 'fortnights' (accepted: s, ms"))
        << qPrintable(bad.message());
    EXPECT_FALSE(parseTimeFormat("m").ok());  // metres are no time
}

TEST(TimeFormats, TimeColumnSpecSplitsAtTheFormat) {
    EXPECT_EQ(*splitTimeColumnSpec("Time:hh:mm:ss"), std::pair(QString("Time"), QString("hh:mm:ss")));
    EXPECT_EQ(*splitTimeColumnSpec("Time:hh:mm:ss.fff"), std::pair(QString("Time"), QString("hh:mm:ss.fff")));
    EXPECT_EQ(*splitTimeColumnSpec("Time:ms"), std::pair(QString("Time"), QString("ms")));
    EXPECT_EQ(*splitTimeColumnSpec("%time:unix_ns"), std::pair(QString("%time"), QString("unix_ns")));
    EXPECT_EQ(*splitTimeColumnSpec("Time"), std::pair(QString("Time"), QString()));
    const auto bad = splitTimeColumnSpec("Time:parsecs");
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("unknown time format 'parsecs'"));
}

TEST(TimeFormats, ParsesAndFormatsInstants) {
    EXPECT_EQ(formatUtc(0), QStringLiteral("1970-01-01T00:00:00Z"));
    EXPECT_EQ(formatUtc(isoNs("2024-02-29T23:59:59.5Z")), QStringLiteral("2024-02-29T23:59:59.500Z"));
    EXPECT_EQ(formatUtc(isoNs("2024-05-01 13:45:01.123456789+02:00")),
              QStringLiteral("2024-05-01T11:45:01.123456789Z"));
    EXPECT_EQ(formatUtc(isoNs("2024-05-01T13:45-0130")), QStringLiteral("2024-05-01T15:15:00Z"));
    EXPECT_EQ(formatUtc(-1000000), QStringLiteral("1969-12-31T23:59:59.999Z"));
    qint64 ns = 0;
    bool zone = true;
    EXPECT_TRUE(parseIsoDateTime("2024-05-01T13:45:01", ns, zone));
    EXPECT_FALSE(zone);
    EXPECT_FALSE(parseIsoDateTime("2024-02-30T00:00:00Z", ns, zone));
    EXPECT_FALSE(parseIsoDateTime("2024-05-01T25:00:00Z", ns, zone));
    EXPECT_FALSE(parseIsoDateTime("yesterday", ns, zone));
    EXPECT_TRUE(parseClockTime("9:05:01,25", ns));
    EXPECT_EQ(ns, (9 * 3600 + 5 * 60 + 1) * kNsPerSecond + 250000000);
    EXPECT_FALSE(parseClockTime("12:60:00", ns));
    EXPECT_FALSE(parseClockTime("12:00", ns));
    EXPECT_TRUE(parseScaledInstant("1734501485317590607", 1.0, ns));
    EXPECT_EQ(ns, 1734501485317590607LL);  // exact: no detour through double
    EXPECT_TRUE(parseScaledInstant("1734501485.25", 1e9, ns));
    EXPECT_EQ(ns, 1734501485250000000LL);
    EXPECT_FALSE(parseScaledInstant("1e30", 1e9, ns));
    EXPECT_EQ(*parseUtc("2024-05-01"), isoNs("2024-05-01T00:00:00Z"));
    EXPECT_FALSE(parseUtc("May 1st").ok());
}

TEST_F(TimeImport, ClockTimesTakeTheDateFromAColumn) {
    const auto r =
        import("Date,Time,acc_x\n2024-05-01,23:59:59.500,1\n2024-05-02,00:00:00.000,2\n2024-05-02,00:00:00.500,3\n",
               "Time", "hh:mm:ss.fff");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    expectTimes(times(*r), {0.0, 0.5, 1.0});
    EXPECT_EQ(attribute(*r, "t0_utc"), QStringLiteral("2024-05-01T23:59:59.500Z"));
    EXPECT_EQ(stream(*r).info().columns.size(), 1u);  // the date column is not data
    EXPECT_TRUE(r->warnings.isEmpty()) << qPrintable(r->warnings.join('\n'));
}

TEST_F(TimeImport, ClockTimesWithoutADateRollOverAndWarn) {
    const QByteArray text = "Time,acc_x\n23:59:59,1\n00:00:00,2\n00:00:01,3\n";
    const auto r = import(text, "Time", "hh:mm:ss");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    expectTimes(times(*r), {0.0, 1.0, 2.0});
    EXPECT_EQ(attribute(*r, "t0_time_of_day"), QStringLiteral("23:59:59"));
    EXPECT_TRUE(attribute(*r, "t0_utc").isEmpty());
    ASSERT_EQ(r->warnings.size(), 1);
    EXPECT_TRUE(r->warnings[0].contains("clock times without a date")) << qPrintable(r->warnings[0]);
    date = QStringLiteral("2023-12-31");
    const auto dated = import(text, "Time", "hh:mm:ss");
    ASSERT_TRUE(dated.ok());
    EXPECT_EQ(attribute(*dated, "t0_utc"), QStringLiteral("2023-12-31T23:59:59Z"));
    EXPECT_TRUE(dated->warnings.isEmpty());
}

TEST_F(TimeImport, IsoDateTimes) {
    const auto r = import("when,acc_x\n2024-05-01T10:00:00.000+02:00,1\n2024-05-01T08:00:00.010Z,2\n", "when", "iso");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    expectTimes(times(*r), {0.0, 0.01});
    EXPECT_EQ(attribute(*r, "t0_utc"), QStringLiteral("2024-05-01T08:00:00Z"));
    EXPECT_EQ(attribute(*r, "time_format"), QStringLiteral("iso"));
    const auto local = import("when,acc_x\n2024-05-01 10:00:00,1\n2024-05-01 10:00:01,2\n", "when", "iso");
    ASSERT_TRUE(local.ok());
    ASSERT_EQ(local->warnings.size(), 1);
    EXPECT_TRUE(local->warnings[0].contains("taken as UTC"));
}

TEST_F(TimeImport, UnixEpochsKeepNanoseconds) {
    const auto ns = import("stamp,acc_x\n1734501485317590607,1\n1734501485417273454,2\n", "stamp", "unix_ns");
    ASSERT_TRUE(ns.ok()) << qPrintable(ns.message());
    expectTimes(times(*ns), {0.0, 0.099682847});
    EXPECT_EQ(attribute(*ns, "t0_utc"), QStringLiteral("2024-12-18T05:58:05.317590607Z"));
    const auto ms = import("stamp,acc_x\n1714557600000,1\n1714557600010,2\n", "stamp", "unix_ms");
    ASSERT_TRUE(ms.ok());
    expectTimes(times(*ms), {0.0, 0.01});
    EXPECT_EQ(attribute(*ms, "t0_utc"), QStringLiteral("2024-05-01T10:00:00Z"));
    const auto s = import("stamp,acc_x\n1714557600.5,1\n1714557601.5,2\n", "stamp", "unix");
    ASSERT_TRUE(s.ok());
    EXPECT_EQ(attribute(*s, "t0_utc"), QStringLiteral("2024-05-01T10:00:00.500Z"));
}

TEST_F(TimeImport, ExcelSerialDays) {
    // 45413 = 2024-05-01; 0.5 days = noon; one second = 1/86400 day.
    const auto r = import("Serial,acc_x\n45413.5,1\n45413.50001157407,2\n", "Serial", "excel");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(attribute(*r, "t0_utc"), QStringLiteral("2024-05-01T12:00:00Z"));
    EXPECT_NEAR(times(*r)[1], 1.0, 1e-6);
}

TEST_F(TimeImport, DurationsAndUptimeKeepTheirOrigin) {
    start = QStringLiteral("2024-05-01T10:00:00Z");
    const auto r = import("up,acc_x\n5000,1\n5010,2\n", "up", "uptime_ms");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    expectTimes(times(*r), {5.0, 5.01});
    EXPECT_EQ(attribute(*r, "time_base"), QStringLiteral("device uptime"));
    EXPECT_EQ(attribute(*r, "t0_utc"), QStringLiteral("2024-05-01T10:00:00Z"));
    const auto d = import("t,acc_x\n0,1\n0.5,2\n", "t", "min");
    ASSERT_TRUE(d.ok());
    expectTimes(times(*d), {0.0, 30.0});
    start = QStringLiteral("not a time");
    const auto bad = import("t,acc_x\n0,1\n1,2\n", "", "");
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("start: 'not a time' is not an ISO 8601 date-time"))
        << qPrintable(bad.message());
}

TEST_F(TimeImport, HeaderUnitIsATimeFormatToo) {
    const auto r =
        import("Time (hh:mm:ss.fff),Date,acc_x\n10:00:00.000,2024-05-01,1\n10:00:00.020,2024-05-01,2\n", "", "");
    // Not 't', but named like time: its header unit is the format (and the date comes from 'Date').
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(attribute(*r, "t0_utc"), QStringLiteral("2024-05-01T10:00:00Z"));
    const auto named =
        import("t (hh:mm:ss.fff),Date,acc_x\n10:00:00.000,2024-05-01,1\n10:00:00.020,2024-05-01,2\n", "", "");
    ASSERT_TRUE(named.ok()) << qPrintable(named.message());
    EXPECT_EQ(attribute(*named, "t0_utc"), QStringLiteral("2024-05-01T10:00:00Z"));
}

TEST_F(TimeImport, BadCellsNameFileLineAndColumn) {
    auto r = import("Date,Time,acc_x\n2024-05-01,10:00:00,1\n2024-05-01,10:0x:01,2\n", "Time", "hh:mm:ss");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().endsWith(
        "f.csv:3:2 (column 'Time'): '10:0x:01' is not a clock time hh:mm:ss[.fff] (time format 'hh:mm:ss')"))
        << qPrintable(r.message());
    r = import("Date,Time,acc_x\n2024-05-01,10:00:00,1\n2024-13-01,10:00:01,2\n", "Time", "hh:mm:ss");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().endsWith("f.csv:3:1 (column 'Date'): '2024-13-01' is not a date YYYY-MM-DD"))
        << qPrintable(r.message());
    r = import("when,acc_x\n2024-05-01T10:00:00Z,1\nsoon,2\n", "when", "iso");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("f.csv:3:1 (column 'when'): 'soon' is not an ISO 8601 date-time"))
        << qPrintable(r.message());
    r = import("stamp,acc_x\n1714557600000,1\n,2\n", "stamp", "unix_ms");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("f.csv:3:1 (column 'stamp'): empty time")) << qPrintable(r.message());
    r = import("stamp,acc_x\n1714557600000,1\nabc,2\n", "stamp", "unix_ms");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("f.csv:3:1 (column 'stamp'): 'abc' is not a number (time format 'unix_ms')"))
        << qPrintable(r.message());
    r = import("stamp,acc_x\n1,1\n2,2\n", "stamp", "furlongs");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("unknown time format 'furlongs'")) << qPrintable(r.message());
    date = QStringLiteral("01.05.2024");
    r = import("Time,acc_x\n10:00:00,1\n10:00:01,2\n", "Time", "hh:mm:ss");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("date '01.05.2024': expected YYYY-MM-DD")) << qPrintable(r.message());
}

TEST_F(TimeImport, AbsurdSamplingRateWarns) {
    // Milliseconds declared as seconds: one sample every 10 s "at 100 Hz".
    QByteArray slow = "t,acc_x\n", fast = "t,acc_x\n";
    for (int i = 0; i < 10; ++i) {
        slow += QByteArray::number(i * 3600 * 2) + ",1\n";
        fast += QByteArray::number(i * 10) + ",1\n";
    }
    auto r = import(slow, "", "");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->warnings.size(), 1);
    EXPECT_TRUE(r->warnings[0].contains("samples are 7.2e+03 s apart (2 h); is the time format right?"))
        << qPrintable(r->warnings[0]);
    r = import(fast, "t", "us");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->warnings.size(), 1);
    EXPECT_TRUE(r->warnings[0].contains("with time format 'us' the samples are 1e-05 s apart (100 kHz)"))
        << qPrintable(r->warnings[0]);
    r = import(fast, "t", "ms");  // 100 Hz: fine
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r->warnings.isEmpty());
}

TEST(TimeFormats, GuessesTheFormatOfAFirstTimeStamp) {
    EXPECT_EQ(guessTimeFormat("10:00:00"), QStringLiteral("hh:mm:ss"));
    EXPECT_EQ(guessTimeFormat(" 9:59:59.25 "), QStringLiteral("hh:mm:ss"));
    EXPECT_EQ(guessTimeFormat("2024-05-01T10:00:00.250Z"), QStringLiteral("iso"));
    EXPECT_EQ(guessTimeFormat("2024-05-01 10:00:00"), QStringLiteral("iso"));
    EXPECT_EQ(guessTimeFormat("1714557600"), QStringLiteral("unix"));
    EXPECT_EQ(guessTimeFormat("1714557600.5"), QStringLiteral("unix"));
    EXPECT_EQ(guessTimeFormat("1714557600250"), QStringLiteral("unix_ms"));
    EXPECT_EQ(guessTimeFormat("1714557600250000"), QStringLiteral("unix_us"));
    EXPECT_EQ(guessTimeFormat("1734501485317590607"), QStringLiteral("unix_ns"));  // the ROS stamps of shared/data
    // Durations: seconds since a start, however long, and numbers outside 2000–2100 in every unit.
    EXPECT_EQ(guessTimeFormat("0"), QString());
    EXPECT_EQ(guessTimeFormat("12.5"), QString());
    EXPECT_EQ(guessTimeFormat("86400"), QString());
    EXPECT_EQ(guessTimeFormat("5e8"), QString());
    EXPECT_EQ(guessTimeFormat("-1714557600"), QString());
    EXPECT_EQ(guessTimeFormat("nan"), QString());
    EXPECT_EQ(guessTimeFormat("24 Jul"), QString());
}

// No 't' column and no --time-column: a column named like time is the time column, in the format
// its first value shows, with a warning that says so.
TEST_F(TimeImport, ATimeLikeColumnIsTheTimeColumnInTheFormatItShows) {
    const auto clock = import("Time,acc_x\n10:00:00.000,1\n10:00:00.500,2\n10:00:01.000,3\n", "", "");
    ASSERT_TRUE(clock.ok()) << qPrintable(clock.message());
    expectTimes(times(*clock), {0.0, 0.5, 1.0});
    EXPECT_EQ(attribute(*clock, "t0_time_of_day"), QStringLiteral("10:00:00"));
    ASSERT_FALSE(clock->warnings.isEmpty());
    EXPECT_TRUE(clock->warnings[0].contains("column 'Time' taken as the time column, format hh:mm:ss"))
        << qPrintable(clock->warnings[0]);

    const auto epoch = import("Timestamp,acc_x\n1714557600250,1\n1714557600260,2\n", "", "");
    ASSERT_TRUE(epoch.ok()) << qPrintable(epoch.message());
    expectTimes(times(*epoch), {0.0, 0.01});
    EXPECT_EQ(attribute(*epoch, "t0_utc"), QStringLiteral("2024-05-01T10:00:00.250Z"));

    const auto seconds = import("Elapsed Time,acc_x\n0,1\n0.01,2\n", "", "");
    ASSERT_TRUE(seconds.ok()) << qPrintable(seconds.message());
    expectTimes(times(*seconds), {0.0, 0.01});
    EXPECT_TRUE(seconds->warnings.join('\n').contains("in seconds")) << qPrintable(seconds->warnings.join('\n'));

    // A header unit wins over the guess; an interchange 't' column is never second-guessed.
    const auto unit = import("time [ms],acc_x\n0,1\n10,2\n", "", "");
    ASSERT_TRUE(unit.ok()) << qPrintable(unit.message());
    expectTimes(times(*unit), {0.0, 0.01});
    const auto plain = import("t,Time,acc_x\n0,10:00:00,1\n1,10:00:01,2\n", "", "");
    EXPECT_FALSE(plain.ok());  // 'Time' is text in a data column: refused with file:line:column, not taken as time
}
