// gaitmap import against the raw files: every value, left/right assignment by header, gyr in rad/s.
#include "core/io/GaitmapImporter.h"
#include "core/io/Importer.h"

#include "tests/SharedData.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>
#include <cmath>
#include <numbers>

using namespace athlos;

namespace {

const QString kStride = QStringLiteral(ATHLOS_SHARED_DATA_DIR "/gaitmap/imu_sample_ic_stride.csv");
const QString kStairUp = QStringLiteral(ATHLOS_SHARED_DATA_DIR "/gaitmap/imu_sample_healthy_stair_up.csv");

// The raw file, split naively (these files have no quotes): header rows and numbers.
struct Raw {
    QStringList sensors, axes;
    std::vector<std::vector<double>> rows;
    int column(const QString& sensor, const QString& axis) const {
        for (int i = 0; i < sensors.size(); ++i)
            if (sensors[i] == sensor && axes[i] == axis) return i;
        return -1;
    }
};

Raw readRaw(const QString& path) {
    QFile f(path);
    EXPECT_TRUE(f.open(QIODevice::ReadOnly));
    Raw raw;
    const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
    raw.sensors = QString::fromUtf8(lines[0].trimmed()).split(',');
    raw.axes = QString::fromUtf8(lines[1].trimmed()).split(',');
    for (int i = 2; i < lines.size(); ++i) {
        std::vector<double> row;
        for (const QByteArray& cell : lines[i].trimmed().split(',')) row.push_back(cell.toDouble());
        raw.rows.push_back(row);
    }
    return raw;
}

Expected<ImportResult> importGaitmap(const QString& file, const QString& format = "gaitmap") {
    ImportOptions options;
    options.format = format;
    options.target = "walk";
    return importFile(file, options);
}

// Every sample of both feet equals the raw column of the same sensor and axis (gyr in rad/s).
void expectMatchesRaw(const ImportResult& result, const Raw& raw) {
    ASSERT_EQ(result.items.size(), 2u);
    const std::pair<const char*, const char*> feet[] = {{"walk/left-foot", "left_sensor"},
                                                        {"walk/right-foot", "right_sensor"}};
    for (size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(result.items[i].path, feet[i].first);
        const Stream& s = std::get<Stream>(result.items[i].item);
        EXPECT_EQ(s.info().kind, "imu");
        EXPECT_EQ(s.info().frame, "sensor");
        EXPECT_EQ(s.info().columnNames(), (QStringList{"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"}));
        EXPECT_EQ(s.info().columns[0].unit, "m/s^2");
        EXPECT_EQ(s.info().columns[3].unit, "rad/s");
        const StreamData& d = **s.data();
        ASSERT_EQ(d.rows(), raw.rows.size());
        for (int c = 0; c < 6; ++c) {
            const QString axis = s.info().columns[c].name;
            const int rawColumn = raw.column(feet[i].second, axis);
            ASSERT_GT(rawColumn, 0) << axis.toStdString();
            const double scale = axis.startsWith("gyr") ? std::numbers::pi / 180.0 : 1.0;
            for (size_t r = 0; r < d.rows(); ++r)
                ASSERT_DOUBLE_EQ(d.at(r, c), raw.rows[r][rawColumn] * scale)
                    << feet[i].first << " " << axis.toStdString() << " row " << r;
        }
    }
}

}  // namespace

TEST(GaitmapImport, StrideFileWithSampleIndexAndInterleavedColumns) {
    ATHLOS_SKIP_WITHOUT_SHARED(kStride);
    const Raw raw = readRaw(kStride);
    ASSERT_EQ(raw.rows.size(), 4053u);
    const auto r = importGaitmap(kStride);
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    expectMatchesRaw(*r, raw);
    const Stream& left = std::get<Stream>(r->items[0].item);
    EXPECT_EQ(left.info().attributes["sampling_rate"].toDouble(), 102.4);
    const StreamData& d = **left.data();
    EXPECT_EQ(d.t[0], 0.0);
    EXPECT_DOUBLE_EQ(d.t[1024], 10.0);  // sample index / 102.4 Hz
    EXPECT_EQ(left.info().provenance.processorId, "import:gaitmap");
    // Interleaved: the file's column 1 is left acc_x, column 2 right acc_x.
    EXPECT_EQ(d.at(0, 0), -6.314179038);
    EXPECT_EQ((**std::get<Stream>(r->items[1].item).data()).at(0, 0), -6.493950687);
}

