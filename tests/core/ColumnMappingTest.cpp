// CSV column mapping (ImportOptions::columns, timeColumn, timeUnit): renames, unit conversion to SI,
// skipped columns, and every bad mapping naming the option or column at fault.
#include "TestFiles.h"
#include "core/io/Importer.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

using namespace athlos;

namespace {

class ColumnMap : public ::testing::Test {
protected:
    QString write(const QString& name, const QByteArray& content) { return test::writeFile(dir_, name, content); }
    static ImportOptions csv(const QString& kind = {}) {
        ImportOptions o;
        o.format = "csv";
        o.kind = kind;
        o.target = "rec";
        return o;
    }
    static const Stream& stream(const ImportResult& r) { return std::get<Stream>(r.items.at(0).item); }
    static void expectError(const Expected<ImportResult>& r, const QString& part) {
        ASSERT_FALSE(r.ok()) << "should fail with: " << part.toStdString();
        EXPECT_TRUE(r.message().contains(part))
            << "'" << r.message().toStdString() << "' lacks '" << part.toStdString() << "'";
    }
    // A sensor export: time in ms, acc in g, gyro in deg/s, an angle in deg, a text date column.
    QString exportFile() {
        return write("export.csv",
                     "Time;AccX;Gyro Z;Angle;Date\n"
                     "0;1;90;180;2024-05-01\n"
                     "10;0.5;-45;90;2024-05-01\n"
                     "20;-2;0;-90;2024-05-01\n");
    }

