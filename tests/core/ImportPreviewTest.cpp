// Import preview: detected format, kind, channels and units for each known format; the mapping it
// suggests imports a foreign export correctly; the dry run reports errors with file:line:column.
#include "TestFiles.h"
#include "core/io/ImportPreview.h"

#include "tests/SharedData.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

using namespace athlos;

namespace {

const QString kImuSmall = QStringLiteral(ATHLOS_TEST_DATA_DIR "/imu_small.csv");
const QString kGaitmap = QStringLiteral(ATHLOS_SHARED_DATA_DIR "/gaitmap/imu_sample_ic_stride.csv");
const QString kBroad = QStringLiteral(ATHLOS_SHARED_DATA_DIR "/broad/02_undisturbed_slow_rotation_B.hdf5");

QByteArray sentence(const QByteArray& body) {
    int sum = 0;
    for (char c : body) sum ^= static_cast<unsigned char>(c);
    return "$" + body + "*" + QByteArray::number(sum, 16).rightJustified(2, '0').toUpper() + "\r\n";
}

class Preview : public ::testing::Test {
protected:
    QString write(const QString& name, const QByteArray& content) { return test::writeFile(dir_, name, content); }
    static const PreviewColumn* column(const ImportPreview& p, const QString& source) {
        for (const PreviewColumn& c : p.columns)
            if (c.source == source) return &c;
        return nullptr;
    }
    QTemporaryDir dir_;
};

TEST(DetectChannel, CommonExportNames) {
    EXPECT_EQ(detectChannel("acc_x"), QStringLiteral("acc_x"));
    EXPECT_EQ(detectChannel("AccX"), QStringLiteral("acc_x"));
    EXPECT_EQ(detectChannel("Accelerometer Y"), QStringLiteral("acc_y"));
    EXPECT_EQ(detectChannel("gyro-z"), QStringLiteral("gyr_z"));
    EXPECT_EQ(detectChannel("gx"), QStringLiteral("gyr_x"));
    EXPECT_EQ(detectChannel("Mag_Z"), QStringLiteral("mag_z"));
    EXPECT_EQ(detectChannel("Timestamp"), QStringLiteral("t"));
    EXPECT_EQ(detectChannel("time_ms"), QStringLiteral("t"));
    EXPECT_EQ(detectChannel("Latitude"), QStringLiteral("lat"));
    EXPECT_EQ(detectChannel("lng"), QStringLiteral("lon"));
    EXPECT_EQ(detectChannel("pos_x"), QStringLiteral("pos_x"));  // reference kind's own name
    EXPECT_EQ(detectChannel("heart rate"), QString());
    EXPECT_EQ(detectChannel("box"), QString());  // ends in x, but "bo" is no sensor
}

TEST(StoredUnit, KindRuleOrSi) {
    EXPECT_EQ(*storedUnitFor("imu", "gyr_x", "deg/s"), QStringLiteral("rad/s"));
    EXPECT_EQ(*storedUnitFor("imu", "acc_x", ""), QStringLiteral("m/s^2"));
    EXPECT_EQ(*storedUnitFor("imu", "pitch", "deg"), QStringLiteral("rad"));  // no rule: SI
    EXPECT_EQ(*storedUnitFor("imu", "t", "ms", true), QStringLiteral("s"));
    EXPECT_EQ(*storedUnitFor("imu", "load", ""), QString());
    EXPECT_TRUE(storedUnitFor("imu", "acc_x", "deg/s").message().contains("cannot be converted"));
    EXPECT_TRUE(storedUnitFor("imu", "load", "kN").message().contains("unknown unit 'kN'"));
}

TEST_F(Preview, CsvWithHeaderUnits) {
    const auto p = previewFile(kImuSmall, "auto", 3);
    ASSERT_TRUE(p.ok()) << qPrintable(p.message());
    EXPECT_EQ(p->format, QStringLiteral("csv"));
    EXPECT_EQ(p->kind, QStringLiteral("imu"));
    EXPECT_TRUE(p->mappable);
    EXPECT_EQ(p->headerLine, 2);  // a comment line comes first
    ASSERT_EQ(p->rows.size(), 3u);
    EXPECT_EQ(p->rows[0].front(), QStringLiteral("0.00"));
    const PreviewColumn* acc = column(*p, "acc_x");
    ASSERT_TRUE(acc);
    EXPECT_EQ(acc->header, QStringLiteral("acc_x (g)"));
    EXPECT_EQ(acc->unit, QStringLiteral("g"));
    EXPECT_EQ(acc->storedUnit, QStringLiteral("m/s^2"));
    const PreviewColumn* gyr = column(*p, "gyr_z");
    ASSERT_TRUE(gyr);
    EXPECT_EQ(gyr->unit, QStringLiteral("deg/s"));
    EXPECT_EQ(gyr->storedUnit, QStringLiteral("rad/s"));
    EXPECT_TRUE(column(*p, "t")->time);
    // Nothing to map: the file follows the interchange convention.
    const ImportOptions o = suggestedOptions(*p);
    EXPECT_TRUE(o.columns.empty());
    EXPECT_TRUE(o.timeColumn.isEmpty());
}

TEST_F(Preview, ForeignExportIsMappedAndImportsInSi) {
    const QString file = write("watch.csv",
                               "Date;Timestamp [ms];AccX [g];Gyro Y [deg/s];Heart Rate\n"
                               "2024-05-01;1000;0.5;180;120\n"
                               "2024-05-01;1010;1;-90;121\n");
    const auto p = previewFile(file);
    ASSERT_TRUE(p.ok()) << qPrintable(p.message());
    EXPECT_EQ(p->kind, QStringLiteral("imu"));
    EXPECT_EQ(column(*p, "Timestamp")->channel, QStringLiteral("t"));
    EXPECT_EQ(column(*p, "Timestamp")->unit, QStringLiteral("ms"));
    EXPECT_EQ(column(*p, "AccX")->channel, QStringLiteral("acc_x"));
    EXPECT_EQ(column(*p, "Gyro Y")->channel, QStringLiteral("gyr_y"));
    EXPECT_EQ(column(*p, "Heart Rate")->channel, QStringLiteral("Heart Rate"));  // kept as it is
    const ImportOptions o = suggestedOptions(*p);
    EXPECT_EQ(o.timeColumn, QStringLiteral("Timestamp"));
    EXPECT_EQ(o.timeUnit, QStringLiteral("ms"));

    ImportOptions options = o;
    options.target = "rec";
    const auto r = importFile(file, options);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Stream& s = std::get<Stream>(r->items.at(0).item);
    EXPECT_EQ(s.info().columnNames(), (QStringList{"acc_x", "gyr_y", "Heart Rate"}));  // Date (text) skipped
    const StreamData& d = **s.data();
    EXPECT_DOUBLE_EQ(d.t[0], 1.0);
    EXPECT_DOUBLE_EQ(d.t[1], 1.01);
    EXPECT_DOUBLE_EQ(d.at(0, 0), 0.5 * 9.80665);
    EXPECT_NEAR(d.at(0, 1), std::numbers::pi, 1e-15);
    EXPECT_DOUBLE_EQ(d.at(1, 2), 121.0);
}

TEST_F(Preview, TimeUnitFromColumnName) {
    const QString file = write("t.csv", "time_ms,ax,ay\n0,1,2\n5,1,2\n");
    const auto p = previewFile(file);
    ASSERT_TRUE(p.ok()) << qPrintable(p.message());
    ImportOptions o = suggestedOptions(*p);
    EXPECT_EQ(o.timeUnit, QStringLiteral("ms"));
    o.target = "rec";
    const auto r = importFile(file, o);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_DOUBLE_EQ((**std::get<Stream>(r->items[0].item).data()).t[1], 0.005);
}

TEST_F(Preview, Gaitmap) {
    ATHLOS_SKIP_WITHOUT_SHARED(kGaitmap);
    const auto p = previewFile(kGaitmap, "auto", 5);
    ASSERT_TRUE(p.ok()) << qPrintable(p.message());
    EXPECT_EQ(p->format, QStringLiteral("gaitmap"));
    EXPECT_EQ(p->kind, QStringLiteral("imu"));
    EXPECT_FALSE(p->mappable);
    EXPECT_EQ(p->items, (QStringList{"left-foot", "right-foot"}));
    const PreviewColumn* gyr = column(*p, "left-foot/gyr_x");
    ASSERT_TRUE(gyr);
    EXPECT_EQ(gyr->unit, QStringLiteral("deg/s"));  // gaitmap's convention, converted on import
    EXPECT_EQ(gyr->storedUnit, QStringLiteral("rad/s"));
    EXPECT_EQ(column(*p, "right-foot/acc_z")->unit, QStringLiteral("m/s^2"));
    ASSERT_EQ(p->rows.size(), 5u);
    EXPECT_EQ(p->rows[0].size(), qsizetype(p->columns.size()));
    EXPECT_EQ(p->rows[1][0].toDouble(), 1.0 / 102.4);  // sample index at 102.4 Hz
}

TEST_F(Preview, Broad) {
    ATHLOS_SKIP_WITHOUT_SHARED(kBroad);
    const auto p = previewFile(kBroad, "auto", 4);
    ASSERT_TRUE(p.ok()) << qPrintable(p.message());
    EXPECT_EQ(p->format, QStringLiteral("broad"));
    EXPECT_EQ(p->items, (QStringList{"imu", "reference"}));
    EXPECT_TRUE(column(*p, "imu/gyr_x"));
    EXPECT_EQ(column(*p, "reference/qw")->storedUnit, QStringLiteral("1"));
    EXPECT_EQ(p->rows.size(), 4u);
}

TEST_F(Preview, Nmea) {
    QByteArray text;
    text += sentence("GPGGA,123519.00,4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,");
    text += sentence("GPRMC,123519.00,A,4807.038,N,01131.000,E,10.0,90.0,230394,003.1,W");
    const auto p = previewFile(write("walk.nmea", text));
    ASSERT_TRUE(p.ok()) << qPrintable(p.message());
    EXPECT_EQ(p->format, QStringLiteral("nmea"));
    EXPECT_EQ(p->kind, QStringLiteral("gnss"));
    EXPECT_EQ(column(*p, "lat")->unit, QStringLiteral("deg"));
    ASSERT_EQ(p->rows.size(), 1u);
    EXPECT_NEAR(p->rows[0][1].toDouble(), 48 + 7.038 / 60, 1e-6);
}

TEST_F(Preview, UnknownFileFormatIsAnError) {
    const auto p = previewFile(write("x.bin", QByteArray("\0\1\2", 3)));
    ASSERT_FALSE(p.ok());
    EXPECT_TRUE(p.message().contains("cannot tell the file format")) << qPrintable(p.message());
}

TEST_F(Preview, CheckReportsErrorsWithoutImporting) {
    const QString good = write("good.csv", "t,acc_x,acc_y\n0,1,2\n0.01,1,2\n");
    ImportOptions o;
    o.target = "run";
    const ImportCheck ok = checkImport(good, o);
    EXPECT_TRUE(ok.errors.isEmpty()) << qPrintable(ok.errors.join('\n'));
    EXPECT_EQ(ok.items, QStringList{"run/imu"});
    EXPECT_EQ(ok.samples, 2);

    const QString bad = write("bad.csv", "t,acc_x,acc_y\n0,1,2\n0.01,1,2\n0.02,1,abc\n");
    const ImportCheck check = checkImport(bad, o);
    ASSERT_EQ(check.errors.size(), 1);
    EXPECT_TRUE(check.errors[0].endsWith("bad.csv:4:3 (column 'acc_y'): 'abc' is not a number"))
        << qPrintable(check.errors[0]);
    EXPECT_TRUE(check.items.isEmpty());
    EXPECT_FALSE(check.cancelled);
}

}  // namespace
