// Issue #11: a damaged project file is refused with a clear message, never a crash; format
// version 2 carries checksums; version-1 files are read and upgraded.
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

std::unique_ptr<Project> makeSmallProject(const QString& path) {
    auto project = Project::create(path, QStringLiteral("rugby"));
    project->meta().extra = QJsonObject{{QStringLiteral("venue"), QStringLiteral("Twickenham")}};
    project->putStream(QStringLiteral("run1/imu"),
                       test::makeStream(QStringLiteral("imu"), test::imuColumns(), test::makeSamples(2000, 6, 11)));
    project->putStream(
        QStringLiteral("run1/lps"),
        test::makeStream(QStringLiteral("lps-position"), {{"x", "m"}, {"y", "m"}}, test::makeSamples(500, 2, 12)));
    Table beacons;
    beacons.kind = QStringLiteral("beacons");
    beacons.columns = {{QStringLiteral("id"), {}, true, {}, {QStringLiteral("B1"), QStringLiteral("Bäke 2")}},
                       {QStringLiteral("x"), QStringLiteral("m"), false, {0.0, 42.195}, {}}};
    project->putTable(QStringLiteral("run1/beacons"), beacons);
    project->ensureRecording(QStringLiteral("run1")).annotations = {
        {QStringLiteral("tackle"), 3.0, 3.5, QStringLiteral("anna"), 0.9, QStringLiteral("manual")},
        {QStringLiteral("scrum"), 8.0, 12.0, QString(), 1.0, QStringLiteral("manual")}};
    project->annotationClasses() = {QStringLiteral("tackle"), QStringLiteral("scrum")};
    return project;
}

class StoreRobustnessTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        test::quietHdf5();
        path_ = dir_.filePath(QStringLiteral("match.athlos"));
    }
    QTemporaryDir dir_;
    QString path_;
};

struct Visit {
    int variableStrings = 0;
    int datasets = 0;
    int checksummed = 0;
};

herr_t countAttribute(hid_t object, const char* name, const H5A_info_t*, void* out) {
    const hid_t attribute = H5Aopen(object, name, H5P_DEFAULT);
    const hid_t type = H5Aget_type(attribute);
    if (H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) > 0) ++static_cast<Visit*>(out)->variableStrings;
    H5Tclose(type);
    H5Aclose(attribute);
    return 0;
}

herr_t visitObject(hid_t object, const char* name, const H5O_info_t* info, void* out) {
    Visit& visit = *static_cast<Visit*>(out);
    const hid_t opened = H5Oopen(object, name, H5P_DEFAULT);
    H5Aiterate2(opened, H5_INDEX_NAME, H5_ITER_INC, nullptr, countAttribute, out);
    if (info->type == H5O_TYPE_DATASET) {
        const hid_t type = H5Dget_type(opened);
        if (H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) > 0) ++visit.variableStrings;
        H5Tclose(type);
        const hid_t space = H5Dget_space(opened);
        const bool empty = H5Sget_simple_extent_npoints(space) == 0;
        H5Sclose(space);
        if (!empty) {
            ++visit.datasets;
            const hid_t dcpl = H5Dget_create_plist(opened);
            unsigned flags = 0;
            size_t elements = 0;
            if (H5Pget_filter_by_id2(dcpl, H5Z_FILTER_FLETCHER32, &flags, &elements, nullptr, 0, nullptr, nullptr) >= 0)
                ++visit.checksummed;
            H5Pclose(dcpl);
        }
    }
    H5Oclose(opened);
    return 0;
}

