// CSV export: export → import reproduces values bit for bit, export → import → export bytes.
#include "core/io/Exporter.h"
#include "core/io/Importer.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace athlos;

namespace {

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0 || (std::isnan(a) && std::isnan(b)); }

Expected<ImportResult> importCsv(const QString& file, const QString& kind) {
    ImportOptions options;
    options.format = "csv";
    options.kind = kind;
    options.target = "rt";
    return importFile(file, options);
}

// Random doubles across the whole range: tiny, subnormal, huge, negative, zero, NaN.
double randomValue(std::mt19937_64& rng) {
    constexpr double kSpecial[] = {0.0,       -0.0,
                                   5e-324,    -2.2250738585072014e-308,
                                   1e-300,    1.7976931348623157e308,
                                   -1e300,    0.1,
                                   1.0 / 3.0, std::numeric_limits<double>::quiet_NaN()};
    std::uniform_int_distribution<int> pick(0, 9);
    if (pick(rng) == 0) return kSpecial[pick(rng)];
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-320, 307);
    return mantissa(rng) * std::pow(10.0, exponent(rng));
}

}  // namespace

TEST(CsvRoundTrip, RandomDoublesSurviveExportAndImportBitForBit) {
    QTemporaryDir dir;
    std::mt19937_64 rng(20240611);
    const int rows = 2000, columns = 6;
    StreamData data(rows, columns);
    double t = -1e-3;
    std::uniform_real_distribution<double> step(1e-9, 0.37);
    for (int r = 0; r < rows; ++r) {
        t += step(rng);
        data.t[r] = t;
        for (int c = 0; c < columns; ++c) data.at(r, c) = randomValue(rng);
    }
    StreamInfo info;
    info.name = "imu";
    info.kind = "imu";
    info.frame = "sensor";
    for (const char* name : {"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"})
        info.columns.push_back({name, QString(name).startsWith("acc") ? "m/s^2" : "rad/s"});
    const Stream original(info, data);

    const QString first = dir.filePath("a.csv");
    ASSERT_TRUE(exportStreamCsv(original, first).ok());
    EXPECT_TRUE(readAll(first).startsWith("t,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z\n"));
    const auto back = importCsv(first, "imu");
    ASSERT_TRUE(back.ok()) << back.message().toStdString();
    const Stream& s = std::get<Stream>(back->items[0].item);
    EXPECT_EQ(s.info().columns, info.columns);
    const StreamData& d = **s.data();
    ASSERT_EQ(d.rows(), data.rows());
    for (int r = 0; r < rows; ++r) {
        ASSERT_TRUE(sameBits(d.t[r], data.t[r])) << "t row " << r;
        for (int c = 0; c < columns; ++c)
            ASSERT_TRUE(sameBits(d.at(r, c), data.at(r, c)))
                << "row " << r << " col " << c << ": " << data.at(r, c) << " came back as " << d.at(r, c);
    }
    const QString second = dir.filePath("b.csv");
    ASSERT_TRUE(exportStreamCsv(s, second).ok());
    EXPECT_EQ(readAll(first), readAll(second));
}

TEST(CsvRoundTrip, UnitsOutsideTheKindGoIntoTheHeader) {
    QTemporaryDir dir;
    StreamInfo info;
    info.name = "angles";
    info.kind = "joint-angles";
    info.columns = {{"hip_flexion", "deg"}, {"knee(left)", ""}};
    StreamData data(2, 2);
    data.t = {0.0, 0.01};
    data.values = {10.5, -3, 11.25, -2.5};
    const QString file = dir.filePath("angles.csv");
    ASSERT_TRUE(exportStreamCsv(Stream(info, data), file).ok());
    EXPECT_TRUE(readAll(file).startsWith("t,hip_flexion [deg],knee(left) []\n")) << readAll(file).toStdString();
    const auto back = importCsv(file, "joint-angles");
    ASSERT_TRUE(back.ok()) << back.message().toStdString();
    const Stream& s = std::get<Stream>(back->items[0].item);
    EXPECT_EQ(s.info().columns, info.columns);
    EXPECT_EQ((**s.data()).values, data.values);
}

