// NMEA-0183 import: RMC/GGA/VTG merging, units, checksum errors with line numbers, field errors.
#include "core/io/NmeaImporter.h"

#include "TestFiles.h"
#include "core/io/Importer.h"

#include "tests/SharedData.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <cmath>

using namespace athlos;

namespace {
// Appends the correct checksum to a sentence body (without '$').
QByteArray sentence(const QByteArray& body) {
    int sum = 0;
    for (char c : body) sum ^= static_cast<unsigned char>(c);
    return "$" + body + "*" + QByteArray::number(sum, 16).rightJustified(2, '0').toUpper() + "\r\n";
}
}  // namespace

TEST(NmeaImporter, MergesRmcGgaVtgPerEpoch) {
    QByteArray text;
    text += sentence("GPGGA,123519.00,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,");
    text += sentence("GPRMC,123519.00,A,4807.038,N,01131.000,E,10.0,90.0,230394,003.1,W");
    text += sentence("GNGGA,123519.10,4807.039,N,01131.001,E,1,09,1.0,545.6,M,46.9,M,,");
    text += sentence("GNVTG,0.0,T,,M,3.888,N,7.2,K,A");
    const auto r = NmeaImporter::parse(text, QStringLiteral("walk.nmea"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_EQ(r->items.size(), 1u);
    const Stream& s = std::get<Stream>(r->items[0].item);
    EXPECT_EQ(s.kind(), QStringLiteral("gnss"));
    const auto data = *s.data();
    ASSERT_EQ(data->rows(), 2u);
    EXPECT_EQ(data->t[0], 0.0);  // t from the first fix; its UTC time with the RMC date:
    EXPECT_EQ(s.info().attributes.value("t0_utc").toString(), QStringLiteral("1994-03-23T12:35:19Z"));
    EXPECT_NEAR(data->t[1], 0.1, 1e-9);
    EXPECT_NEAR(data->at(0, 0), 48 + 7.038 / 60, 1e-12);  // lat
    EXPECT_NEAR(data->at(0, 1), 11 + 31.0 / 60, 1e-12);   // lon
    EXPECT_NEAR(data->at(0, 2), 545.4, 1e-12);            // alt
    EXPECT_NEAR(data->at(0, 3), 0.0, 1e-9);               // vn: course 90° = east
    EXPECT_NEAR(data->at(0, 4), 10.0 * 1852.0 / 3600.0, 1e-9);
    EXPECT_TRUE(std::isnan(data->at(0, 5)));  // vd unknown
    EXPECT_EQ(s.info().columns[6].name, QStringLiteral("fix"));
    EXPECT_NEAR(data->at(0, 6), 1.0, 1e-12);  // fix quality
    EXPECT_NEAR(data->at(0, 7), 8.0, 1e-12);  // sats
    EXPECT_NEAR(data->at(0, 8), 0.9, 1e-12);  // hdop
    EXPECT_NEAR(data->at(1, 3), 2.0, 1e-9);   // VTG 7.2 km/h due north
    EXPECT_NEAR(data->at(1, 7), 9.0, 1e-12);
    EXPECT_TRUE(r->warnings.isEmpty()) << qPrintable(r->warnings.join('\n'));
}

TEST(NmeaImporter, ChecksumErrorsAreSkippedWithLineNumbers) {
    QByteArray text;
    text += sentence("GPGGA,000001.00,0100.000,S,00200.000,W,1,05,1.2,10.0,M,0.0,M,,");
    text += "$GPGGA,000002.00,0100.000,S,00200.000,W,1,05,1.2,10.0,M,0.0,M,,*00\r\n";  // line 2: bad
    text += sentence("GPGGA,000003.00,0100.000,S,00200.000,W,1,05,1.2,10.0,M,0.0,M,,");
    const auto r = NmeaImporter::parse(text, QStringLiteral("f.nmea"));
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->warnings.size(), 2);  // the checksum, and no date (GGA only)
    EXPECT_TRUE(r->warnings[0].startsWith(QStringLiteral("f.nmea:2:65: checksum"))) << qPrintable(r->warnings[0]);
    EXPECT_TRUE(r->warnings[1].contains(QStringLiteral("no RMC sentence with a date"))) << qPrintable(r->warnings[1]);
    const auto data = *std::get<Stream>(r->items[0].item).data();
    EXPECT_EQ(data->rows(), 2u);
    EXPECT_NEAR(data->at(0, 0), -(1.0), 1e-12);
    EXPECT_NEAR(data->at(0, 1), -(2.0), 1e-12);
}

TEST(NmeaImporter, BadFieldIsAnErrorNamingLineAndField) {
    QByteArray text;
    text += sentence("GPRMC,120000.00,A,4807.038,N,01131.000,E,0.0,0.0,010120,,");
    text += sentence("GPRMC,120001.00,A,48x7.038,N,01131.000,E,0.0,0.0,010120,,");
    const auto r = NmeaImporter::parse(text, QStringLiteral("g.nmea"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().startsWith(QStringLiteral("g.nmea:2:20: RMC sentence"))) << qPrintable(r.message());
    EXPECT_TRUE(r.message().contains(QStringLiteral("latitude")));
}

TEST(NmeaImporter, NoFixEpochsAreLeftOutAndMidnightRollsOver) {
    QByteArray text;
    text += sentence("GPRMC,235959.00,A,0000.000,N,00000.000,E,0.0,0.0,010120,,");
    text += sentence("GPRMC,000000.00,V,0000.000,N,00000.000,E,0.0,0.0,020120,,");
    text += sentence("GPRMC,000001.00,A,0000.000,N,00000.000,E,0.0,0.0,020120,,");
    const auto r = NmeaImporter::parse(text, QStringLiteral("h.nmea"));
    ASSERT_TRUE(r.ok());
    const auto data = *std::get<Stream>(r->items[0].item).data();
    ASSERT_EQ(data->rows(), 2u);
    EXPECT_NEAR(data->t[1] - data->t[0], 2.0, 1e-9);
    EXPECT_FALSE(NmeaImporter::parse("$GPTXT,hello*00\n", QStringLiteral("x")).ok());
}

// A long log as loggers write it: binary bytes before the first sentence, a no-fix epoch stamped
// 23:59:59 (a stale receiver clock), then an hour of fixes after midnight. No false roll-over: the
// duration is the hour, and the start is the first fix's date and time.
TEST(NmeaImporter, BinaryPrefixAndNoFixBeforeMidnightDoNotShiftTheDay) {
    QByteArray text("\x00\x01\xb5\x62\x06\x01\xff\xfe garbage\n", 18);
    text += QByteArray("\xa0\xa2") + sentence("GPGGA,235959.00,,,,,0,00,99.9,,M,,M,,");
    text += sentence("GPRMC,235959.00,V,,,,,,,311223,,");
    for (int s = 0; s <= 3600; ++s) {
        const QByteArray hhmmss = QStringLiteral("%1%2%3.00")
                                      .arg(s / 3600, 2, 10, QLatin1Char('0'))
                                      .arg(s / 60 % 60, 2, 10, QLatin1Char('0'))
                                      .arg(s % 60, 2, 10, QLatin1Char('0'))
                                      .toLatin1();
        text += sentence("GPGGA," + hhmmss + ",4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,");
        text += sentence("GPRMC," + hhmmss + ",A,4807.038,N,01131.000,E,0.0,0.0,010124,,");
    }
    const auto r = NmeaImporter::parse(text, QStringLiteral("long.nmea"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Stream& s = std::get<Stream>(r->items[0].item);
    const auto data = *s.data();
    ASSERT_EQ(data->rows(), 3601u);
    EXPECT_EQ(data->t.front(), 0.0);
    EXPECT_NEAR(data->t.back(), 3600.0, 1e-9);
    EXPECT_EQ(s.info().attributes.value("t0_utc").toString(), QStringLiteral("2024-01-01T00:00:00Z"));

    // The same without RMC (no dates): the day still does not move, the time of day is kept, and
    // the date option completes it.
    QByteArray ggaOnly;
    for (const QByteArray& line : text.split('\n'))
        if (!line.contains("RMC")) ggaOnly += line + '\n';
    const auto g = NmeaImporter::parse(ggaOnly, QStringLiteral("gga.nmea"));
    ASSERT_TRUE(g.ok()) << qPrintable(g.message());
    const Stream& gs = std::get<Stream>(g->items[0].item);
    EXPECT_NEAR((*gs.data())->t.back(), 3600.0, 1e-9);
    EXPECT_EQ(gs.info().attributes.value("t0_time_of_day").toString(), QStringLiteral("00:00:00"));
    ImportOptions options;
    options.date = QStringLiteral("2024-01-01");
    const auto dated = NmeaImporter::parse(ggaOnly, QStringLiteral("gga.nmea"), options);
    ASSERT_TRUE(dated.ok());
    EXPECT_EQ(std::get<Stream>(dated->items[0].item).info().attributes.value("t0_utc").toString(),
              QStringLiteral("2024-01-01T00:00:00Z"));
    EXPECT_TRUE(dated->warnings.isEmpty());

    // Auto-detection sees the sentences behind the binary prefix.
    QTemporaryDir dir;
    const QString file = test::writeFile(dir, QStringLiteral("long.log"), text);
    const auto chosen = chooseImporter(file, QStringLiteral("auto"));
    ASSERT_TRUE(chosen.ok()) << qPrintable(chosen.message());
    EXPECT_EQ((*chosen)->format(), QStringLiteral("nmea"));
}

// A real roll-over: fixes at 23:59:58 and 00:00:01 with RMC dates a day apart; and a GGA-only log.
TEST(NmeaImporter, MidnightWithDatesAndWithout) {
    QByteArray text;
    text += sentence("GPRMC,235958.00,A,0000.000,N,00000.000,E,0.0,0.0,311224,,");
    text += sentence("GPGGA,235959.00,0000.000,N,00000.000,E,1,05,1.0,1.0,M,0.0,M,,");
    text += sentence("GPRMC,000001.00,A,0000.000,N,00000.000,E,0.0,0.0,010125,,");
    const auto r = NmeaImporter::parse(text, QStringLiteral("m.nmea"));
    ASSERT_TRUE(r.ok());
    const Stream& s = std::get<Stream>(r->items[0].item);
    EXPECT_EQ((*s.data())->t, (std::vector<double>{0.0, 1.0, 3.0}));
    EXPECT_EQ(s.info().attributes.value("t0_utc").toString(), QStringLiteral("2024-12-31T23:59:58Z"));
}

TEST(NmeaImporter, BadDateNamesLineAndColumn) {
    const auto r = NmeaImporter::parse(sentence("GPRMC,120000.00,A,4807.038,N,01131.000,E,0.0,0.0,321399,,"),
                                       QStringLiteral("d.nmea"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().startsWith(QStringLiteral("d.nmea:1:51: RMC sentence: cannot read date")))
        << qPrintable(r.message());
}

// The gpsd regression logs: dates from RMC, the start at the first fix, the duration of the fixes.
TEST(NmeaImporter, SharedLogs) {
    struct Case {
        const char* file;
        const char* t0;
        double duration;
        size_t rows;
    };
    for (const Case& c : {Case{"haicom-305N.log", "2007-04-08T09:53:04.802Z", 70.985, 68},
                          Case{"nmea-rtk.log", "2020-03-18T13:28:19.600Z", 641.9, 122}}) {
        const QString file = QString::fromUtf8(ATHLOS_SHARED_DATA_DIR "/nmea/") + QLatin1String(c.file);
        ATHLOS_SKIP_WITHOUT_SHARED(file);
        ImportOptions options;
        options.target = QStringLiteral("g");
        const auto r = importFile(file, options);  // auto-detected despite the leading comments
        ASSERT_TRUE(r.ok()) << qPrintable(r.message());
        const Stream& s = std::get<Stream>(r->items[0].item);
        EXPECT_EQ(s.info().attributes.value("t0_utc").toString(), QLatin1String(c.t0)) << c.file;
        const auto data = *s.data();
        EXPECT_EQ(data->rows(), c.rows) << c.file;
        EXPECT_NEAR(data->t.back(), c.duration, 1e-6) << c.file;
    }
}
