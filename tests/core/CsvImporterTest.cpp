// CSV import: the interchange convention, units, delimiters, time repair and every error path.
#include "TestFiles.h"
#include "core/io/Importer.h"
#include "core/util/Version.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

using namespace athlos;

namespace {

class CsvImport : public ::testing::Test {
protected:
    QString write(const QString& name, const QByteArray& content) { return test::writeFile(dir_, name, content); }
    static Expected<ImportResult> import(const QString& file, const QString& kind, const QString& repair = "reject",
                                         const QString& target = "rec", const Progress& progress = {}) {
        ImportOptions options;
        options.format = "csv";
        options.kind = kind;
        options.timeRepair = repair;
        options.target = target;
        return importFile(file, options, progress);
    }
    static const Stream& stream(const ImportResult& r, size_t i = 0) { return std::get<Stream>(r.items.at(i).item); }
    static const StreamData& data(const Stream& s) { return **s.data(); }
    // "t,acc_x,acc_y,acc_z" + n rows: t = i/100, acc = (i, -i, 9.81).
    static QByteArray imuLines(int n) {
        QByteArray text = "t,acc_x,acc_y,acc_z\n";
        for (int i = 0; i < n; ++i)
            text +=
                QByteArray::number(i / 100.0) + ',' + QByteArray::number(i) + ',' + QByteArray::number(-i) + ",9.81\n";
        return text;
    }
    static void expectError(const Expected<ImportResult>& r, const QString& part) {
        ASSERT_FALSE(r.ok()) << "should fail with: " << part.toStdString();
        EXPECT_TRUE(r.message().contains(part))
            << "'" << r.message().toStdString() << "' lacks '" << part.toStdString() << "'";
    }

    QTemporaryDir dir_;
};

}  // namespace

TEST_F(CsvImport, ImportsAnImuStreamWithProvenance) {
    const QString file = write("imu.csv", imuLines(5));
    const auto r = import(file, "imu");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    ASSERT_EQ(r->items.size(), 1u);
    EXPECT_EQ(r->items[0].path, "rec/imu");
    const Stream& s = stream(*r);
    EXPECT_EQ(s.info().kind, "imu");
    EXPECT_EQ(s.info().frame, "sensor");
    ASSERT_EQ(s.info().columns.size(), 3u);
    EXPECT_EQ(s.info().columns[0], (Column{"acc_x", "m/s^2"}));
    const StreamData& d = data(s);
    ASSERT_EQ(d.rows(), 5u);
    EXPECT_EQ(d.t[3], 0.03);
    EXPECT_EQ(d.at(4, 1), -4.0);
    EXPECT_EQ(d.at(2, 2), 9.81);
    const Provenance& p = s.info().provenance;
    EXPECT_EQ(p.processorId, "import:csv");
    EXPECT_EQ(p.sourceFile, QFileInfo(file).absoluteFilePath());
    EXPECT_EQ(p.appVersion, appVersion());
    EXPECT_TRUE(p.time.isValid());
    EXPECT_EQ(p.time.timeSpec(), Qt::UTC);
    EXPECT_TRUE(r->warnings.isEmpty());
}

TEST_F(CsvImport, NamesStreamsAfterKindOrTarget) {
    const QString file = write("imu.csv", imuLines(3));
    EXPECT_EQ(import(file, "imu", "reject", "run1/custom")->items[0].path, "run1/custom");
    const QString lps = write("lps.csv", "t,x,y,z\n0,1,2,3\n0.1,1,2,3\n");
    const auto r = import(lps, "lps-position");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_EQ(r->items[0].path, "rec/lps");
    EXPECT_EQ(stream(*r).info().frame, "lps");
    expectError(import(file, "imu", "reject", "a/b/c"), "a/b/c");

    ImportOptions options;  // --frame overrides the kind's default
    options.format = "csv";
    options.kind = "imu";
    options.target = "rec";
    options.frame = "body";
    EXPECT_EQ(std::get<Stream>(importFile(file, options)->items[0].item).info().frame, "body");
}

TEST_F(CsvImport, InfersTheKindFromTheColumns) {
    EXPECT_EQ(import(write("a.csv", imuLines(2)), "")->items[0].path, "rec/imu");
    EXPECT_EQ(import(write("b.csv", "t,x,y\n0,1,2\n"), "")->items[0].path, "rec/lps");
    EXPECT_EQ(import(write("c.csv", "t,qw,qx,qy,qz\n0,1,0,0,0\n"), "")->items[0].path, "rec/orientation");
    EXPECT_EQ(import(write("d.csv", "id,x,y,z\nA,1,2,3\n"), "")->items[0].path, "rec/beacons");
    expectError(import(write("e.csv", "t,foo\n0,1\n"), ""), "kind");
}

