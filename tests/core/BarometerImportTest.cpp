// The barometer stream kind: pressure stored in Pa, a header without a unit read in hPa (the
// interchange convention), other pressure units converted, kind inferred from a pressure column,
// and an export that re-imports unchanged.
#include "TestFiles.h"
#include "core/io/Exporter.h"
#include "core/io/Importer.h"
#include "core/model/StreamKinds.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>

using namespace athlos;

namespace {

Expected<ImportResult> importCsv(const QString& file, const QString& kind) {
    ImportOptions options;
    options.format = "csv";
    options.kind = kind;
    options.target = "walk";
    return importFile(file, options, {});
}

const StreamData& samplesOf(const ImportResult& r) { return **std::get<Stream>(r.items.at(0).item).data(); }

}  // namespace

TEST(BarometerKind, RuleIsPascalAndBareHeadersAreHectopascal) {
    const StreamKind* k = findStreamKind("barometer");
    ASSERT_NE(k, nullptr);
    EXPECT_EQ(k->unitFor("pressure"), "Pa");
    EXPECT_EQ(k->assumedUnitFor("pressure"), "hPa");
    EXPECT_EQ(k->assumedUnitFor("temp"), "");
    EXPECT_EQ(findStreamKind("imu")->assumedUnitFor("acc_x"), "");
}

TEST(BarometerKind, ImportConvertsToPascal) {
    QTemporaryDir dir;
    const QString bare = test::writeFile(dir, "baro.csv", "t,pressure\n0,1013.25\n0.04,1013.5\n");
    const auto r = importCsv(bare, "barometer");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    const Stream& s = std::get<Stream>(r->items.at(0).item);
    EXPECT_EQ(s.info().kind, "barometer");
    EXPECT_EQ(r->items[0].path, "walk/barometer");
    ASSERT_EQ(s.info().columns.size(), 1u);
    EXPECT_EQ(s.info().columns[0].unit, "Pa");
    EXPECT_DOUBLE_EQ(samplesOf(*r).at(0, 0), 101325.0);
    EXPECT_DOUBLE_EQ(samplesOf(*r).at(1, 0), 101350.0);

    // Explicit units are converted as written; the kind is inferred from the pressure column.
    const QString pa = test::writeFile(dir, "pa.csv", "t,pressure [Pa]\n0,90000\n1,90001\n");
    const auto rp = importCsv(pa, "");
    ASSERT_TRUE(rp.ok()) << rp.message().toStdString();
    EXPECT_EQ(std::get<Stream>(rp->items.at(0).item).info().kind, "barometer");
    EXPECT_DOUBLE_EQ(samplesOf(*rp).at(0, 0), 90000.0);
    const QString kpa = test::writeFile(dir, "kpa.csv", "t,pressure (kPa)\n0,101.3\n1,101.2\n");
    const auto rk = importCsv(kpa, "barometer");
    ASSERT_TRUE(rk.ok()) << rk.message().toStdString();
    EXPECT_NEAR(samplesOf(*rk).at(0, 0), 101300.0, 1e-6);

    // A unit that is not a pressure is refused, naming the column.
    const QString bad = test::writeFile(dir, "bad.csv", "t,pressure [m]\n0,1\n1,2\n");
    const auto rb = importCsv(bad, "barometer");
    ASSERT_FALSE(rb.ok());
    EXPECT_TRUE(rb.message().contains("pressure")) << rb.message().toStdString();
}

TEST(BarometerKind, ExportReimportsUnchanged) {
    QTemporaryDir dir;
    const QString bare = test::writeFile(dir, "baro.csv", "t,pressure\n0,1013.25\n0.04,1013.5\n");
    const auto r = importCsv(bare, "barometer");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    const QString out = dir.filePath("out.csv");
    ASSERT_TRUE(exportStreamCsv(std::get<Stream>(r->items.at(0).item), out).ok());
    QFile f(out);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    EXPECT_TRUE(f.readLine().contains("pressure [Pa]"));  // the unit is written: a bare header means hPa
    const auto again = importCsv(out, "barometer");
    ASSERT_TRUE(again.ok()) << again.message().toStdString();
    EXPECT_DOUBLE_EQ(samplesOf(*again).at(1, 0), 101350.0);
}
