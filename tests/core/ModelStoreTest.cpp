// Trained models in the project file (/models/<name>): saved, reopened and copied unchanged; a
// model whose stored size exceeds TrainedModel::kMaxDefinitionBytes is refused at open.
#include "core/model/Project.h"
#include "core/store/ProjectFile.h"

#include <hdf5.h>

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;

namespace {
TrainedModel sampleModel() {
    TrainedModel m;
    m.name = QStringLiteral("wrist");
    m.format = QStringLiteral("opencv-yaml");
    m.definition = QByteArray("%YAML:1.0\n---\nclassifier:\n   kind: \"random-forest\"\n") + QByteArray(100000, 'x');
    m.description = QJsonObject{{QStringLiteral("classes"), QJsonArray{QStringLiteral("run"), QStringLiteral("walk")}},
                                {QStringLiteral("window"), 3.0}};
    return m;
}
}  // namespace

TEST(ModelStoreTest, ModelsSurviveSaveReopenAndCopy) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.athlos"));
    auto project = Project::create(path);
    project->models()[QStringLiteral("wrist")] = sampleModel();
    ASSERT_TRUE(project->save().ok());
    auto opened = Project::open(path);
    ASSERT_TRUE(opened.ok()) << qPrintable(opened.message());
    ASSERT_EQ((*opened)->models().size(), 1u);
    EXPECT_EQ(*(*opened)->model(QStringLiteral("wrist")), sampleModel());
    EXPECT_EQ((*opened)->model(QStringLiteral("other")), nullptr);
    const QString copy = dir.filePath(QStringLiteral("copy.athlos"));
    ASSERT_TRUE((*opened)->saveAs(copy).ok());
    auto copied = Project::open(copy);
    ASSERT_TRUE(copied.ok());
    EXPECT_EQ(*(*copied)->model(QStringLiteral("wrist")), sampleModel());
}

TEST(ModelStoreTest, OversizedModelIsRefusedBeforeAllocation) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("p.athlos"));
    auto project = Project::create(path);
    project->models()[QStringLiteral("wrist")] = sampleModel();
    ASSERT_TRUE(project->save().ok());
    project.reset();
    {
        // Replace the definition by a text dataset that claims more than the limit (never written,
        // so the file stays small).
        const QByteArray file = QFile::encodeName(path);
        const hid_t f = H5Fopen(file.constData(), H5F_ACC_RDWR, H5P_DEFAULT);
        ASSERT_GE(f, 0);
        ASSERT_GE(H5Ldelete(f, "/models/wrist/definition", H5P_DEFAULT), 0);
        const hid_t type = H5Tcopy(H5T_C_S1);
        H5Tset_size(type, std::size_t(TrainedModel::kMaxDefinitionBytes) + 1);
        const hid_t space = H5Screate(H5S_SCALAR);
        const hid_t dataset =
            H5Dcreate2(f, "/models/wrist/definition", type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        ASSERT_GE(dataset, 0);
        H5Dclose(dataset);
        H5Sclose(space);
        H5Tclose(type);
        H5Fclose(f);
    }
    EXPECT_LT(QFileInfo(path).size(), 10'000'000);
    auto opened = Project::open(path);
    ASSERT_FALSE(opened.ok());
    EXPECT_TRUE(
        opened.message().contains(QStringLiteral("/models/wrist/definition holds 268435457 bytes, more than "
                                                 "the limit of 268435456 bytes")))
        << qPrintable(opened.message());
}