TEST_F(CsvImport, NonNumericCellNamesFileLineAndColumn) {
    QList<QByteArray> lines = imuLines(100).split('\n');
    lines[57] = "0.56,56,abc,9.81";  // line 58 (the header is line 1), column 3 = acc_y
    const auto r = import(write("imu.csv", lines.join('\n')), "imu");
    expectError(r, "imu.csv:58:3 (column 'acc_y'): 'abc' is not a number");
}

TEST_F(CsvImport, LineNumbersCountCommentsAndBlankLines) {
    const auto r = import(write("imu.csv", "# made by hand\nt,acc_x\n\n0,1\n# note\n0.1,x\n"), "imu");
    expectError(r, "imu.csv:6:2 (column 'acc_x')");
}

TEST_F(CsvImport, WrongFieldCount) {
    expectError(import(write("few.csv", "t,acc_x,acc_y\n0,1,2\n0.1,1\n"), "imu"), "few.csv:3:3");
    expectError(import(write("few.csv", "t,acc_x,acc_y\n0,1,2\n0.1,1\n"), "imu"),
                "line has 2 fields, the header has 3");
    expectError(import(write("many.csv", "t,acc_x,acc_y\n0,1,2\n0.1,1,2,3\n"), "imu"), "many.csv:3:4");
    expectError(import(write("many.csv", "t,acc_x,acc_y\n0,1,2\n0.1,1,2,3\n"), "imu"), "line has 4 fields");
}

TEST_F(CsvImport, HeaderErrors) {
    expectError(import(write("not.csv", "stamp,acc_x\n0,1\n"), "imu"), "not.csv:1: no 't' column");
    expectError(import(write("dup.csv", "t,acc_x,acc_x\n0,1,2\n"), "imu"),
                "dup.csv:1:3 (column 'acc_x'): duplicate column name");
    expectError(import(write("empty.csv", ""), "imu"), "empty.csv: empty file");
    expectError(import(write("blank.csv", "\n\n# only a comment\n"), "imu"), "blank.csv: empty file");
    expectError(import(write("head.csv", "t,acc_x\n"), "imu"), "head.csv: no data rows");
    expectError(import(write("q.csv", "t,qw,qx\n0,1,0\n"), "orientation"), "needs a column 'qy'");
    expectError(import(write("g.csv", "t,alt\n0,1\n"), "gnss"), "lat, lon");
}

TEST_F(CsvImport, BadUnitNamesColumnAndFile) {
    const auto r = import(write("units.csv", "t,acc_x,gyr_x [m]\n0,1,2\n"), "imu");
    expectError(r, "units.csv:1:3 (column 'gyr_x')");
    expectError(r, "rad/s");
    expectError(import(write("t.csv", "t [m],acc_x\n0,1\n"), "imu"), "t.csv:1:1 (column 't')");
    expectError(import(write("u.csv", "t,acc_x [bogus]\n0,1\n"), "imu"), "bogus");
}

TEST_F(CsvImport, ConvertsUnitsToSi) {
    const auto r = import(write("u.csv",
                                "t [ms],acc_x (g),gyr_x [deg/s],mag_x [G],temp_board [degF]\n"
                                "0,1,180,0.5,70\n10,-2,-90,1,71\n"),
                          "imu");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    const Stream& s = stream(*r);
    const StreamData& d = data(s);
    EXPECT_EQ(d.t[1], 0.01);
    EXPECT_DOUBLE_EQ(d.at(0, 0), 9.80665);
    EXPECT_DOUBLE_EQ(d.at(1, 0), -2 * 9.80665);
    EXPECT_DOUBLE_EQ(d.at(0, 1), std::numbers::pi);
    EXPECT_DOUBLE_EQ(d.at(1, 1), -std::numbers::pi / 2);
    EXPECT_DOUBLE_EQ(d.at(0, 2), 50.0);
    EXPECT_EQ(d.at(1, 3), 71.0);  // a column the kind does not know keeps value and unit
    EXPECT_EQ(s.info().columns[1], (Column{"gyr_x", "rad/s"}));
    EXPECT_EQ(s.info().columns[2], (Column{"mag_x", "uT"}));
    EXPECT_EQ(s.info().columns[3], (Column{"temp_board", "degF"}));
    EXPECT_EQ(s.info().attributes["source_units"].toObject()["gyr_x"].toString(), "deg/s");
}

