// Files the project store must refuse, each with a message that names the file (never a crash).
#include "core/store/ProjectFile.h"
#include "tests/core/StoreTestData.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cstring>
#include <random>

namespace athlos {
namespace {

using test::fileBytes;
using test::writeBytes;

class StoreRefusalTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        test::quietHdf5();
        path_ = dir_.filePath(QStringLiteral("team ä.athlos"));
    }
    void saveValid() {
        auto project = test::makeFullProject(path_);
        ASSERT_TRUE(project->save().ok());
    }
    // Opens path expecting a refusal that names the file and contains every one of parts.
    void expectRefusal(const QString& path, const QStringList& parts) {
        auto opened = Project::open(path);
        ASSERT_FALSE(opened.ok()) << "opened " << path.toStdString();
        const QString message = opened.message();
        EXPECT_TRUE(message.contains(QFileInfo(path).fileName())) << message.toStdString();
        for (const QString& part : parts) EXPECT_TRUE(message.contains(part)) << message.toStdString();
    }
    QTemporaryDir dir_;
    QString path_;
};

// Raw HDF5 edits of a saved project.
struct RawFile {
    explicit RawFile(const QString& path)
        : id(H5Fopen(QFile::encodeName(path).constData(), H5F_ACC_RDWR, H5P_DEFAULT)) {}
    ~RawFile() {
        if (id >= 0) H5Fclose(id);
    }
    hid_t id;
};

void writeFixedStringAttribute(hid_t object, const char* name, const char* value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, std::strlen(value) + 1);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attribute, type, value);
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
}

TEST_F(StoreRefusalTest, MissingFile) {
    expectRefusal(dir_.filePath(QStringLiteral("nowhere.athlos")), {QStringLiteral("does not exist")});
}

TEST_F(StoreRefusalTest, GarbageBytes) {
    std::mt19937 rng(7);
    QByteArray garbage(64 * 1024, '\0');
    for (char& c : garbage) c = char(rng());
    ASSERT_TRUE(writeBytes(path_, garbage));
    expectRefusal(path_, {QStringLiteral("not an HDF5 file")});
    ASSERT_TRUE(writeBytes(path_, QByteArray()));
    expectRefusal(path_, {});
}

TEST_F(StoreRefusalTest, Hdf5FileThatIsNotAProject) {
    {
        const hid_t file = H5Fcreate(QFile::encodeName(path_).constData(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        H5Gclose(H5Gcreate2(file, "recordings", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
        H5Fclose(file);
    }
    expectRefusal(path_, {QStringLiteral("not an Athlos project"), QStringLiteral("format")});

    const QString other = dir_.filePath(QStringLiteral("netcdf.h5"));
    {
        const hid_t file = H5Fcreate(QFile::encodeName(other).constData(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
        writeFixedStringAttribute(file, "format", "netcdf4");  // fixed-length strings are read, too
        H5Fclose(file);
    }
    expectRefusal(other, {QStringLiteral("not an Athlos project"), QStringLiteral("netcdf4")});
}

TEST_F(StoreRefusalTest, NewerFormatVersion) {
    saveValid();
    {
        RawFile raw(path_);
        ASSERT_GE(raw.id, 0);
        const hid_t attribute = H5Aopen(raw.id, "format_version", H5P_DEFAULT);
        const long long newer = Project::kFormatVersion + 1;
        ASSERT_GE(H5Awrite(attribute, H5T_NATIVE_LLONG, &newer), 0);
        H5Aclose(attribute);
    }
    expectRefusal(path_, {QStringLiteral("was written by a newer Athlos (format version %1; this build reads up to %2)")
                              .arg(Project::kFormatVersion + 1)
                              .arg(Project::kFormatVersion)});
}

TEST_F(StoreRefusalTest, TruncatedFile) {
    saveValid();
    const QByteArray whole = fileBytes(path_);
    ASSERT_GT(whole.size(), 1 << 20);
    for (const double fraction : {0.01, 0.1, 0.5, 0.9}) {
        SCOPED_TRACE(fraction);
        ASSERT_TRUE(writeBytes(path_, whole.left(qsizetype(whole.size() * fraction))));
        expectRefusal(path_, {QStringLiteral("truncated")});
    }
    ASSERT_TRUE(writeBytes(path_, whole.left(whole.size() - 1)));
    expectRefusal(path_, {QStringLiteral("truncated")});
}

TEST_F(StoreRefusalTest, FileTruncatedAfterOpenFailsToLoad) {
    saveValid();
    auto opened = Project::open(path_);
    ASSERT_TRUE(opened.ok());
    const QByteArray whole = fileBytes(path_);
    ASSERT_TRUE(writeBytes(path_, whole.left(whole.size() / 2)));
    auto data = (*opened)->stream(QStringLiteral("run2/lps"))->data();
    ASSERT_FALSE(data.ok());
    EXPECT_TRUE(data.message().contains(QFileInfo(path_).fileName())) << data.message().toStdString();
    EXPECT_TRUE(data.message().contains(QStringLiteral("/recordings/run2/lps"))) << data.message().toStdString();
}

TEST_F(StoreRefusalTest, DataRowsDifferFromTimeRows) {
    saveValid();
    {
        RawFile raw(path_);
        ASSERT_GE(raw.id, 0);
        ASSERT_GE(H5Ldelete(raw.id, "/recordings/run1/imu/data", H5P_DEFAULT), 0);
        const hsize_t dims[2] = {999, 6};
        const hid_t space = H5Screate_simple(2, dims, nullptr);
        const hid_t dataset = H5Dcreate2(raw.id, "/recordings/run1/imu/data", H5T_IEEE_F64LE, space, H5P_DEFAULT,
                                         H5P_DEFAULT, H5P_DEFAULT);
        ASSERT_GE(dataset, 0);
        H5Dclose(dataset);
        H5Sclose(space);
    }
    expectRefusal(path_, {QStringLiteral("/recordings/run1/imu"), QStringLiteral("data has 999 rows but t has 1000")});
    // A loader pointed at the damaged stream refuses as well.
    auto loaded = ProjectFile::loadStream(path_, QStringLiteral("/recordings/run1/imu"), 6);
    ASSERT_FALSE(loaded.ok());
    EXPECT_TRUE(loaded.message().contains(QStringLiteral("999 rows"))) << loaded.message().toStdString();
    EXPECT_TRUE(loaded.message().contains(QFileInfo(path_).fileName())) << loaded.message().toStdString();
}

TEST_F(StoreRefusalTest, MissingStreamAttributeNamesTheObject) {
    saveValid();
    {
        RawFile raw(path_);
        ASSERT_GE(raw.id, 0);
        ASSERT_GE(H5Adelete_by_name(raw.id, "/recordings/run2/lps", "rows", H5P_DEFAULT), 0);
    }
    expectRefusal(path_, {QStringLiteral("rows"), QStringLiteral("/recordings/run2/lps")});
}

TEST_F(StoreRefusalTest, FailedReadLeavesTheProjectUnchanged) {
    saveValid();
    auto project = Project::create(dir_.filePath(QStringLiteral("other.athlos")), QStringLiteral("football"));
    ASSERT_TRUE(writeBytes(path_, QByteArray("not a project")));
    ASSERT_FALSE(ProjectFile::read(path_, *project).ok());
    EXPECT_EQ(project->meta().sport, QStringLiteral("football"));
    EXPECT_TRUE(project->recordingNames().isEmpty());
}

}  // namespace
}  // namespace athlos
