// Vendor exports detected from their content and imported with one command. The samples are written
// from the vendors' published layouts as the author knows them (no vendor file or web access was
// available while writing these tests):
//   STATSports: Apex/Sonra "raw data" export, 10 Hz: Player Display Name, Time, Elapsed Time (s), Lat, Lon,
//     Speed (m/s), Instantaneous Acceleration Impulse, Heart Rate (bpm) (STATSports Apex user guide, export).
//   Catapult: OpenField raw CSV export: '#' preamble lines, then Timestamp, Seconds, Velocity, Acceleration,
//     Odometer, Latitude, Longitude, Heart Rate, Player Load, Positional Quality (%), HDOP, #Sats
//     (Catapult OpenField export documentation).
//   Kinexon: position export, one row per player and time stamp: ts in ms, sensor id, mapped id, full name,
//     x in m, y in m, z in m, speed in m/s (Kinexon export format description).
//   Metrica Sports: github.com/metrica-sports/sample-data, Sample_Game_1_RawTrackingData_Home_Team.csv
//     (three header rows: team, jersey number, Period,Frame,Time [s],PlayerN,,…,Ball,; NaN off the pitch).
//   GPX 1.1: https://www.topografix.com/GPX/1/1/ with Garmin's TrackPointExtension (gpxtpx:hr, gpxtpx:cad).
#include "TestFiles.h"
#include "core/io/Importer.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <cmath>

using namespace athlos;

namespace {

class Vendor : public ::testing::Test {
protected:
    Expected<ImportResult> import(const QString& name, const QByteArray& content, const QString& expectedFormat) {
        const QString file = test::writeFile(dir_, name, content);
        const auto chosen = chooseImporter(file, QStringLiteral("auto"));
        EXPECT_TRUE(chosen.ok()) << qPrintable(chosen.message());
        if (chosen) {
            EXPECT_EQ((*chosen)->format(), expectedFormat);
        }
        ImportOptions o;
        o.target = QStringLiteral("s");
        return importFile(file, o);
    }
    static const Stream& stream(const ImportResult& r, size_t i = 0) { return std::get<Stream>(r.items.at(i).item); }
    static QStringList columns(const Stream& s) {
        QStringList n;
        for (const Column& c : s.info().columns) n << c.name + QLatin1Char('[') + c.unit + QLatin1Char(']');
        return n;
    }

private:
    QTemporaryDir dir_;
};

}  // namespace

TEST_F(Vendor, StatsportsWholeSessionAsGnss) {
    // A session over midnight at 10 Hz: every row imports, t runs on past 00:00.
    QByteArray text =
        "Player Display Name,Time,Elapsed Time (s),Lat,Lon,Speed (m/s),Instantaneous Acceleration Impulse,Heart Rate "
        "(bpm)\n";
    for (int i = 0; i < 30; ++i) {
        const int tenths = 23 * 36000 + 59 * 600 + 590 + i;  // from 23:59:59.0
        const int s = (tenths / 10) % 86400;
        text += QStringLiteral("Anna Berg,%1:%2:%3.%4,%5,53.2707,-6.2011,%6,0.1,%7\n")
                    .arg(s / 3600, 2, 10, QLatin1Char('0'))
                    .arg(s / 60 % 60, 2, 10, QLatin1Char('0'))
                    .arg(s % 60, 2, 10, QLatin1Char('0'))
                    .arg(tenths % 10)
                    .arg(i / 10.0)
                    .arg(3.5)
                    .arg(150)
                    .toLatin1();
    }
    const auto r = import("session.csv", text, "statsports");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_EQ(r->items.size(), 1u);
    const Stream& s = stream(*r);
    EXPECT_EQ(s.kind(), QStringLiteral("gnss"));
    EXPECT_EQ(columns(s), (QStringList{"elapsed[s]", "lat[deg]", "lon[deg]", "speed[m/s]", "acc_impulse[]", "hr[Hz]"}));
    const auto d = *s.data();
    ASSERT_EQ(d->rows(), 30u);
    EXPECT_NEAR(d->t.back(), 2.9, 1e-9);
    EXPECT_NEAR(d->at(0, 5), 2.5, 1e-12);  // 150 bpm
    EXPECT_EQ(s.info().attributes.value("athlete").toString(), QStringLiteral("Anna Berg"));
    EXPECT_EQ(s.info().attributes.value("t0_time_of_day").toString(), QStringLiteral("23:59:59"));
}