TEST_F(CsvImport, UnknownKindKeepsGivenUnits) {
    const auto r = import(write("k.csv", "t,hip [deg],knee\n0,10,20\n1,11,21\n"), "my-angles");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_EQ(r->items[0].path, "rec/my-angles");
    EXPECT_EQ(stream(*r).info().columns[0], (Column{"hip", "deg"}));
    EXPECT_EQ(stream(*r).info().columns[1], (Column{"knee", ""}));
    EXPECT_EQ(data(stream(*r)).at(1, 0), 11.0);
}

TEST_F(CsvImport, DetectsDelimiterAndToleratesQuotesCrlfCommentsAndBom) {
    const QByteArray rows[] = {
        "t,acc_x,acc_y\n0,1.5,2\n0.5,3,-4\n",
        "t;acc_x;acc_y\n0;1.5;2\n0.5;3;-4\n",
        "t\tacc_x\tacc_y\n0\t1.5\t2\n0.5\t3\t-4\n",
        "\xEF\xBB\xBF\"t\",\"acc_x\", \"acc_y\"\r\n# comment\r\n0,1.5,2\r\n  0.5 , \"3\" ,+4e0\r\n\r\n\r\n",
    };
    int i = 0;
    for (const QByteArray& text : rows) {
        const auto r = import(write(QStringLiteral("d%1.csv").arg(i++), text), "imu");
        ASSERT_TRUE(r.ok()) << i << ": " << r.message().toStdString();
        const StreamData& d = data(stream(*r));
        ASSERT_EQ(d.rows(), 2u) << i;
        EXPECT_EQ(d.t[1], 0.5) << i;
        EXPECT_EQ(d.at(0, 0), 1.5) << i;
        EXPECT_EQ(std::abs(d.at(1, 1)), 4.0) << i;
    }
}

TEST_F(CsvImport, SemicolonFileWithDecimalCommasAndCentimetres) {
    const auto r = import(QStringLiteral(ATHLOS_TEST_DATA_DIR "/lps_semicolon.csv"), "lps-position");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    const StreamData& d = data(stream(*r));
    ASSERT_EQ(d.rows(), 5u);
    EXPECT_DOUBLE_EQ(d.at(1, 0), 1.105);
    EXPECT_DOUBLE_EQ(d.at(1, 1), -0.5225);
    EXPECT_DOUBLE_EQ(d.at(4, 2), 1.2);
    EXPECT_EQ(stream(*r).info().columns[0].unit, "m");
}

TEST_F(CsvImport, SharedImuFileWithUnits) {
    const auto r = import(QStringLiteral(ATHLOS_TEST_DATA_DIR "/imu_small.csv"), "imu");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    const StreamData& d = data(stream(*r));
    ASSERT_EQ(d.rows(), 20u);
    EXPECT_DOUBLE_EQ(d.at(0, 2), 9.80665);                          // acc_z 1 g
    EXPECT_DOUBLE_EQ(d.at(0, 5), 90.0 * std::numbers::pi / 180.0);  // gyr_z 90 deg/s
}

TEST_F(CsvImport, EmptyCellsAndNonFiniteValues) {
    const auto r = import(write("nan.csv", "t,acc_x,acc_y\n0,,1\n0.1,nan,2\n"), "imu");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_TRUE(std::isnan(data(stream(*r)).at(0, 0)));
    EXPECT_TRUE(std::isnan(data(stream(*r)).at(1, 0)));
    expectError(import(write("t.csv", "t,acc_x\n0,1\n,2\n"), "imu"), "t.csv:3:1 (column 't'): empty time");
    expectError(import(write("tn.csv", "t,acc_x\n0,1\nnan,2\n"), "imu"),
                "tn.csv:3:1 (column 't'): 'nan' is not a finite number");
    expectError(import(write("inf.csv", "t,acc_x\n0,1\n1,-inf\n"), "imu"),
                "inf.csv:3:2 (column 'acc_x'): '-inf' is not a finite number");
}

TEST_F(CsvImport, TimeRepairReject) {
    const QByteArray text = "t,acc_x\n0,1\n0.2,2\n0.1,3\n0.3,4\n";
    const auto r = import(write("back.csv", text), "imu");
    expectError(r, "back.csv:4:1 (column 't'): time 0.1 is not after 0.2 on line 3");
    expectError(import(write("eq.csv", "t,acc_x\n0,1\n0,2\n"), "imu"), "eq.csv:3:1");
    expectError(import(write("x.csv", text), "imu", "fix"), "unknown time repair 'fix'");
}

