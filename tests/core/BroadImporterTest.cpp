// BROAD import against the real trial, checked with direct HDF5 reads; damaged and incomplete files.
#include "core/io/Importer.h"

#include "tests/SharedData.h"

#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>
#include <algorithm>
#include <cmath>
#include <hdf5.h>

using namespace athlos;

namespace {

const QString kTrial = QStringLiteral(ATHLOS_SHARED_DATA_DIR "/broad/02_undisturbed_slow_rotation_B.hdf5");

// Reads a whole float dataset with the HDF5 C API, independently of the importer.
std::vector<double> readDataset(const QString& file, const char* name) {
    const hid_t f = H5Fopen(file.toLocal8Bit().constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t d = H5Dopen2(f, name, H5P_DEFAULT);
    const hid_t s = H5Dget_space(d);
    std::vector<double> out(size_t(H5Sget_simple_extent_npoints(s)));
    H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
    H5Sclose(s);
    H5Dclose(d);
    H5Fclose(f);
    return out;
}

std::vector<signed char> readMovement(const QString& file) {
    const hid_t f = H5Fopen(file.toLocal8Bit().constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t d = H5Dopen2(f, "movement", H5P_DEFAULT);
    const hid_t s = H5Dget_space(d);
    const hid_t type = H5Dget_type(d);
    const hid_t native = H5Tget_native_type(type, H5T_DIR_ASCEND);
    std::vector<signed char> out(size_t(H5Sget_simple_extent_npoints(s)));
    H5Dread(d, native, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data());
    H5Tclose(native);
    H5Tclose(type);
    H5Sclose(s);
    H5Dclose(d);
    H5Fclose(f);
    return out;
}

Expected<ImportResult> importBroad(const QString& file, const QString& format = "broad",
                                   const QString& target = "trial") {
    ImportOptions options;
    options.format = format;
    options.target = target;
    return importFile(file, options);
}

void writeDataset(hid_t file, const char* name, hsize_t rows, hsize_t columns) {
    const hsize_t dims[2] = {rows, columns};
    const hid_t space = H5Screate_simple(2, dims, nullptr);
    const hid_t d = H5Dcreate2(file, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    std::vector<double> zeros(rows * columns, 0.5);
    H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data());
    H5Dclose(d);
    H5Sclose(space);
}

}  // namespace

TEST(BroadImport, ImportsImuAndReferenceOfTheRealTrial) {
    ATHLOS_SKIP_WITHOUT_SHARED(kTrial);
    const auto r = importBroad(kTrial);
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    ASSERT_EQ(r->items.size(), 2u);
    EXPECT_EQ(r->items[0].path, "trial/imu");
    EXPECT_EQ(r->items[1].path, "trial/reference");
    const Stream& imu = std::get<Stream>(r->items[0].item);
    const Stream& ref = std::get<Stream>(r->items[1].item);

    EXPECT_EQ(imu.info().kind, "imu");
    EXPECT_EQ(imu.info().frame, "sensor");
    EXPECT_EQ(imu.info().columnNames(),
              (QStringList{"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z", "mag_x", "mag_y", "mag_z"}));
    EXPECT_EQ(imu.info().columns[0].unit, "m/s^2");
    EXPECT_EQ(imu.info().columns[4].unit, "rad/s");
    EXPECT_EQ(imu.info().columns[8].unit, "uT");
    EXPECT_EQ(ref.info().kind, "reference");
    EXPECT_EQ(ref.info().frame, "ENU");
    EXPECT_EQ(ref.info().columnNames(), (QStringList{"qw", "qx", "qy", "qz", "movement", "pos_x", "pos_y", "pos_z"}));
    EXPECT_EQ(ref.info().provenance.processorId, "import:broad");

    const double rate = imu.info().attributes["sampling_rate"].toDouble();
    EXPECT_NEAR(rate, 285.714, 1e-3);
    const StreamData& d = **imu.data();
    const StreamData& q = **ref.data();
    const size_t rows = 53240;
    ASSERT_EQ(d.rows(), rows);
    ASSERT_EQ(q.rows(), rows);
    EXPECT_EQ(d.t[0], 0.0);
    EXPECT_DOUBLE_EQ(d.t[1000], 1000.0 / rate);
    EXPECT_EQ(d.t, q.t);

    const auto acc = readDataset(kTrial, "imu_acc");
    const auto gyr = readDataset(kTrial, "imu_gyr");
    const auto mag = readDataset(kTrial, "imu_mag");
    const auto quat = readDataset(kTrial, "opt_quat");
    const auto pos = readDataset(kTrial, "opt_pos");
    const auto movement = readMovement(kTrial);
    size_t quatNaN = 0, importedNaN = 0;
    for (size_t r = 0; r < rows; ++r) {
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(d.at(r, c), acc[r * 3 + c]) << r;
            ASSERT_EQ(d.at(r, 3 + c), gyr[r * 3 + c]) << r;
            ASSERT_EQ(d.at(r, 6 + c), mag[r * 3 + c]) << r;
            ASSERT_TRUE(q.at(r, 5 + c) == pos[r * 3 + c] || (std::isnan(q.at(r, 5 + c)) && std::isnan(pos[r * 3 + c])))
                << r;
        }
        for (int c = 0; c < 4; ++c) {
            quatNaN += std::isnan(quat[r * 4 + c]);
            importedNaN += std::isnan(q.at(r, c));
            if (!std::isnan(quat[r * 4 + c])) {
                ASSERT_EQ(q.at(r, c), quat[r * 4 + c]) << r;
            }
        }
        ASSERT_EQ(q.at(r, 4), double(movement[r])) << r;
    }
    EXPECT_EQ(importedNaN, quatNaN);  // optical dropouts are kept, not filled
    EXPECT_GT(std::count(movement.begin(), movement.end(), 1), 0);
    EXPECT_GT(std::count(movement.begin(), movement.end(), 0), 0);

    // At rest (the first samples, before the movement starts) the accelerometer measures gravity.
    ASSERT_EQ(movement[0], 0);
    double magnitude = 0.0;
    const int rest = 100;
    for (int r = 0; r < rest; ++r)
        magnitude += std::sqrt(d.at(r, 0) * d.at(r, 0) + d.at(r, 1) * d.at(r, 1) + d.at(r, 2) * d.at(r, 2));
    EXPECT_NEAR(magnitude / rest, 9.81, 0.15);
}

TEST(BroadImport, AutoDetectionAndTargetNaming) {
    ATHLOS_SKIP_WITHOUT_SHARED(kTrial);
    const auto r = importBroad(kTrial, "auto", "t2/broad");
    ASSERT_TRUE(r.ok()) << r.message().toStdString();
    EXPECT_EQ(r->items[0].path, "t2/broad-imu");
    EXPECT_EQ(r->items[1].path, "t2/broad-reference");
    EXPECT_EQ(std::get<Stream>(r->items[0].item).info().name, "broad-imu");
    EXPECT_EQ(std::get<Stream>(r->items[0].item).info().provenance.processorId, "import:broad");
}

TEST(BroadImport, RefusesTruncatedAndGarbageFiles) {
    ATHLOS_SKIP_WITHOUT_SHARED(kTrial);
    QTemporaryDir dir;
    QFile source(kTrial);
    ASSERT_TRUE(source.open(QIODevice::ReadOnly));
    const QByteArray bytes = source.readAll();

    const QString truncated = dir.filePath("truncated.hdf5");
    {
        QFile f(truncated);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(bytes.left(bytes.size() / 3));
    }
    const auto t = importBroad(truncated);
    ASSERT_FALSE(t.ok());
    EXPECT_TRUE(t.message().contains("truncated.hdf5")) << t.message().toStdString();

    const QString garbage = dir.filePath("garbage.hdf5");
    {
        QFile f(garbage);
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(bytes.left(8) + QByteArray(4096, '\x5a'));
    }
    const auto g = importBroad(garbage);
    ASSERT_FALSE(g.ok());
    EXPECT_TRUE(g.message().contains("garbage.hdf5")) << g.message().toStdString();
    EXPECT_FALSE(importBroad(garbage, "auto").ok());  // not detected as BROAD either

    const auto csv = importBroad(ATHLOS_TEST_DATA_DIR "/beacons.csv");
    ASSERT_FALSE(csv.ok());
    EXPECT_TRUE(csv.message().contains("not an HDF5 file")) << csv.message().toStdString();
}

TEST(BroadImport, NamesTheMissingDataset) {
    QTemporaryDir dir;
    const QString file = dir.filePath("incomplete.hdf5");
    const hid_t f = H5Fcreate(file.toLocal8Bit().constData(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    writeDataset(f, "imu_acc", 10, 3);
    writeDataset(f, "imu_gyr", 10, 3);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t attr = H5Acreate2(f, "sampling_rate", H5T_IEEE_F64LE, scalar, H5P_DEFAULT, H5P_DEFAULT);
    const double rate = 100.0;
    H5Awrite(attr, H5T_NATIVE_DOUBLE, &rate);
    H5Aclose(attr);
    H5Sclose(scalar);
    H5Fclose(f);

    const auto r = importBroad(file, "auto");
    ASSERT_FALSE(r.ok());
    EXPECT_TRUE(r.message().contains("incomplete.hdf5")) << r.message().toStdString();
    EXPECT_TRUE(r.message().contains("'imu_mag'")) << r.message().toStdString();

    // A dataset of the wrong shape is named as well.
    const hid_t g = H5Fopen(file.toLocal8Bit().constData(), H5F_ACC_RDWR, H5P_DEFAULT);
    writeDataset(g, "imu_mag", 10, 2);
    H5Fclose(g);
    const auto shape = importBroad(file);
    ASSERT_FALSE(shape.ok());
    EXPECT_TRUE(shape.message().contains("'imu_mag' should be N×3")) << shape.message().toStdString();
}