Visit visitFile(const QString& path) {
    Visit visit;
    const hid_t file = H5Fopen(QFile::encodeName(path).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EXPECT_GE(file, 0);
    H5Ovisit2(file, H5_INDEX_NAME, H5_ITER_INC, visitObject, &visit, H5O_INFO_BASIC);
    H5Fclose(file);
    return visit;
}

unsigned superblockVersion(const QString& path) {
    const hid_t file = H5Fopen(QFile::encodeName(path).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
    H5F_info2_t info{};
    H5Fget_info2(file, &info);
    H5Fclose(file);
    return info.super.version;
}

TEST_F(StoreRobustnessTest, Version2HasFixedStringsChecksumsAndTheNewFileFormat) {
    ASSERT_TRUE(makeSmallProject(path_)->save().ok());
    const Visit visit = visitFile(path_);
    EXPECT_EQ(visit.variableStrings, 0);
    EXPECT_GT(visit.datasets, 6);
    EXPECT_EQ(visit.checksummed, visit.datasets);  // every non-empty dataset
    EXPECT_GE(superblockVersion(path_), 3u);       // HDF5 1.10 format: metadata checksums
    auto opened = Project::open(path_);
    ASSERT_TRUE(opened.ok()) << opened.message().toStdString();
    EXPECT_EQ((*opened)->meta().formatVersion, 2);
    const Table* beacons = (*opened)->table(QStringLiteral("run1/beacons"));
    ASSERT_TRUE(beacons);
    EXPECT_EQ(beacons->columns[0].texts, (QStringList{QStringLiteral("B1"), QStringLiteral("Bäke 2")}));
    EXPECT_EQ((*opened)->recording(QStringLiteral("run1"))->annotations,
              makeSmallProject(path_)->recording(QStringLiteral("run1"))->annotations);
    EXPECT_EQ((*opened)->meta().extra.value(QStringLiteral("venue")).toString(), QStringLiteral("Twickenham"));
}

// A large JSON attribute (a long pipeline history) still fits as a fixed-length string.
TEST_F(StoreRobustnessTest, LargeJsonAttributeRoundTrips) {
    auto project = makeSmallProject(path_);
    QJsonArray history;
    for (int i = 0; i < 3000; ++i)
        history.append(QJsonObject{{QStringLiteral("name"), QStringLiteral("step %1 with a long description").arg(i)}});
    project->pipelineHistory() = history;
    ASSERT_TRUE(project->save().ok());
    auto opened = Project::open(path_);
    ASSERT_TRUE(opened.ok()) << opened.message().toStdString();
    EXPECT_EQ((*opened)->pipelineHistory(), history);
}

// Fletcher32 covers the stored bytes of every chunk: a flipped byte inside the samples is reported
// as a checksum failure, not read as plausible numbers.
TEST_F(StoreRobustnessTest, DamagedSampleChunkIsDetectedByItsChecksum) {
    ASSERT_TRUE(makeSmallProject(path_)->save().ok());
    haddr_t address = HADDR_UNDEF;
    hsize_t size = 0;
    {
        const hid_t file = H5Fopen(QFile::encodeName(path_).constData(), H5F_ACC_RDONLY, H5P_DEFAULT);
        const hid_t data = H5Dopen2(file, "/recordings/run1/imu/data", H5P_DEFAULT);
        hsize_t offset[2] = {0, 0};
        unsigned mask = 0;
        const hid_t space = H5Dget_space(data);
        ASSERT_GE(H5Dget_chunk_info(data, space, 0, offset, &mask, &address, &size), 0);
        H5Sclose(space);
        H5Dclose(data);
        H5Fclose(file);
    }
    ASSERT_NE(address, HADDR_UNDEF);
    QByteArray bytes = fileBytes(path_);
    const qsizetype at = qsizetype(address + size / 2);
    ASSERT_LT(at, bytes.size());
    bytes[at] = char(bytes[at] ^ 0x5a);
    writeBytes(path_, bytes);
    auto opened = Project::open(path_);
    ASSERT_FALSE(opened.ok());
    EXPECT_TRUE(opened.message().contains(QStringLiteral("match.athlos"))) << opened.message().toStdString();
    EXPECT_TRUE(opened.message().contains(QStringLiteral("checksum"), Qt::CaseInsensitive))
        << opened.message().toStdString();
}

// Mutation fuzzing as a unit test: a few hundred files with 1–24 random bytes replaced. Each is
// either refused with a message naming the file or opened and fully readable; nothing crashes
// (a crash inside libhdf5 would take this test process down).
TEST_F(StoreRobustnessTest, RandomlyDamagedFilesAreRefusedOrReadNeverCrash) {
    ASSERT_TRUE(makeSmallProject(path_)->save().ok());
    const QByteArray original = fileBytes(path_);
    std::mt19937 rng(20261124);
    std::uniform_int_distribution<int> byte(0, 255), count(1, 24);
    std::uniform_int_distribution<qsizetype> where(0, original.size() - 1);
    std::uniform_int_distribution<qsizetype> header(0, std::min<qsizetype>(original.size() - 1, 4096));
    int refused = 0, opened = 0;
    for (int trial = 0; trial < 250; ++trial) {
        QByteArray bytes = original;
        const int n = count(rng);
        // Half the trials hit the first 4 KiB, where the superblock and root metadata live.
        for (int i = 0; i < n; ++i) bytes[trial % 2 ? where(rng) : header(rng)] = char(byte(rng));
        const QString mutant = dir_.filePath(QStringLiteral("mutant-%1.athlos").arg(trial));
        writeBytes(mutant, bytes);
        auto project = Project::open(mutant);
        if (!project) {
            ++refused;
            EXPECT_TRUE(project.message().contains(QStringLiteral("mutant-%1.athlos").arg(trial)))
                << project.message().toStdString();
            continue;
        }
        ++opened;
        for (const QString& path : (*project)->streamPaths()) {
            auto data = (*project)->stream(path)->data();
            if (!data) {
                EXPECT_FALSE(data.message().isEmpty());
            }
        }
    }
    EXPECT_GT(refused, 50);
    std::printf("damaged files: %d refused, %d opened\n", refused, opened);
}

// Format version 1: variable-length strings, no checksums, HDF5 1.8 format. Written here with the
// plain HDF5 API, as Athlos 0.1 did.
void writeVariableString(hid_t object, const char* name, const char* value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attribute, type, &value);
    H5Aclose(attribute);
    H5Sclose(space);
    H5Tclose(type);
}

void writeScalar(hid_t object, const char* name, hid_t fileType, hid_t memType, const void* value) {
    const hid_t space = H5Screate(H5S_SCALAR);
    const hid_t attribute = H5Acreate2(object, name, fileType, space, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(attribute, memType, value);
    H5Aclose(attribute);
    H5Sclose(space);
}

void writeDoubles(hid_t parent, const char* name, const std::vector<double>& values, int rank, const hsize_t* dims) {
    const hid_t space = H5Screate_simple(rank, dims, nullptr);
    const hid_t dataset = H5Dcreate2(parent, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(dataset);
    H5Sclose(space);
}

void writeVariableStrings(hid_t parent, const char* name, const std::vector<const char*>& values) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, H5T_VARIABLE);
    H5Tset_cset(type, H5T_CSET_UTF8);
    const hsize_t n = values.size();
    const hid_t space = H5Screate_simple(1, &n, nullptr);
    const hid_t dataset = H5Dcreate2(parent, name, type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Dwrite(dataset, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data());
    H5Dclose(dataset);
    H5Sclose(space);
    H5Tclose(type);
}

void writeVersion1Project(const QString& path) {
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_V18);
    const hid_t file = H5Fcreate(QFile::encodeName(path).constData(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl);
    H5Pclose(fapl);
    const long long version = 1;
    writeVariableString(file, "format", "athlos");
    writeScalar(file, "format_version", H5T_STD_I64LE, H5T_NATIVE_LLONG, &version);
    writeVariableString(file, "app_version", "0.1.0");
    writeVariableString(file, "sport", "athletics");
    writeVariableString(file, "extra", "{\"venue\":\"Bislett\"}");
    writeVariableString(file, "annotation_classes", "[\"stride\"]");
    H5Gclose(H5Gcreate2(file, "geometry", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    const hid_t recordings = H5Gcreate2(file, "recordings", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const hid_t rec = H5Gcreate2(recordings, "run1", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    writeVariableString(rec, "metadata", "{\"athlete\":\"Zoë\"}");
    const hid_t stream = H5Gcreate2(rec, "imu", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    writeVariableString(stream, "type", "stream");
    writeVariableString(stream, "kind", "imu");
    writeVariableString(stream, "frame", "sensor");
    writeVariableString(stream, "columns",
                        "[{\"name\":\"acc_x\",\"unit\":\"m/s^2\"},{\"name\":\"acc_y\",\"unit\":\"m/s^2\"}]");
    writeVariableString(stream, "attributes", "{}");
    writeVariableString(stream, "provenance", "{}");
    const long long rows = 4;
    const double tBegin = 0.0, tEnd = 0.03;
    writeScalar(stream, "rows", H5T_STD_I64LE, H5T_NATIVE_LLONG, &rows);
    writeScalar(stream, "t_begin", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &tBegin);
    writeScalar(stream, "t_end", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &tEnd);
    writeVariableString(stream, "content_hash", "");
    const hsize_t tDims[1] = {4}, dDims[2] = {4, 2};
    writeDoubles(stream, "t", {0.0, 0.01, 0.02, 0.03}, 1, tDims);
    writeDoubles(stream, "data", {1, 2, 3, 4, 5, 6, 7, 8}, 2, dDims);
    const hid_t annotations = H5Gcreate2(file, "annotations", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const hid_t run = H5Gcreate2(annotations, "run1", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const hsize_t one[1] = {1};
    writeVariableStrings(run, "label", {"stride"});
    writeVariableStrings(run, "annotator", {"anna"});
    writeVariableStrings(run, "source", {"manual"});
    writeDoubles(run, "t_start", {0.01}, 1, one);
    writeDoubles(run, "t_end", {0.02}, 1, one);
    writeDoubles(run, "confidence", {1.0}, 1, one);
    for (hid_t group : {run, annotations, stream, rec, recordings}) H5Gclose(group);
    H5Fclose(file);
}

TEST_F(StoreRobustnessTest, Version1ProjectIsReadAndUpgradedBySaving) {
    writeVersion1Project(path_);
    ASSERT_GT(visitFile(path_).variableStrings, 0);
    {
        auto opened = Project::open(path_);
        ASSERT_TRUE(opened.ok()) << opened.message().toStdString();
        Project& project = **opened;
        EXPECT_EQ(project.meta().formatVersion, 1);
        EXPECT_EQ(project.meta().extra.value(QStringLiteral("venue")).toString(), QStringLiteral("Bislett"));
        EXPECT_EQ(project.recording(QStringLiteral("run1"))->metadata.value(QStringLiteral("athlete")).toString(),
                  QStringLiteral("Zoë"));
        ASSERT_EQ(project.recording(QStringLiteral("run1"))->annotations.size(), 1u);
        EXPECT_EQ(project.recording(QStringLiteral("run1"))->annotations[0].annotator, QStringLiteral("anna"));
        ASSERT_TRUE(project.save().ok());
        EXPECT_EQ(project.meta().formatVersion, 2);
    }
    const Visit visit = visitFile(path_);
    EXPECT_EQ(visit.variableStrings, 0);
    EXPECT_EQ(visit.checksummed, visit.datasets);  // the v1 samples were rewritten, not copied
    auto reopened = Project::open(path_);
    ASSERT_TRUE(reopened.ok()) << reopened.message().toStdString();
    EXPECT_EQ((*reopened)->meta().formatVersion, 2);
    auto data = (*reopened)->stream(QStringLiteral("run1/imu"))->data();
    ASSERT_TRUE(data.ok());
    EXPECT_EQ((*data)->values, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ((*reopened)->recording(QStringLiteral("run1"))->annotations[0].label, QStringLiteral("stride"));
}

// The crash of issue #11: variable-length strings of a version-1 file live in a global heap
// collection ("GCOL"); damaged heap object sizes made libhdf5 crash in H5HG_read. Every mutation of
// the collection's objects is refused (or read), never a crash.
TEST_F(StoreRobustnessTest, DamagedGlobalHeapOfAVersion1FileIsRefusedNotACrash) {
    writeVersion1Project(path_);
    const QByteArray original = fileBytes(path_);
    const qsizetype heap = original.indexOf("GCOL");
    ASSERT_GE(heap, 0);
    std::mt19937 rng(18);
    std::uniform_int_distribution<int> byte(0, 255);
    int refused = 0;
    for (int trial = 0; trial < 60; ++trial) {
        QByteArray bytes = original;
        // Collection header (16 bytes), then objects: index, reference count, size (8 bytes), data.
        for (int i = 0; i < 18; ++i) {
            const qsizetype at = heap + 8 + (trial * 7 + i * 5) % 256;
            if (at < bytes.size()) bytes[at] = char(byte(rng));
        }
        const QString mutant = dir_.filePath(QStringLiteral("heap-%1.athlos").arg(trial));
        writeBytes(mutant, bytes);
        auto project = Project::open(mutant);
        if (!project) {
            ++refused;
            EXPECT_TRUE(project.message().contains(QStringLiteral("heap-%1.athlos").arg(trial)))
                << project.message().toStdString();
        }
    }
    EXPECT_GT(refused, 10);
}

}  // namespace
}  // namespace athlos
