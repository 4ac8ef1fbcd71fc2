// Two-way ranging (kind lps-range): the long CSV t,beacon,range stored wide like TDoA and exported
// back; ROS exports of per-anchor range files (../shared/data/uwb-outdoor) imported and merged into
// one stream, and their anchors into one beacon table; folder imports with a roster.
#include "TestFiles.h"
#include "core/io/Exporter.h"
#include "core/io/Importer.h"
#include "core/io/MultiImport.h"
#include "core/io/TdoaLayout.h"

#include "tests/SharedData.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <cmath>

using namespace athlos;

namespace {

const QString kUwb = QString::fromUtf8(ATHLOS_SHARED_DATA_DIR "/uwb-outdoor/LOS_Trajectory_A_Case_1/");

QStringList anchorFiles() {
    QStringList files;
    for (const char* a : {"A3", "A5", "A9", "A12"}) files << kUwb + QLatin1String(a) + QStringLiteral(".csv");
    return files;
}

ImportOptions optionsFor(const QString& kind, const QString& target = QStringLiteral("uwb")) {
    ImportOptions o;
    o.kind = kind;
    o.target = target;
    return o;
}

const Stream& streamOf(const ImportResult& r, size_t i = 0) { return std::get<Stream>(r.items.at(i).item); }

}  // namespace

