// One writer per project; stale saves of a killed process are recovered or removed with a note.
#include "core/store/ProjectLock.h"
#include "tests/core/StoreTestData.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

namespace athlos {
namespace {

class ProjectLockTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        test::quietHdf5();
        path_ = dir_.filePath(QStringLiteral("team.athlos"));
        auto project = Project::create(path_, QStringLiteral("football"));
        project->putStream(
            QStringLiteral("match/p1"),
            test::makeStream(QStringLiteral("lps-position"), {{"x", "m"}, {"y", "m"}}, test::makeSamples(300, 2, 5)));
        ASSERT_TRUE(project->save().ok());
    }
    QTemporaryDir dir_;
    QString path_;
};

TEST_F(ProjectLockTest, SecondWriterIsRefusedWithAMessage) {
    auto first = Project::openForChange(path_);
    ASSERT_TRUE(first.ok()) << first.message().toStdString();
    EXPECT_TRUE((*first)->holdsLock());
    const QByteArray before = test::fileBytes(path_);

    auto second = Project::openForChange(path_);
    ASSERT_FALSE(second.ok());
    EXPECT_TRUE(second.message().contains(QStringLiteral("team.athlos"))) << second.message().toStdString();
    EXPECT_TRUE(second.message().contains(QStringLiteral("another Athlos process"))) << second.message().toStdString();

    // A reader may still open it, but its save is refused: it would overwrite the writer's work.
    auto reader = Project::open(path_);
    ASSERT_TRUE(reader.ok());
    (*reader)->meta().sport = QStringLiteral("rugby");
    const Status saved = (*reader)->save();
    ASSERT_FALSE(saved.ok());
    EXPECT_TRUE(saved.message().contains(QStringLiteral("another Athlos process"))) << saved.message().toStdString();
    EXPECT_EQ(test::fileBytes(path_), before);

    // The holder saves as usual; once it is gone the next writer gets the lock.
    (*first)->meta().sport = QStringLiteral("futsal");
    ASSERT_TRUE((*first)->save().ok());
    first = makeError(QStringLiteral("released"));
    auto third = Project::openForChange(path_);
    ASSERT_TRUE(third.ok()) << third.message().toStdString();
    EXPECT_EQ((*third)->meta().sport, QStringLiteral("futsal"));
}

TEST_F(ProjectLockTest, SaveAsMovesTheLockToTheNewFile) {
    auto project = Project::openForChange(path_);
    ASSERT_TRUE(project.ok());
    const QString copy = dir_.filePath(QStringLiteral("copy.athlos"));
    ASSERT_TRUE((*project)->saveAs(copy).ok());
    EXPECT_TRUE((*project)->holdsLock());
    EXPECT_FALSE(Project::openForChange(copy).ok());
    EXPECT_TRUE(Project::openForChange(path_).ok());
}

TEST_F(ProjectLockTest, UnfinishedSaveIsRemovedWithANote) {
    const QString tmp = dir_.filePath(QStringLiteral(".team.athlos.tmp-00000000deadbeef"));
    ASSERT_TRUE(test::writeBytes(tmp, test::fileBytes(path_).left(2000)));  // killed half-way
    const QByteArray before = test::fileBytes(path_);
    auto project = Project::openForChange(path_);
    ASSERT_TRUE(project.ok()) << project.message().toStdString();
    ASSERT_EQ((*project)->notes().size(), 1);
    EXPECT_TRUE((*project)->notes()[0].contains(QStringLiteral("removed"))) << (*project)->notes()[0].toStdString();
    EXPECT_FALSE(QFileInfo::exists(tmp));
    EXPECT_EQ(test::fileBytes(path_), before);
}

TEST_F(ProjectLockTest, CompleteUnrenamedSaveIsKeptAsARecoveredCopy) {
    auto changed = Project::open(path_);
    ASSERT_TRUE(changed.ok());
    (*changed)->meta().sport = QStringLiteral("hockey");
    const QString tmp = dir_.filePath(QStringLiteral(".team.athlos.tmp-0000000012345678"));
    ASSERT_TRUE((*changed)->saveAs(tmp).ok());  // a save killed between fsync and rename
    changed = makeError(QStringLiteral("gone"));
    auto project = Project::openForChange(path_);
    ASSERT_TRUE(project.ok());
    ASSERT_EQ((*project)->notes().size(), 1);
    EXPECT_TRUE((*project)->notes()[0].contains(QStringLiteral("kept as"))) << (*project)->notes()[0].toStdString();
    EXPECT_FALSE(QFileInfo::exists(tmp));
    const QStringList recovered = QDir(dir_.path()).entryList({QStringLiteral("team.recovered-*.athlos")});
    ASSERT_EQ(recovered.size(), 1);
    auto copy = Project::open(dir_.filePath(recovered[0]));
    ASSERT_TRUE(copy.ok());
    EXPECT_EQ((*copy)->meta().sport, QStringLiteral("hockey"));
    EXPECT_EQ((*project)->meta().sport, QStringLiteral("football"));
}

TEST_F(ProjectLockTest, ReadersLeaveStaleSavesAlone) {
    const QString tmp = dir_.filePath(QStringLiteral(".team.athlos.tmp-00000000cafef00d"));
    ASSERT_TRUE(test::writeBytes(tmp, QByteArray("partial")));
    EXPECT_TRUE(Project::open(path_).ok());
    EXPECT_TRUE(QFileInfo::exists(tmp));
    EXPECT_EQ(ProjectLock::staleSavesOf(path_), QStringList{tmp});
}

}  // namespace
}  // namespace athlos