TEST(GaitmapImport, StairFileWithTimeInSecondsAndGroupedColumns) {
    ATHLOS_SKIP_WITHOUT_SHARED(kStairUp);
    const Raw raw = readRaw(kStairUp);
    const auto r = importGaitmap(kStairUp, "auto");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    expectMatchesRaw(*r, raw);
    const Stream& right = std::get<Stream>(r->items[1].item);
    EXPECT_DOUBLE_EQ(right.info().attributes["sampling_rate"].toDouble(), 204.8);
    const StreamData& d = **right.data();
    for (size_t i = 0; i < d.rows(); ++i) ASSERT_EQ(d.t[i], raw.rows[i][0]) << i;  // time column taken as is
    EXPECT_EQ(right.info().provenance.processorId, "import:gaitmap");
}

TEST(GaitmapImport, PandasLevelNamesInTheIndexColumn) {
    ATHLOS_SKIP_WITHOUT_SHARED(kStride);
    // pandas' to_csv of a MultiIndex frame writes the level names ("sensor", "axis") into the index
    // column, and a third row with the index name when it has one: the same streams as with empty cells.
    const Raw raw = readRaw(kStride);
    QFile in(kStride);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    QByteArray text = in.readAll();
    in.close();
    ASSERT_TRUE(text.startsWith(",left_sensor"));
    const qsizetype secondLine = text.indexOf('\n') + 1;
    ASSERT_EQ(text.at(secondLine), ',');
    QTemporaryDir dir;
    const QByteArray width = QByteArray(raw.sensors.size() - 1, ',');
    for (const bool indexNameRow : {false, true}) {
        QByteArray named = text;
        named.insert(secondLine, "axis");
        named.insert(0, "sensor");
        if (indexNameRow) named.insert(named.indexOf('\n', secondLine + 10) + 1, "sample" + width + "\n");
        const QString path = dir.filePath(indexNameRow ? "named_index.csv" : "named.csv");
        QFile out(path);
        ASSERT_TRUE(out.open(QIODevice::WriteOnly));
        out.write(named);
        out.close();
        const auto r = importGaitmap(path);
        ASSERT_TRUE(r.ok()) << r.message().toStdString();
        expectMatchesRaw(*r, raw);
        const StreamData& d = **std::get<Stream>(r->items[0].item).data();
        EXPECT_DOUBLE_EQ(d.t[1], 1.0 / GaitmapImporter::kIndexRate);  // still read as a sample index
        GaitmapImporter importer;
        EXPECT_TRUE(importer.canRead(path, named.left(4096)));
    }
}