TEST_F(CsvImport, TimeRepairSortDropsExactDuplicates) {
    const auto r = import(write("s.csv", "t,acc_x\n0,1\n0.2,2\n0.1,3\n0.2,2\n0.3,4\n"), "imu", "sort");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    const StreamData& d = data(stream(*r));
    EXPECT_EQ(d.t, (std::vector<double>{0, 0.1, 0.2, 0.3}));
    EXPECT_EQ(d.values, (std::vector<double>{1, 3, 2, 4}));
    ASSERT_EQ(r->warnings.size(), 2);
    EXPECT_TRUE(r->warnings.join(' ').contains("1 exact duplicate")) << r->warnings.join('|').toStdString();
    expectError(import(write("c.csv", "t,acc_x\n0,1\n0.2,2\n0.2,5\n"), "imu", "sort"),
                "lines 3 and 4 have the same time 0.2");
}

TEST_F(CsvImport, TimeRepairDropKeepsIncreasingSamples) {
    const auto r = import(write("d.csv", "t,acc_x\n0,1\n0.2,2\n0.1,3\n0.2,5\n0.3,4\n"), "imu", "drop");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    const StreamData& d = data(stream(*r));
    EXPECT_EQ(d.t, (std::vector<double>{0, 0.2, 0.3}));
    EXPECT_EQ(d.values, (std::vector<double>{1, 2, 4}));
    ASSERT_EQ(r->warnings.size(), 1);
    EXPECT_TRUE(r->warnings[0].contains("dropped 2 samples")) << r->warnings[0].toStdString();
    EXPECT_TRUE(r->warnings[0].contains("line 4"));
}

TEST_F(CsvImport, WarnsAboutGyroscopeValuesThatLookLikeDegrees) {
    const auto r = import(write("g.csv", "t,gyr_x,gyr_y\n0,0.1,120\n0.1,0.2,-200\n"), "imu");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    ASSERT_EQ(r->warnings.size(), 1);
    EXPECT_TRUE(r->warnings[0].contains("gyr_y")) << r->warnings[0].toStdString();
    EXPECT_TRUE(r->warnings[0].contains("deg/s"));
    EXPECT_TRUE(import(write("ok.csv", "t,gyr_x [deg/s]\n0,120\n"), "imu")->warnings.isEmpty());
}

TEST_F(CsvImport, TdoaLongFormatBecomesWideStream) {
    const auto r = import(QStringLiteral(ATHLOS_TEST_DATA_DIR "/tdoa_small.csv"), "lps-tdoa");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_EQ(r->items[0].path, "rec/tdoa");
    const Stream& s = stream(*r);
    EXPECT_EQ(s.info().kind, "lps-tdoa");
    EXPECT_EQ(s.info().columnNames(), (QStringList{"dt_A1", "dt_A2", "dt_A3"}));
    EXPECT_EQ(s.info().attributes["beacon_ids"].toArray(), (QJsonArray{"A1", "A2", "A3"}));
    const StreamData& d = data(s);
    EXPECT_EQ(d.t, (std::vector<double>{0.0, 0.1, 0.2}));
    EXPECT_EQ(d.at(0, 1), -2.25e-9);
    EXPECT_TRUE(std::isnan(d.at(1, 0)));
    EXPECT_EQ(d.at(2, 2), 2.75e-9);

    expectError(import(write("tb.csv", "t,beacon,dt\n0,1,1e-9\n0,1,2e-9\n"), "lps-tdoa"), "tb.csv:3");
    expectError(import(write("te.csv", "t,beacon,dt\n0,1,1e-9\n0.1,,2e-9\n"), "lps-tdoa"),
                "te.csv:3:2 (column 'beacon'): empty id");
    expectError(import(write("tx.csv", "t,beacon,dt,rssi\n0,1,1e-9,3\n"), "lps-tdoa"), "t, beacon, dt");
    const auto ns = import(write("ns.csv", "t,beacon,dt [ns]\n0.2,7,1.5\n0.1,7,2\n"), "lps-tdoa", "sort");
    ASSERT_TRUE(ns.ok()) << ns.message().toStdString();
    EXPECT_EQ(stream(*ns).info().columnNames(), (QStringList{"dt_7"}));
    EXPECT_DOUBLE_EQ(data(stream(*ns)).at(0, 0), 2e-9);
}

