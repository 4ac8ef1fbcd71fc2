// Standalone HDF5 export, read back with the plain HDF5 C API as a non-Athlos user would.
#include "core/io/Exporter.h"
#include "tests/core/StoreTestData.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <QTemporaryDir>
#include <string>

namespace athlos {
namespace {

std::vector<double> readDoubles(hid_t file, const char* name, std::vector<hsize_t>* dims = nullptr) {
    const hid_t dataset = H5Dopen2(file, name, H5P_DEFAULT);
    EXPECT_GE(dataset, 0) << name;
    const hid_t space = H5Dget_space(dataset);
    std::vector<hsize_t> shape(std::size_t(H5Sget_simple_extent_ndims(space)));
    H5Sget_simple_extent_dims(space, shape.data(), nullptr);
    std::vector<double> values(std::size_t(H5Sget_simple_extent_npoints(space)));
    if (!values.empty()) H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Sclose(space);
    H5Dclose(dataset);
    if (dims) *dims = shape;
    return values;
}

// Athlos writes fixed-length, NUL-padded UTF-8 strings (no variable-length strings since format 2).
std::vector<std::string> readStringArrayAttribute(hid_t object, const char* name) {
    const hid_t attribute = H5Aopen(object, name, H5P_DEFAULT);
    const hid_t space = H5Aget_space(attribute);
    const hid_t type = H5Aget_type(attribute);
    EXPECT_EQ(H5Tis_variable_str(type), 0);
    const std::size_t width = H5Tget_size(type);
    const std::size_t count = std::size_t(H5Sget_simple_extent_npoints(space));
    std::vector<char> raw(width * count);
    H5Aread(attribute, type, raw.data());
    std::vector<std::string> values;
    for (std::size_t i = 0; i < count; ++i) {
        const char* s = raw.data() + i * width;
        values.emplace_back(s, std::find(s, s + width, '\0'));
    }
    H5Tclose(type);
    H5Sclose(space);
    H5Aclose(attribute);
    return values;
}

TEST(StoreExportTest, StreamFileIsSelfDescribing) {
    QTemporaryDir dir;
    const StreamData data = test::makeSamples(70000, 6, 11);
    Stream stream = test::makeStream(QStringLiteral("imu"), test::imuColumns(), data);
    stream.info().name = QStringLiteral("imu");
    const QString file = dir.filePath(QStringLiteral("imu.h5"));
    const Status exported = exportStreamHdf5(stream, file);
    ASSERT_TRUE(exported.ok()) << exported.message().toStdString();

    const hid_t h5 = H5Fopen(QFile::encodeName(file).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(h5, 0);
    std::vector<hsize_t> dims;
    EXPECT_EQ(readDoubles(h5, "t"), data.t);
    EXPECT_EQ(readDoubles(h5, "data", &dims), data.values);
    EXPECT_EQ(dims, (std::vector<hsize_t>{70000, 6}));
    EXPECT_EQ(readStringArrayAttribute(h5, "column_names"),
              (std::vector<std::string>{"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"}));
    EXPECT_EQ(readStringArrayAttribute(h5, "units")[3], "rad/s");
    H5Fclose(h5);
}

TEST(StoreExportTest, TableFileHasOneDatasetPerColumn) {
    QTemporaryDir dir;
    Table table;
    table.name = QStringLiteral("beacons");
    table.kind = QStringLiteral("beacons");
    table.columns = {{QStringLiteral("id"), {}, true, {}, {QStringLiteral("B1"), QStringLiteral("B2")}},
                     {QStringLiteral("x"), QStringLiteral("m"), false, {1.5, -2.25}, {}}};
    const QString file = dir.filePath(QStringLiteral("beacons.h5"));
    ASSERT_TRUE(exportTableHdf5(table, file).ok());
    const hid_t h5 = H5Fopen(QFile::encodeName(file).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
    ASSERT_GE(h5, 0);
    EXPECT_EQ(readDoubles(h5, "x"), (std::vector<double>{1.5, -2.25}));
    EXPECT_GT(H5Lexists(h5, "id", H5P_DEFAULT), 0);
    H5Fclose(h5);
}

TEST(StoreExportTest, FailureNamesTheFileAndLeavesNothing) {
    QTemporaryDir dir;
    test::quietHdf5();
    Stream stream = test::makeStream(QStringLiteral("imu"), {{"x", "m"}}, test::makeSamples(10, 1, 1));
    const QString file = dir.filePath(QStringLiteral("missing-folder/out.h5"));
    const Status exported = exportStreamHdf5(stream, file);
    ASSERT_FALSE(exported.ok());
    EXPECT_TRUE(exported.message().contains(QStringLiteral("out.h5"))) << exported.message().toStdString();
    EXPECT_FALSE(QFile::exists(file));
}

}  // namespace
}  // namespace athlos