    QTemporaryDir dir_;
};

TEST_F(ColumnMap, RenamesAndConvertsToSi) {
    ImportOptions o = csv("imu");
    o.timeColumn = "Time";
    o.timeUnit = "ms";
    o.columns = {{"AccX", "acc_x", "g", false},
                 {"Gyro Z", "gyr_z", "deg/s", false},
                 {"Angle", "pitch", "deg", false},
                 {"Date", {}, {}, true}};
    const auto r = importFile(exportFile(), o);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Stream& s = stream(*r);
    EXPECT_EQ(r->items[0].path, QStringLiteral("rec/imu"));
    ASSERT_EQ(s.info().columnNames(), (QStringList{"acc_x", "gyr_z", "pitch"}));
    EXPECT_EQ(s.info().columns[0].unit, QStringLiteral("m/s^2"));
    EXPECT_EQ(s.info().columns[1].unit, QStringLiteral("rad/s"));
    EXPECT_EQ(s.info().columns[2].unit, QStringLiteral("rad"));  // no imu rule: SI all the same
    const StreamData& d = **s.data();
    ASSERT_EQ(d.rows(), 3u);
    EXPECT_DOUBLE_EQ(d.t[1], 0.010);
    EXPECT_DOUBLE_EQ(d.t[2], 0.020);
    EXPECT_DOUBLE_EQ(d.at(0, 0), 9.80665);
    EXPECT_DOUBLE_EQ(d.at(2, 0), -2 * 9.80665);
    EXPECT_NEAR(d.at(0, 1), std::numbers::pi / 2, 1e-15);
    EXPECT_NEAR(d.at(1, 1), -std::numbers::pi / 4, 1e-15);
    EXPECT_NEAR(d.at(0, 2), std::numbers::pi, 1e-15);
    const QJsonObject units = s.info().attributes.value("source_units").toObject();
    EXPECT_EQ(units.value("acc_x").toString(), QStringLiteral("g"));
    EXPECT_EQ(units.value("gyr_z").toString(), QStringLiteral("deg/s"));
    // The mapping is part of the provenance, so the import can be repeated.
    const QJsonArray columns = s.info().provenance.parameters.value("columns").toArray();
    ASSERT_EQ(columns.size(), 4);
    EXPECT_EQ(columns[0].toObject().value("channel").toString(), QStringLiteral("acc_x"));
    EXPECT_EQ(s.info().provenance.parameters.value("time_column").toString(), QStringLiteral("Time"));
}

TEST_F(ColumnMap, KindIsInferredFromMappedNames) {
    ImportOptions o = csv();
    o.timeColumn = "Time";
    o.columns = {
        {"AccX", "acc_x", "g", false}, {"Gyro Z", "gyr_z", {}, false}, {"Angle", {}, {}, true}, {"Date", {}, {}, true}};
    const auto r = importFile(exportFile(), o);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(stream(*r).kind(), QStringLiteral("imu"));
    // Without a unit, gyr_z takes the kind's (rad/s): the 90 stays 90, and the importer warns.
    EXPECT_DOUBLE_EQ((**stream(*r).data()).at(0, 1), 90.0);
    EXPECT_EQ(stream(*r).info().columnNames(), (QStringList{"acc_x", "gyr_z"}));
}

TEST_F(ColumnMap, SkippedColumnsAreNotParsed) {
    // "Date" is text: without the skip it is an error naming its cell.
    ImportOptions o = csv("imu");
    o.timeColumn = "Time";
    o.columns = {{"AccX", "acc_x", {}, false}, {"Gyro Z", "gyr_z", {}, false}, {"Angle", {}, {}, true}};
    expectError(importFile(exportFile(), o), "export.csv:2:5 (column 'Date'): '2024-05-01' is not a number");
    o.columns.push_back({"Date", {}, {}, true});
    const auto r = importFile(exportFile(), o);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    EXPECT_EQ(stream(*r).info().columns.size(), 2u);
    EXPECT_EQ((**stream(*r).data()).columns, 2);
}

TEST_F(ColumnMap, CellErrorsNameTheFileColumn) {
    const QString file = write("bad.csv", "Time,Skip,AccY\n0,x,1\n1,x,2\n2,x,abc\n");
    ImportOptions o = csv("imu");
    o.timeColumn = "Time";
    o.columns = {{"Skip", {}, {}, true}, {"AccY", "acc_y", {}, false}};
    expectError(importFile(file, o), "bad.csv:4:3 (column 'AccY'): 'abc' is not a number");
}

TEST_F(ColumnMap, BadMappingsNameTheParameter) {
    const QString file = exportFile();
    ImportOptions o = csv("imu");
    o.timeColumn = "Time";
    o.columns = {{"AccX", "acc_x", "furlong", false}, {"Date", {}, {}, true}};
    expectError(importFile(file, o), "column mapping for 'AccX': unknown unit 'furlong'");

    o.columns = {{"AccX", "acc_x", {}, false}, {"Gyro Z", "acc_x", {}, false}, {"Date", {}, {}, true}};
    expectError(importFile(file, o), "export.csv:1:3 (column 'Gyro Z'): duplicate channel 'acc_x' (also column 2)");

    o.columns = {{"AccX", "acc_x", "deg/s", false}, {"Date", {}, {}, true}};
    expectError(importFile(file, o),
                "export.csv:1:2 (column 'AccX'): unit 'deg/s' (angular rate) cannot be converted to 'm/s^2'");

    o.columns = {{"AccZ", "acc_z", {}, false}};
    expectError(importFile(file, o), "column mapping: the file has no column 'AccZ'");

    o.columns = {{"AccX", "acc_x", {}, false}, {"AccX", "acc_y", {}, false}};
    expectError(importFile(file, o), "column 'AccX' is mapped twice");

    o.columns = {{"Date", {}, {}, true}};
    o.timeColumn = "Zeit";
    expectError(importFile(file, o), "time column 'Zeit' is not in the file");

    o.timeColumn = "Date";
    expectError(importFile(file, o), "time column 'Date' is also marked to skip");

    o.timeColumn = "Time";
    o.timeUnit = "m";
    expectError(importFile(file, o), "time column 'Time': unknown time format 'm' (accepted: s, ms");

    o.timeColumn.clear();  // no time column at all, and none named like one
    o.timeUnit.clear();
    o.columns = {{"Time", "stamp", {}, false}};
    expectError(importFile(file, o), "export.csv:1: no 't' column");

    o.timeColumn = "Time";
    o.columns = {{"AccX", "t", {}, false}, {"Date", {}, {}, true}};
    expectError(importFile(file, o), "(column 'AccX'): the name 't' is taken by the time column 'Time'");
}

TEST_F(ColumnMap, MappingIsForCsvOnly) {
    const QString file = write("walk.nmea", "$GPGGA,000001.00,0100.000,S,00200.000,W,1,05,1.2,10.0,M,0.0,M,,*7C\r\n");
    ImportOptions o;
    o.format = "nmea";
    o.columns = {{"lat", "latitude", {}, false}};
    expectError(importFile(file, o), "a column mapping applies to CSV files only (format 'nmea')");
}

TEST_F(ColumnMap, AthleteGoesIntoRecordingMetadata) {
    auto owned = Project::create(dir_.filePath("p.athlos"));
    Project& project = *owned;
    ImportOptions o = csv("imu");
    o.timeColumn = "Time";
    o.timeUnit = "ms";
    o.target = "anna";
    o.columns = {{"AccX", "acc_x", "g", false}, {"Gyro Z", "gyr_z", "deg/s", false}, {"Date", {}, {}, true}};
    o.metadata.insert("athlete", "Anna");
    auto r = importFile(exportFile(), o);
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    ASSERT_TRUE(applyImport(project, std::move(*r), false).ok());
    ASSERT_TRUE(project.recording("anna"));
    EXPECT_EQ(project.recording("anna")->metadata.value("athlete").toString(), QStringLiteral("Anna"));
    EXPECT_TRUE(project.stream("anna/imu"));
}

}  // namespace