TEST(CsvRoundTrip, TdoaIsExportedInLongFormAndComesBackTheSame) {
    QTemporaryDir dir;
    const auto first = importCsv(ATHLOS_TEST_DATA_DIR "/tdoa_small.csv", "lps-tdoa");
    ASSERT_TRUE(first.ok()) << first.message().toStdString();
    const Stream& a = std::get<Stream>(first->items[0].item);
    const QString file = dir.filePath("tdoa.csv");
    ASSERT_TRUE(exportStreamCsv(a, file).ok());
    EXPECT_EQ(readAll(file), readAll(ATHLOS_TEST_DATA_DIR "/tdoa_small.csv"));
    const auto second = importCsv(file, "lps-tdoa");
    ASSERT_TRUE(second.ok()) << second.message().toStdString();
    const Stream& b = std::get<Stream>(second->items[0].item);
    EXPECT_EQ(b.info().columns, a.info().columns);
    EXPECT_EQ(b.info().contentHash, a.info().contentHash);
}

TEST(CsvRoundTrip, TableTextIsQuotedWhereNeeded) {
    QTemporaryDir dir;
    Table table;
    table.name = "beacons";
    table.kind = "beacons";
    TableColumn id{"id", "", true, {}, {"#1", "a,b", "say \"hi\"", "", " padded "}};
    TableColumn x{"x", "m", false, {1.5, -0.0, 1e-310, std::numeric_limits<double>::quiet_NaN(), 3}, {}};
    TableColumn y{"y", "m", false, {0, 1, 2, 3, 4}, {}};
    table.columns = {id, x, y};
    const QString file = dir.filePath("beacons.csv");
    ASSERT_TRUE(exportTableCsv(table, file).ok());
    const auto back = importCsv(file, "beacons");
    ASSERT_TRUE(back.ok()) << back.message().toStdString() << "\n" << readAll(file).toStdString();
    const Table& t = std::get<Table>(back->items[0].item);
    ASSERT_EQ(t.rows(), 5);
    EXPECT_EQ(t.column("id")->texts, id.texts);
    for (int r = 0; r < 5; ++r) EXPECT_TRUE(sameBits(t.column("x")->numbers[r], x.numbers[r])) << r;
    EXPECT_EQ(t.column("y")->numbers, y.numbers);

    table.columns[2].numbers.pop_back();
    EXPECT_FALSE(exportTableCsv(table, dir.filePath("ragged.csv")).ok());
}

TEST(CsvRoundTrip, ExportIsAtomicAndCancellable) {
    QTemporaryDir dir;
    const QString file = dir.filePath("keep.csv");
    {
        QFile f(file);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write("old content\n");
    }
    StreamData data(200000, 3);
    for (size_t r = 0; r < data.rows(); ++r) {
        data.t[r] = double(r) * 0.01;
        for (int c = 0; c < 3; ++c) data.at(r, c) = std::sin(double(r + c));
    }
    StreamInfo info;
    info.name = "imu";
    info.kind = "imu";
    info.columns = {{"acc_x", "m/s^2"}, {"acc_y", "m/s^2"}, {"acc_z", "m/s^2"}};
    CancelToken token;
    token.cancel();
    const Status cancelled = exportStreamCsv(Stream(info, data), file, Progress([](double, const QString&) {}, token));
    ASSERT_FALSE(cancelled.ok());
    EXPECT_EQ(cancelled.message(), "cancelled");
    EXPECT_EQ(readAll(file), "old content\n");

    const Status noFolder = exportStreamCsv(Stream(info, data), dir.filePath("missing/x.csv"));
    ASSERT_FALSE(noFolder.ok());
    EXPECT_TRUE(noFolder.message().contains("x.csv")) << noFolder.message().toStdString();
}