TEST(GaitmapImport, OneSensorPerSideAreTheFeetWhateverTheirNames) {
    // gaitmap's datasets name the sensors by position (l_lateral, r_instep, …): one of each side are the
    // left-foot and right-foot streams the gait processors expect; more than one foot sensor per side
    // keep their names, and other body parts are never the feet.
    QTemporaryDir dir;
    const auto streams = [&](const QByteArray& header) {
        QFile f(dir.filePath("s.csv"));
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(header + "\n");
        QByteArray axes = "axis", row = "0";
        const int n = int(header.count(','));
        for (int i = 0; i < n; ++i) axes += ",gyr_x";
        f.write(axes + "\n");
        for (int k = 0; k < 3; ++k) {
            row = QByteArray::number(k);
            for (int i = 0; i < n; ++i) row += ",1";
            f.write(row + "\n");
        }
        f.close();
        QStringList names, sensors;
        auto r = importGaitmap(dir.filePath("s.csv"));
        EXPECT_TRUE(r.ok()) << r.message().toStdString();
        if (r.ok())
            for (const auto& item : r->items) {
                names << std::get<Stream>(item.item).info().name;
                sensors << std::get<Stream>(item.item).info().attributes["sensor"].toString();
            }
        return std::make_pair(names.join(' '), sensors.join(' '));
    };
    EXPECT_EQ(streams("sensor,l_lateral,r_lateral"),
              std::make_pair(QString("left-foot right-foot"), QString("l_lateral r_lateral")));
    EXPECT_EQ(streams("sensor,Left_Foot,Right_Foot,chest").first, "left-foot right-foot chest");
    EXPECT_EQ(streams("sensor,foot_r,foot_l").first, "right-foot left-foot");
    EXPECT_EQ(streams("sensor,LeftFoot,footRight").first, "left-foot right-foot");
    // Other body parts are never feet: an ankle pair beside the foot pair, a wrist pair alone.
    EXPECT_EQ(streams("sensor,l_ankle,l_lateral,r_ankle,r_lateral").first, "l-ankle left-foot r-ankle right-foot");
    EXPECT_EQ(streams("sensor,LeftWrist,RightWrist").first, "LeftWrist RightWrist");
    EXPECT_EQ(streams("sensor,l_thigh,r_thigh,l_heel,r_heel").first, "l-thigh r-thigh left-foot right-foot");
    // Several foot positions per side (gaitmap's sensor position study) are ambiguous: names kept.
    EXPECT_EQ(streams("sensor,l_heel,l_instep,r_heel,r_instep").first, "l-heel l-instep r-heel r-instep");
    EXPECT_EQ(streams("sensor,left_sensor,l_ankle,right_sensor").first, "left-foot l-ankle right-foot");
    EXPECT_EQ(streams("sensor,lateral,instep").first, "lateral instep");
}

TEST(GaitmapImport, DetectsOnlyGaitmapFiles) {
    GaitmapImporter importer;
    EXPECT_TRUE(importer.canRead("walk.csv", ",left_sensor,right_sensor\n,acc_x,acc_x\n0,1,2\n"));
    EXPECT_FALSE(importer.canRead("imu.csv", "t,acc_x,acc_y\n0,1,2\n"));
    // Other sensor names over pandas' axis row (gaitmap's datasets: l_lateral, r_instep, …).
    EXPECT_TRUE(importer.canRead("walk.csv", "sensor,l_lateral,r_lateral\naxis,acc_x,acc_x\n0,1,2\n"));
    EXPECT_TRUE(importer.canRead("walk.csv", ",l_lateral,r_lateral\n,gyr_x,gyr_x\n0,1,2\n"));
    EXPECT_FALSE(importer.canRead("imu.csv", "sensor,a,b\nt,acc_x,acc_x\n0,1,2\n"));
    EXPECT_FALSE(importer.canRead("walk.h5", ",left_sensor\n,acc_x\n"));
}

