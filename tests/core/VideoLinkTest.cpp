// A recording's video link: offset from an event pair, relative path, survives save/reopen,
// and a moved video gives a clear message while the link stays.
#include "core/model/Project.h"
#include "core/video/FrameCodePattern.h"
#include "core/video/VideoLink.h"
#include "core/video/VideoReader.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;

namespace {

TEST(VideoLinkTest, OffsetFromAnEventPairMapsBothWays) {
    // A clap at 3.2 s in the video appears as an acceleration spike at 15.7 s in the recording.
    const double offset = VideoLink::offsetFromEvent(3.2, 15.7);
    EXPECT_NEAR(offset, 12.5, 1e-12);
    VideoLink link;
    link.offset = offset;
    EXPECT_NEAR(link.recordingTime(3.2), 15.7, 1e-12);
    EXPECT_NEAR(link.videoTime(15.7), 3.2, 1e-12);
    // The video started before the recording: negative offset.
    EXPECT_NEAR(VideoLink::offsetFromEvent(10.0, 4.0), -6.0, 1e-12);
}

TEST(VideoLinkTest, AttachStoresRelativePathAndSurvivesSaveAndReopen) {
    QTemporaryDir dir;
    ASSERT_TRUE(QDir(dir.path()).mkpath(QStringLiteral("clips")));
    const QString video = dir.filePath(QStringLiteral("clips/run.avi"));
    FrameCodeVideo spec;
    spec.frames = 50;
    ASSERT_TRUE(writeFrameCodeVideo(video, spec));
    const QString projectPath = dir.filePath(QStringLiteral("p.athlos"));
    auto project = Project::create(projectPath);
    project->ensureRecording(QStringLiteral("rec")).metadata[QStringLiteral("athlete")] = QStringLiteral("A");

    auto link = VideoLink::attach(*project, QStringLiteral("rec"), video, 1.25);
    ASSERT_TRUE(link) << qPrintable(link.message());
    EXPECT_EQ(link->storedPath, QStringLiteral("clips/run.avi"));
    EXPECT_TRUE(project->isModified());
    ASSERT_TRUE(VideoLink::setOffset(*project, QStringLiteral("rec"), -2.375));
    ASSERT_TRUE(project->save());

    // Move project and clips together: the relative path still resolves.
    QTemporaryDir moved;
    ASSERT_TRUE(QDir(moved.path()).mkpath(QStringLiteral("clips")));
    ASSERT_TRUE(QFile::rename(projectPath, moved.filePath(QStringLiteral("p.athlos"))));
    ASSERT_TRUE(QFile::rename(video, moved.filePath(QStringLiteral("clips/run.avi"))));
    auto reopened = Project::open(moved.filePath(QStringLiteral("p.athlos")));
    ASSERT_TRUE(reopened) << qPrintable(reopened.message());
    const auto stored = VideoLink::of(**reopened, QStringLiteral("rec"));
    ASSERT_TRUE(stored.has_value());
    EXPECT_DOUBLE_EQ(stored->offset, -2.375);
    EXPECT_EQ(stored->storedPath, QStringLiteral("clips/run.avi"));
    EXPECT_EQ((*reopened)->recording(QStringLiteral("rec"))->metadata.value(QStringLiteral("athlete")).toString(),
              QStringLiteral("A"));
    EXPECT_EQ(VideoLink::firstLinkedRecording(**reopened), QStringLiteral("rec"));
    auto resolved = VideoLink::resolve(**reopened, QStringLiteral("rec"));
    ASSERT_TRUE(resolved) << qPrintable(resolved.message());
    EXPECT_EQ(QFileInfo(*resolved).canonicalFilePath(),
              QFileInfo(moved.filePath(QStringLiteral("clips/run.avi"))).canonicalFilePath());
    EXPECT_TRUE(VideoReader::open(*resolved));

    // The video disappears: a clear message naming the file; the link stays.
    ASSERT_TRUE(QFile::remove(moved.filePath(QStringLiteral("clips/run.avi"))));
    auto missing = VideoLink::resolve(**reopened, QStringLiteral("rec"));
    ASSERT_FALSE(missing);
    EXPECT_TRUE(missing.message().contains(QLatin1String("run.avi"))) << qPrintable(missing.message());
    EXPECT_TRUE(missing.message().contains(QLatin1String("missing"))) << qPrintable(missing.message());
    EXPECT_TRUE(VideoLink::of(**reopened, QStringLiteral("rec")).has_value());

    EXPECT_TRUE(VideoLink::detach(**reopened, QStringLiteral("rec")));
    EXPECT_FALSE(VideoLink::of(**reopened, QStringLiteral("rec")).has_value());
    EXPECT_FALSE(VideoLink::detach(**reopened, QStringLiteral("rec")));
}

TEST(VideoLinkTest, ProjectMovedAloneFallsBackToAbsolutePath) {
    QTemporaryDir dir, other;
    const QString video = dir.filePath(QStringLiteral("v.avi"));
    FrameCodeVideo spec;
    spec.frames = 10;
    ASSERT_TRUE(writeFrameCodeVideo(video, spec));
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    project->ensureRecording(QStringLiteral("rec"));
    ASSERT_TRUE(VideoLink::attach(*project, QStringLiteral("rec"), video));
    ASSERT_TRUE(project->saveAs(other.filePath(QStringLiteral("p.athlos"))));
    auto resolved = VideoLink::resolve(*project, QStringLiteral("rec"));
    ASSERT_TRUE(resolved) << qPrintable(resolved.message());
    EXPECT_EQ(*resolved, QFileInfo(video).absoluteFilePath());
}

TEST(VideoLinkTest, AttachRefusesBadInput) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    project->ensureRecording(QStringLiteral("rec"));
    project->setModified(false);
    auto noRecording = VideoLink::attach(*project, QStringLiteral("nope"), dir.filePath(QStringLiteral("x.avi")));
    ASSERT_FALSE(noRecording);
    EXPECT_TRUE(noRecording.message().contains(QLatin1String("nope")));
    auto missing = VideoLink::attach(*project, QStringLiteral("rec"), dir.filePath(QStringLiteral("x.avi")));
    ASSERT_FALSE(missing);
    EXPECT_TRUE(missing.message().contains(QLatin1String("x.avi")));
    EXPECT_FALSE(VideoLink::of(*project, QStringLiteral("rec")).has_value());
    EXPECT_FALSE(project->isModified());
    EXPECT_FALSE(VideoLink::setOffset(*project, QStringLiteral("rec"), 1.0));
}

}  // namespace