TEST_F(Vendor, CatapultOpenField) {
    const auto r = import("openfield.csv",
                          "# OpenField Export : Athlete Raw Data\n"
                          "Timestamp,Seconds,Velocity,Acceleration,Odometer,Latitude,Longitude,Heart Rate,Player Load,"
                          "Positional Quality (%),HDOP,#Sats\n"
                          "10:00:00,0.0,1.2,0.1,0.0,-37.8136,144.9631,120,0.0,85,0.8,12\n"
                          "10:00:00,0.1,1.3,0.2,0.12,-37.81361,144.96311,121,0.01,86,0.8,12\n",
                          "catapult");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Stream& s = stream(*r);
    EXPECT_EQ(columns(s), (QStringList{"speed[m/s]", "acc[m/s^2]", "distance[m]", "lat[deg]", "lon[deg]", "hr[Hz]",
                                       "player_load[]", "quality[1]", "hdop[1]", "sats[1]"}));
    EXPECT_NEAR((*s.data())->at(1, 7), 0.86, 1e-12);
}

TEST_F(Vendor, KinexonPlayersBecomeStreams) {
    const auto r = import("kinexon.csv",
                          "ts in ms,sensor id,mapped id,full name,x in m,y in m,z in m,speed in m/s\n"
                          "1714557600000,101,7,Anna Berg,1.0,2.0,0.0,3.0\n"
                          "1714557600000,102,9,Ben Lee,-5.0,3.0,0.0,2.0\n"
                          "1714557600050,101,7,Anna Berg,1.1,2.0,0.0,3.1\n"
                          "1714557600050,102,9,Ben Lee,-5.1,3.0,0.0,2.1\n",
                          "kinexon");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_EQ(r->items.size(), 2u);
    EXPECT_EQ(r->items[0].path, QStringLiteral("s/anna-berg"));
    EXPECT_EQ(r->items[1].path, QStringLiteral("s/ben-lee"));
    const Stream& ben = stream(*r, 1);
    EXPECT_EQ(ben.kind(), QStringLiteral("lps-position"));
    EXPECT_EQ(ben.info().attributes.value("athlete").toString(), QStringLiteral("Ben Lee"));
    EXPECT_EQ(ben.info().attributes.value("t0_utc").toString(), QStringLiteral("2024-05-01T10:00:00Z"));
    const auto d = *ben.data();
    ASSERT_EQ(d->rows(), 2u);
    EXPECT_NEAR(d->t[1], 0.05, 1e-12);
    EXPECT_EQ(d->at(1, 0), -5.1);
    // A bad cell names the line of the original file.
    const auto bad = import("kinexon-bad.csv",
                            "ts in ms,sensor id,mapped id,full name,x in m,y in m,z in m,speed in m/s\n"
                            "1714557600000,101,7,Anna Berg,1.0,2.0,0.0,3.0\n"
                            "1714557600000,102,9,Ben Lee,-5.0,abc,0.0,2.0\n",
                            "kinexon");
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("kinexon-bad.csv:3:6 (column 'y in m'): 'abc' is not a number"))
        << qPrintable(bad.message());
}