TEST(LpsRange, LongCsvIsStoredWideAndExportedLong) {
    QTemporaryDir dir;
    const QString file = test::writeFile(dir, "r.csv", "t,beacon,range\n0,A,1.5\n0,B,2.5\n0.1,A,1.6\n0.2,B,2.4\n");
    auto r = importFile(file, optionsFor({}, "rec"));  // inferred from beacon + range
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Stream& s = streamOf(*r);
    EXPECT_EQ(s.kind(), QStringLiteral("lps-range"));
    EXPECT_EQ(r->items[0].path, QStringLiteral("rec/range"));
    ASSERT_EQ(s.info().columns.size(), 2u);
    EXPECT_EQ(s.info().columns[0], (Column{"range_A", "m"}));
    const auto d = *s.data();
    EXPECT_EQ(d->t, (std::vector<double>{0.0, 0.1, 0.2}));
    EXPECT_EQ(d->at(0, 1), 2.5);
    EXPECT_TRUE(std::isnan(d->at(1, 1)));
    EXPECT_EQ(s.info().attributes.value("beacon_ids").toArray(), (QJsonArray{"A", "B"}));

    const QString out = dir.filePath("out.csv");
    ASSERT_TRUE(exportStreamCsv(s, out).ok());
    QFile f(out);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_EQ(f.readAll(), QByteArray("t,beacon,range\n0,A,1.5\n0,B,2.5\n0.1,A,1.6\n0.2,B,2.4\n"));

    // Errors: the long form only, an empty range, a centimetre header converted.
    r = importFile(test::writeFile(dir, "wide.csv", "t,beacon,range,rssi\n0,A,1,2\n"), optionsFor("lps-range", "rec"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("wide.csv:1: kind 'lps-range' has the columns t, beacon, range (long format)"))
        << qPrintable(r.message());
    r = importFile(test::writeFile(dir, "gap.csv", "t,beacon,range\n0,A,1\n0.1,A,\n"), optionsFor("lps-range", "rec"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("gap.csv:3:3 (column 'range'): empty range")) << qPrintable(r.message());
    r = importFile(test::writeFile(dir, "cm.csv", "t,beacon,range [cm]\n0,A,150\n"), optionsFor("lps-range", "rec"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ((*streamOf(*r).data())->at(0, 0), 1.5);
}

TEST(LpsRange, RosAnchorFileIsDetectedWithNanosecondStamps) {
    ATHLOS_SKIP_WITHOUT_SHARED(kUwb + "A3.csv");
    const auto chosen = chooseImporter(kUwb + "A3.csv", "auto");
    ASSERT_TRUE(chosen.ok());
    EXPECT_EQ((*chosen)->format(), QStringLiteral("ros"));
    const auto r = importFile(kUwb + "A3.csv", optionsFor({}));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Stream& s = streamOf(*r);
    EXPECT_EQ(s.kind(), QStringLiteral("lps-range"));
    EXPECT_EQ(s.info().columns, (Columns{{"range_3", "m"}}));
    EXPECT_EQ(s.info().attributes.value("t0_utc").toString(), QStringLiteral("2024-12-18T05:58:05.317395687Z"));
    const auto d = *s.data();
    ASSERT_EQ(d->rows(), 1917u);
    EXPECT_EQ(d->at(0, 0), 7.304449333333333);
    EXPECT_NEAR(d->t[1], 0.099444866, 1e-12);  // field.stamp, not %time
}

TEST(LpsRange, FourAnchorFilesMergeIntoOneStream) {
    ATHLOS_SKIP_WITHOUT_SHARED(kUwb + "A12.csv");
    const auto r = importFiles(anchorFiles(), optionsFor("lps-range"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_EQ(r->items.size(), 1u);
    EXPECT_EQ(r->items[0].path, QStringLiteral("uwb/range"));
    const Stream& s = streamOf(*r);
    EXPECT_EQ(s.info().columns, (Columns{{"range_9", "m"}, {"range_5", "m"}, {"range_3", "m"}, {"range_12", "m"}}));
    EXPECT_EQ(s.info().attributes.value("t0_utc").toString(), QStringLiteral("2024-12-18T05:58:05.315057992Z"));
    const auto d = *s.data();
    EXPECT_EQ(d->rows(), 8405u);  // no two anchors share a stamp
    size_t measured[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < d->rows(); ++i)
        for (int c = 0; c < 4; ++c) measured[c] += !std::isnan(d->at(i, c));
    EXPECT_EQ(measured[0], 2194u);
    EXPECT_EQ(measured[2], 1917u);
    EXPECT_EQ(s.info().provenance.parameters.value("files").toArray().size(), 4);
    EXPECT_EQ(d->firstNonIncreasing(), -1);
}

TEST(LpsRange, AnchorFilesGiveTheBeaconTable) {
    ATHLOS_SKIP_WITHOUT_SHARED(kUwb + "A12.csv");
    const auto r = importFiles(anchorFiles(), optionsFor("beacons"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_EQ(r->items.size(), 1u);
    EXPECT_EQ(r->items[0].path, QStringLiteral("uwb/beacons"));
    const Table& t = std::get<Table>(r->items[0].item);
    ASSERT_EQ(t.rows(), 4);
    EXPECT_EQ(t.column("id")->texts, (QStringList{"3", "5", "9", "12"}));
    EXPECT_EQ(t.column("x")->numbers, (std::vector<double>{2.5775, 2.5775, 2.5775, 0.69}));
    EXPECT_EQ(t.column("y")->numbers, (std::vector<double>{0.87, -0.87, -0.87, 0.87}));
    EXPECT_EQ(t.column("z")->numbers, (std::vector<double>{1.97, 1.97, 0.5, 0.5}));
}

TEST(LpsRange, MergeErrorsNameTheFiles) {
    QTemporaryDir dir;
    // An anchor that moves within one ROS file.
    const QString moving = test::writeFile(dir, "A7.csv",
                                           "%time,field.stamp,field.id,field.x,field.y,field.z,field.distanceFromTag\n"
                                           "1000,1000,7,1.0,2.0,0.5,3.0\n2000,2000,7,1.5,2.0,0.5,3.1\n");
    auto r = importFile(moving, optionsFor("beacons"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("A7.csv:3:4 (column 'x'): anchor '7' has x = 1.5 here but 1 on line 2"))
        << qPrintable(r.message());
    // Two files giving one beacon different positions.
    const QString a = test::writeFile(dir, "a.csv", "id,x,y\nB1,0,0\n");
    const QString b = test::writeFile(dir, "b.csv", "id,x,y\nB1,0,1\n");
    r = importFiles({a, b}, optionsFor("beacons"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("uwb/beacons: 'B1' has y = 0 in a.csv but 1 in b.csv")) << qPrintable(r.message());
    // Pieces of a recording that overlap; and a mix of absolute and relative starts.
    const QString p1 = test::writeFile(dir, "p1.csv", "t,acc_x\n0,1\n1,2\n");
    const QString p2 = test::writeFile(dir, "p2.csv", "t,acc_x\n0.5,1\n2,2\n");
    r = importFiles({p1, p2}, optionsFor("imu"));
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("uwb/imu: p1.csv and p2.csv overlap in time")) << qPrintable(r.message());
    const QString p3 = test::writeFile(dir, "p3.csv", "t,acc_x\n3,1\n4,2\n");
    r = importFiles({p1, p3}, optionsFor("imu"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ((*streamOf(*r).data())->t, (std::vector<double>{0, 1, 3, 4}));
    EXPECT_EQ(r->warnings.size(), 1);  // one clock assumed
    const QString g = test::writeFile(dir, "g.csv", "t,gyr_x\n5,1\n");
    r = importFiles({p1, g}, optionsFor({}));  // both imu, different columns
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(
        r.message().contains("uwb/imu: p1.csv has the columns acc_x, g.csv has gyr_x; only files with the same "
                             "columns make one stream"))
        << qPrintable(r.message());
}

TEST(FolderImport, OneStreamPerFileWithTheRoster) {
    QTemporaryDir dir;
    QDir(dir.path()).mkdir("team");
    const QString folder = dir.filePath("team");
    test::writeFile(dir, "team/anna.csv", "t,x,y\n0,1,2\n1,2,3\n");
    test::writeFile(dir, "team/ben lee.csv", "t,x,y\n0,5,5\n1,6,6\n");
    test::writeFile(dir, "team/notes.md", "not data\n");
    const QString roster =
        test::writeFile(dir, "roster.csv",
                        "file,athlete,number,team,position,mass_kg\nanna.csv,Anna Berg,7,home,FW,61.5\n"
                        "carl,Carl Dahl,9,away,GK,80\n");
    auto r = importFolder(folder, optionsFor("lps-position", "match"), roster);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_EQ(r->items.size(), 2u);
    EXPECT_EQ(r->items[0].path, QStringLiteral("match/anna"));
    EXPECT_EQ(r->items[1].path, QStringLiteral("match/ben-lee"));
    const QJsonObject a = streamOf(*r, 0).info().attributes;
    EXPECT_EQ(a.value("athlete").toString(), QStringLiteral("Anna Berg"));
    EXPECT_EQ(a.value("label").toString(), QStringLiteral("Anna Berg"));
    EXPECT_EQ(a.value("number").toDouble(), 7.0);
    EXPECT_EQ(a.value("team").toString(), QStringLiteral("home"));
    EXPECT_EQ(a.value("position").toString(), QStringLiteral("FW"));
    EXPECT_EQ(a.value("mass_kg").toDouble(), 61.5);
    EXPECT_EQ(streamOf(*r, 1).info().attributes.value("athlete").toString(), QStringLiteral("ben lee"));
    // Warnings: the skipped file, the athlete without a roster entry, the roster entry without a file.
    EXPECT_EQ(r->warnings.size(), 3) << qPrintable(r->warnings.join('\n'));
    EXPECT_TRUE(r->warnings.join('\n').contains("'carl' is in the roster but not in the folder"));

    const QString bad = test::writeFile(dir, "bad.csv", "file,athlete,mass_kg\nanna.csv,Anna,heavy\n");
    r = importFolder(folder, optionsFor("lps-position", "match"), bad);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("bad.csv:2:3 (column 'mass_kg'): 'heavy' is not a number"))
        << qPrintable(r.message());
    const QString nofile = test::writeFile(dir, "nofile.csv", "name,athlete\nanna.csv,Anna\n");
    r = importFolder(folder, optionsFor("lps-position", "match"), nofile);
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("nofile.csv:1: a roster needs a column 'file'")) << qPrintable(r.message());
    r = importFolder(folder, optionsFor("lps-position", "match/x"), roster);
    ASSERT_FALSE(r.ok());
}