TEST(GaitmapImport, ErrorsNameFileLineAndColumn) {
    QTemporaryDir dir;
    auto write = [&](const QString& name, const QByteArray& text) {
        QFile f(dir.filePath(name));
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(text);
        return dir.filePath(name);
    };
    const QByteArray header = ",left_sensor,right_sensor\n,gyr_x,gyr_x\n";
    const auto bad = importGaitmap(write("bad.csv", header + "0,1,2\n1,1,x\n"));
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains("bad.csv:4:3 (column 'right_sensor/gyr_x'): 'x' is not a number"))
        << bad.message().toStdString();
    const auto few = importGaitmap(write("few.csv", header + "0,1,2\n1,1\n"));
    ASSERT_FALSE(few.ok());
    EXPECT_TRUE(few.message().contains("few.csv:4:3")) << few.message().toStdString();
    const auto back = importGaitmap(write("back.csv", header + "0.0,1,2\n0.2,1,2\n0.1,1,2\n"));
    ASSERT_FALSE(back.ok());
    EXPECT_TRUE(back.message().contains("back.csv:5:1")) << back.message().toStdString();
    const auto unit = importGaitmap(write("unit.csv", ",left_sensor\n,acc_x [m]\n0,1\n"));
    ASSERT_FALSE(unit.ok());
    EXPECT_TRUE(unit.message().contains("unit.csv:2:2 (column 'left_sensor/acc_x')")) << unit.message().toStdString();
    EXPECT_FALSE(importGaitmap(write("empty.csv", "")).ok());

    // Explicit units in the axis row win over gaitmap's deg/s.
    const auto rad =
        importGaitmap(write("rad.csv", ",left_sensor,left_sensor\n,gyr_x [rad/s],acc_z (g)\n0,1,1\n1,2,2\n"));
    ASSERT_TRUE(rad.ok()) << rad.message().toStdString();
    const StreamData& d = **std::get<Stream>(rad->items[0].item).data();
    EXPECT_EQ(d.at(1, 1), 2.0);  // columns in canonical order: acc_z, then gyr_x
    EXPECT_DOUBLE_EQ(d.at(1, 0), 2 * 9.80665);
}

TEST(GaitmapImport, SampleIndexRateFromTheMotion) {
    ATHLOS_SKIP_WITHOUT_SHARED(kStairUp);
    ATHLOS_SKIP_WITHOUT_SHARED(kStride);
    // The stair file (204.8 Hz, time in seconds) rewritten with a sample index, as pandas writes
    // gaitmap's imu_sample.csv: the rate comes from the gyroscope/accelerometer agreement, not 102.4 Hz.
    const Raw raw = readRaw(kStairUp);
    QFile in(kStairUp);
    ASSERT_TRUE(in.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = in.readAll().trimmed().split('\n');
    QByteArray indexed = "sensor" + lines[0] + '\n' + lines[1] + '\n';
    for (int i = 2; i < lines.size(); ++i) indexed += QByteArray::number(i - 2) + lines[i].mid(lines[i].indexOf(',')) + '\n';
    QTemporaryDir dir;
    const QString path = dir.filePath("stairs_index.csv");
    QFile out(path);
    ASSERT_TRUE(out.open(QIODevice::WriteOnly));
    out.write(indexed);
    out.close();
    auto r = importGaitmap(path);
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    expectMatchesRaw(*r, raw);
    const Stream& left = std::get<Stream>(r->items[0].item);
    EXPECT_DOUBLE_EQ(left.info().attributes["sampling_rate"].toDouble(), 204.8);
    EXPECT_EQ(left.info().attributes["sampling_rate_source"].toString(), "motion");
    EXPECT_DOUBLE_EQ((**left.data()).t[2048], 10.0);
    ASSERT_EQ(r->warnings.size(), 1);
    EXPECT_TRUE(r->warnings[0].contains("204.8 Hz from the motion")) << r->warnings[0].toStdString();
    // The 102.4 Hz walk is still read at 102.4 Hz, now from its motion.
    r = importGaitmap(kStride);
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_EQ(std::get<Stream>(r->items[0].item).info().attributes["sampling_rate_source"].toString(), "motion");
    EXPECT_DOUBLE_EQ(std::get<Stream>(r->items[0].item).info().attributes["sampling_rate"].toDouble(), 102.4);
    // A given rate wins and is recorded in provenance.
    ImportOptions options;
    options.format = "gaitmap";
    options.target = "walk";
    options.rate = 409.6;
    r = importFile(path, options);
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    const Stream& given = std::get<Stream>(r->items[0].item);
    EXPECT_DOUBLE_EQ(given.info().attributes["sampling_rate"].toDouble(), 409.6);
    EXPECT_EQ(given.info().attributes["sampling_rate_source"].toString(), "given");
    EXPECT_DOUBLE_EQ(given.info().provenance.parameters["rate"].toDouble(), 409.6);
    EXPECT_DOUBLE_EQ((**given.data()).t[4096], 10.0);
}
