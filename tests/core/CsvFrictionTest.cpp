// CSV as people write it: pandas index columns, channel names in any case, columns nobody mapped,
// and the units of sports devices (km/h, mph, hPa, lux, bpm, %, mg, ...). Unknown units list the
// accepted ones.
#include "TestFiles.h"
#include "core/io/Importer.h"
#include "core/util/Units.h"

#include <QTemporaryDir>
#include <gtest/gtest.h>
#include <cmath>
#include <numbers>

using namespace athlos;

namespace {

class CsvFriction : public ::testing::Test {
protected:
    Expected<ImportResult> import(const QByteArray& content, const QString& kind = {}) {
        ImportOptions o = options;
        o.format = QStringLiteral("csv");
        o.kind = kind;
        o.target = QStringLiteral("rec");
        return importFile(test::writeFile(dir_, QStringLiteral("f.csv"), content), o);
    }
    static const Stream& stream(const ImportResult& r) { return std::get<Stream>(r.items.at(0).item); }
    static QStringList names(const ImportResult& r) {
        QStringList n;
        for (const Column& c : stream(r).info().columns) n << c.name + QLatin1Char('[') + c.unit + QLatin1Char(']');
        return n;
    }
    static double at(const ImportResult& r, size_t row, int column) { return (*stream(r).data())->at(row, column); }
    ImportOptions options;

private:
    QTemporaryDir dir_;
};

}  // namespace

TEST_F(CsvFriction, PandasIndexColumnsAreIgnored) {
    for (const QByteArray& header :
         {QByteArray(",t,acc_x"), QByteArray("Unnamed: 0,t,acc_x"), QByteArray("t,acc_x,")}) {
        const QByteArray rows = header.endsWith(',') ? "0,1,\n0.01,2,\n" : "0,0,1\n1,0.01,2\n";
        const auto r = import(header + '\n' + rows);  // the kind is inferred without the index
        ASSERT_TRUE(r.ok()) << header.constData() << ": " << qPrintable(r.message());
        EXPECT_EQ(stream(*r).kind(), QStringLiteral("imu"));
        EXPECT_EQ(names(*r), QStringList{"acc_x[m/s^2]"});
        EXPECT_EQ(at(*r, 1, 0), 2.0);
    }
}

TEST_F(CsvFriction, KnownChannelNamesInAnyCase) {
    auto r = import("t,Lat,LONGITUDE,Altitude,HDOP\n0,48.1,11.5,500,0.9\n1,48.2,11.6,501,1.0\n");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(stream(*r).kind(), QStringLiteral("gnss"));
    EXPECT_EQ(names(*r), (QStringList{"lat[deg]", "lon[deg]", "alt[m]", "hdop[1]"}));
    r = import("t,ACC_X,Acc_Y [g],GYR_Z [deg/s]\n0,1,1,180\n");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(names(*r), (QStringList{"acc_x[m/s^2]", "acc_y[m/s^2]", "gyr_z[rad/s]"}));
    EXPECT_NEAR(at(*r, 0, 1), 9.80665, 1e-12);
    // Two spellings of one channel are a duplicate, named with the column.
    r = import("t,acc_x,ACC_X\n0,1,2\n");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("f.csv:1:3 (column 'ACC_X'): duplicate column name (also column 2)"))
        << qPrintable(r.message());
    // Without a 't' column, "Time" is taken as the time column, and the import says so.
    r = import("Time,acc_x\n0,1\n", "imu");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_TRUE(r->warnings.join('\n').contains("column 'Time' taken as the time column, in seconds"))
        << qPrintable(r->warnings.join('\n'));
}

TEST_F(CsvFriction, DropUnmappedLeavesOnlyWhatTheKindKnows) {
    const QByteArray text = "Date;t;AccX;acc_y;Load;Comment\n2024-05-01;0;1;2;3;fine\n2024-05-01;0.01;4;5;6;ok\n";
    auto r = import(text, "imu");
    ASSERT_FALSE(r.ok());  // the text columns stop a plain import
    EXPECT_TRUE(r.message().contains("f.csv:2:1 (column 'Date')")) << qPrintable(r.message());
    options.dropUnmapped = true;
    options.columns.push_back({QStringLiteral("AccX"), QStringLiteral("acc_x"), QStringLiteral("g"), false});
    r = import(text, "imu");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(names(*r), (QStringList{"acc_x[m/s^2]", "acc_y[m/s^2]"}));
    EXPECT_NEAR(at(*r, 1, 0), 4 * 9.80665, 1e-12);
    // Without a kind nothing is known: only the mapped columns stay.
    r = import(text, "custom");
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(names(*r), (QStringList{"acc_x[m/s^2]"}));
}

TEST_F(CsvFriction, UnitsOfSportsDevices) {
    struct Case {
        const char* unit;
        const char* si;
        double value;     // in unit
        double expected;  // in si
    };
    const Case cases[] = {
        {"km/h", "m/s", 36.0, 10.0},
        {"mph", "m/s", 10.0, 4.4704},
        {"kmh", "m/s", 3.6, 1.0},
        {"hPa", "Pa", 1013.25, 101325.0},
        {"Pa", "Pa", 5.0, 5.0},
        {"mbar", "Pa", 1.0, 100.0},
        {"lux", "lx", 300.0, 300.0},
        {"bpm", "Hz", 120.0, 2.0},
        {"%", "1", 55.0, 0.55},
        {"g", "m/s^2", 2.0, 19.6133},
        {"mg", "m/s^2", 1000.0, 9.80665},
        {"deg", "rad", 180.0, std::numbers::pi},
        {"\u00B0", "rad", 90.0, std::numbers::pi / 2},
        {"d", "s", 1.0, 86400.0},
        {"h", "s", 1.0, 3600.0},
        {"min", "s", 2.0, 120.0},
        {"ms", "s", 5.0, 0.005},
        {"\u00B5s", "s", 5.0, 5e-6},
        {"us", "s", 5.0, 5e-6},
        {"ns", "s", 5.0, 5e-9},
    };
    for (const Case& c : cases) {
        options.columns = {{QStringLiteral("v"), QStringLiteral("value"), QString::fromUtf8(c.unit), false}};
        const auto r = import("t,v\n0," + QByteArray::number(c.value, 'g', 17) + "\n", "custom");
        ASSERT_TRUE(r.ok()) << c.unit << ": " << qPrintable(r.message());
        EXPECT_EQ(stream(*r).info().columns[0].unit, QLatin1String(c.si)) << c.unit;
        EXPECT_NEAR(at(*r, 0, 0), c.expected, 1e-9 * std::max(1.0, std::abs(c.expected))) << c.unit;
    }
}

TEST_F(CsvFriction, UnknownUnitsListTheAcceptedOnes) {
    auto r = import("t,acc_x [furlong/fortnight]\n0,1\n", "imu");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains(
        "f.csv:1:2 (column 'acc_x'): unknown unit 'furlong/fortnight' (accepted for m/s^2: g, m/s^2, mg)"))
        << qPrintable(r.message());
    options.columns = {{QStringLiteral("v"), QStringLiteral("value"), QStringLiteral("parsec"), false}};
    r = import("t,v\n0,1\n", "custom");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("column mapping for 'v': unknown unit 'parsec' (accepted: "));
    EXPECT_TRUE(r.message().contains("bpm")) << qPrintable(r.message());
    EXPECT_TRUE(knownUnitNames(QStringLiteral("Pa")).contains(QStringLiteral("hPa")));
}
