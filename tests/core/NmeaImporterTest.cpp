// NMEA-0183 import: RMC/GGA/VTG merging, units, checksum errors with line numbers, field errors.
#include "core/io/NmeaImporter.h"

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
    EXPECT_NEAR(data->t[0], 12 * 3600 + 35 * 60 + 19.0, 1e-9);
    EXPECT_NEAR(data->at(0, 0), 48 + 7.038 / 60, 1e-12);  // lat
    EXPECT_NEAR(data->at(0, 1), 11 + 31.0 / 60, 1e-12);   // lon
    EXPECT_NEAR(data->at(0, 2), 545.4, 1e-12);            // alt
    EXPECT_NEAR(data->at(0, 3), 0.0, 1e-9);               // vn: course 90° = east
    EXPECT_NEAR(data->at(0, 4), 10.0 * 1852.0 / 3600.0, 1e-9);
    EXPECT_TRUE(std::isnan(data->at(0, 5)));              // vd unknown
    EXPECT_NEAR(data->at(0, 6), 0.9, 1e-12);              // hdop
    EXPECT_NEAR(data->at(1, 3), 2.0, 1e-9);               // VTG 7.2 km/h due north
    EXPECT_NEAR(data->at(1, 7), 9.0, 1e-12);
}

TEST(NmeaImporter, ChecksumErrorsAreSkippedWithLineNumbers) {
    QByteArray text;
    text += sentence("GPGGA,000001.00,0100.000,S,00200.000,W,1,05,1.2,10.0,M,0.0,M,,");
    text += "$GPGGA,000002.00,0100.000,S,00200.000,W,1,05,1.2,10.0,M,0.0,M,,*00\r\n";  // line 2: bad
    text += sentence("GPGGA,000003.00,0100.000,S,00200.000,W,1,05,1.2,10.0,M,0.0,M,,");
    const auto r = NmeaImporter::parse(text, QStringLiteral("f.nmea"));
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r->warnings.size(), 1);
    EXPECT_TRUE(r->warnings[0].contains(QStringLiteral("f.nmea:2:"))) << qPrintable(r->warnings[0]);
    EXPECT_TRUE(r->warnings[0].contains(QStringLiteral("checksum")));
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
    EXPECT_TRUE(r.message().contains(QStringLiteral("g.nmea:2:"))) << qPrintable(r.message());
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