TEST_F(Vendor, MetricaBothHeaderRows) {
    const auto r = import("Sample_Game_1_RawTrackingData_Home_Team.csv",
                          ",,,Home,,Home,,Home,,,\n"
                          ",,,11,,1,,2,,,\n"
                          "Period,Frame,Time [s],Player11,,Player1,,Player2,,Ball,\n"
                          "1,1,0.04,0.00082,0.48238,0.32648,0.65322,NaN,NaN,0.45472,0.38709\n"
                          "1,2,0.08,0.00096,0.48238,0.32648,0.65322,0.5,0.5,0.49645,0.40656\n",
                          "metrica");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_EQ(r->items.size(), 4u);
    EXPECT_EQ(r->items[0].path, QStringLiteral("s/home-11"));
    EXPECT_EQ(r->items[3].path, QStringLiteral("s/ball"));
    const Stream& p2 = stream(*r, 2);
    EXPECT_EQ(p2.info().attributes.value("team").toString(), QStringLiteral("home"));
    EXPECT_EQ(p2.info().attributes.value("number").toDouble(), 2.0);
    const auto d = *p2.data();
    ASSERT_EQ(d->rows(), 1u);  // off the pitch in frame 1
    EXPECT_EQ(d->t[0], 0.08);
    EXPECT_EQ(d->at(0, 0), 0.0);  // the centre spot
    EXPECT_NEAR((*stream(*r, 0).data())->at(0, 0), (0.00082 - 0.5) * 105.0, 1e-9);
    EXPECT_NEAR((*stream(*r, 0).data())->at(0, 1), (0.5 - 0.48238) * 68.0, 1e-9);
}

TEST_F(Vendor, Gpx) {
    const auto r = import("ride.gpx", R"(<?xml version="1.0" encoding="UTF-8"?>
<gpx version="1.1" creator="test" xmlns="http://www.topografix.com/GPX/1/1"
     xmlns:gpxtpx="http://www.garmin.com/xmlschemas/TrackPointExtension/v1">
  <trk><name>Morning run</name><trkseg>
    <trkpt lat="47.3700" lon="8.5400"><ele>408.0</ele><time>2024-05-01T06:00:00Z</time>
      <extensions><gpxtpx:TrackPointExtension><gpxtpx:hr>120</gpxtpx:hr><gpxtpx:cad>84</gpxtpx:cad></gpxtpx:TrackPointExtension></extensions>
    </trkpt>
    <trkpt lat="47.3701" lon="8.5401"><ele>408.5</ele><time>2024-05-01T06:00:01Z</time></trkpt>
  </trkseg></trk>
</gpx>
)",
                          "gpx");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Stream& s = stream(*r);
    EXPECT_EQ(columns(s), (QStringList{"lat[deg]", "lon[deg]", "alt[m]", "hr[Hz]", "cad[Hz]"}));
    EXPECT_EQ(s.info().attributes.value("t0_utc").toString(), QStringLiteral("2024-05-01T06:00:00Z"));
    const auto d = *s.data();
    EXPECT_EQ(d->t, (std::vector<double>{0.0, 1.0}));
    EXPECT_EQ(d->at(0, 3), 2.0);
    EXPECT_TRUE(std::isnan(d->at(1, 3)));
    const auto bad = import("bad.gpx",
                            "<gpx>\n<trk><trkseg>\n  <trkpt lat=\"47.37\" "
                            "lon=\"east\"><time>2024-05-01T06:00:00Z</time></trkpt>\n</trkseg></trk></gpx>\n",
                            "gpx");
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("bad.gpx:3:") && bad.message().contains("lon 'east' is not a longitude"))
        << qPrintable(bad.message());
    const auto untimed =
        import("untimed.gpx", "<gpx>\n<trk><trkseg><trkpt lat=\"1\" lon=\"2\"/></trkseg></trk></gpx>\n", "gpx");
    ASSERT_FALSE(untimed.ok());
    EXPECT_TRUE(untimed.message().contains("untimed.gpx:2:") && untimed.message().contains("has no <time>"))
        << qPrintable(untimed.message());
}