TEST_F(CsvImport, BeaconsBecomeATable) {
    const auto r = import(QStringLiteral(ATHLOS_TEST_DATA_DIR "/beacons.csv"), "beacons");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_EQ(r->items[0].path, "rec/beacons");
    const Table& t = std::get<Table>(r->items[0].item);
    EXPECT_EQ(t.kind, "beacons");
    EXPECT_EQ(t.rows(), 4);
    ASSERT_NE(t.column("id"), nullptr);
    EXPECT_TRUE(t.column("id")->isText);
    EXPECT_EQ(t.column("id")->texts[2], "A3");
    EXPECT_EQ(t.column("x")->numbers[0], -20.5);
    EXPECT_EQ(t.column("z")->unit, "m");
    EXPECT_EQ(t.provenance.processorId, "import:csv");

    const auto mm = import(write("b.csv", "id,x [mm],y [mm]\n\"1\",1500,-250\n"), "beacons");
    ASSERT_TRUE(mm.ok()) << mm.message().toStdString();
    EXPECT_EQ(std::get<Table>(mm->items[0].item).column("x")->numbers[0], 1.5);
    expectError(import(write("bb.csv", "id,x,y\nA,1,oops\n"), "beacons"),
                "bb.csv:2:3 (column 'y'): 'oops' is not a number");
    expectError(import(write("bc.csv", "id,x,y\nA,1\n"), "beacons"), "bc.csv:2:3");
}

TEST_F(CsvImport, GnssFrames) {
    const auto wgs = import(write("g.csv", "t,lat,lon,alt\n0,52.5,13.4,40\n"), "gnss");
    ASSERT_TRUE(wgs.ok()) << wgs.message().toStdString();
    EXPECT_EQ(stream(*wgs).info().frame, "WGS84");
    const auto enu = import(write("l.csv", "t,x,y,z,vx\n0,1,2,3,4\n"), "gnss");
    ASSERT_TRUE(enu.ok()) << enu.message().toStdString();
    EXPECT_EQ(stream(*enu).info().frame, "ENU");
}

TEST_F(CsvImport, ReportsProgressAndHonoursCancellation) {
    QByteArray big = "t,acc_x,acc_y,acc_z\n";
    big.reserve(12 << 20);
    for (int i = 0; big.size() < (10 << 20); ++i)
        big += QByteArray::number(i * 0.001, 'f', 3) + ",0.123456789,-9.876543210,9.806650000\n";
    const QString file = write("big.csv", big);

    std::vector<double> fractions;
    const auto r =
        import(file, "imu", "reject", "rec", Progress([&](double f, const QString&) { fractions.push_back(f); }));
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    ASSERT_GE(fractions.size(), 3u);  // start, at least one block of a few MB, end
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_EQ(fractions.back(), 1.0);

    CancelToken token;
    token.cancel();
    const auto cancelled = import(file, "imu", "reject", "rec", Progress([](double, const QString&) {}, token));
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.message(), "cancelled");
}

TEST_F(CsvImport, FormatDetectionAndMissingFile) {
    ImportOptions options;
    options.kind = "imu";
    options.target = "rec";
    const auto r = importFile(write("auto.csv", imuLines(2)), options);
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_EQ(std::get<Stream>(r->items[0].item).info().provenance.processorId, "import:csv");
    expectError(importFile(dir_.filePath("nope.csv"), options), "nope.csv: no such file");
    expectError(importFile(write("x.bin", QByteArray("\0\1\2", 3)), options), "cannot tell the file format");
    options.format = "xls";
    expectError(importFile(write("y.csv", imuLines(2)), options), "unknown import format 'xls'");
}

TEST_F(CsvImport, ApplyImportIsAllOrNothing) {
    auto project = Project::create(dir_.filePath("p.athlos"));
    ImportResult first = *import(write("imu.csv", imuLines(3)), "imu");
    ASSERT_TRUE(applyImport(*project, first, false).ok());
    ASSERT_NE(project->stream("rec/imu"), nullptr);

    // Two items, the second of which exists: nothing is inserted.
    ImportResult both = *import(write("lps.csv", "t,x,y\n0,1,2\n"), "lps-position");
    both.items.push_back(first.items[0]);
    const Status refused = applyImport(*project, both, false);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(refused.message().contains("rec/imu")) << refused.message().toStdString();
    EXPECT_EQ(project->stream("rec/lps"), nullptr);

    ImportResult again = *import(write("imu2.csv", imuLines(7)), "imu");
    ASSERT_TRUE(applyImport(*project, again, true).ok());
    EXPECT_EQ(project->stream("rec/imu")->info().rows, 7);

    ImportResult twice = *import(write("lps.csv", "t,x,y\n0,1,2\n"), "lps-position");
    twice.items.push_back(twice.items[0]);
    EXPECT_FALSE(applyImport(*project, twice, true).ok());
    EXPECT_EQ(project->stream("rec/lps"), nullptr);
}
