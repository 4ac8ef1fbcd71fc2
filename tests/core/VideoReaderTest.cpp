// Frame-accurate access to videos written here with a frame-index pattern (FrameCodePattern):
// random seeks forwards and backwards must return exactly the requested frame, for an intra-only
// codec (MJPG) and for inter-coded, long-GOP ones (MPEG-4 Part 2, H.264 with B-frames).
#include "core/video/FrameCodePattern.h"
#include "core/video/VideoReader.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <gtest/gtest.h>

#include <random>

using namespace athlos;

namespace {

struct Codec {
    const char* fourcc;
    const char* extension;
};

class VideoReaderCodecTest : public ::testing::TestWithParam<Codec> {};

TEST_P(VideoReaderCodecTest, RandomSeeksReturnTheExactFrame) {
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("pattern") + QLatin1String(GetParam().extension));
    FrameCodeVideo spec;
    spec.fourcc = QLatin1String(GetParam().fourcc);
    spec.frames = 300;
    spec.fps = 30;
    if (Status s = writeFrameCodeVideo(path, spec); !s) GTEST_SKIP() << qPrintable(s.message());

    auto reader = VideoReader::open(path);
    ASSERT_TRUE(reader) << qPrintable(reader.message());
    VideoReader& r = **reader;
    EXPECT_EQ(r.info().frames, spec.frames);
    EXPECT_DOUBLE_EQ(r.info().fps, spec.fps);
    EXPECT_EQ(r.info().width, spec.width);
    EXPECT_EQ(r.info().height, spec.height);
    EXPECT_NEAR(r.info().duration(), 10.0, 1e-9);
    EXPECT_FALSE(r.info().codec.isEmpty());

    std::mt19937 rng(7);
    std::uniform_int_distribution<long long> any(0, spec.frames - 1);
    std::vector<long long> targets = {0, spec.frames - 1, 150, 149, 151, 13, 12, 11, 299, 0, 1};
    for (int k = 0; k < 60; ++k) targets.push_back(any(rng));
    // The last frames come out of the decoder's flush without timestamps: reachable by a seek too.
    for (long long k : {spec.frames - 2, 200LL, spec.frames - 1, 100LL, spec.frames - 3}) targets.push_back(k);
    for (long long target : targets) {
        const long long seeks = r.seekCount();
        auto frame = r.frameAt(target);
        ASSERT_TRUE(frame) << qPrintable(frame.message());
        EXPECT_EQ(frame->index, target);
        EXPECT_EQ(decodeFrameCode(*frame), target) << GetParam().fourcc << " seek to " << target;
        // One seek, at most one retry from further back: never a decode from the beginning.
        EXPECT_LE(r.seekCount() - seeks, 2) << GetParam().fourcc << " seek to " << target;
    }
    // By time: the frame whose interval [i/fps, (i+1)/fps) holds t.
    for (double t : {0.0, 1.0 / 30 - 1e-4, 1.0 / 30, 5.51, 9.99}) {
        auto frame = r.frameAtTime(t);
        ASSERT_TRUE(frame) << qPrintable(frame.message());
        EXPECT_EQ(decodeFrameCode(*frame), r.indexAtTime(t)) << "t=" << t;
    }
    EXPECT_FALSE(r.frameAtTime(10.0));
    EXPECT_FALSE(r.frameAtTime(-0.01));
    EXPECT_FALSE(r.frameAt(spec.frames));
}

TEST_P(VideoReaderCodecTest, SequentialReadingDoesNotSeek) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("seq") + QLatin1String(GetParam().extension));
    FrameCodeVideo spec;
    spec.fourcc = QLatin1String(GetParam().fourcc);
    spec.frames = 120;
    if (Status s = writeFrameCodeVideo(path, spec); !s) GTEST_SKIP() << qPrintable(s.message());
    auto reader = VideoReader::open(path);
    ASSERT_TRUE(reader) << qPrintable(reader.message());
    auto first = (*reader)->frameAt(40);  // one seek
    ASSERT_TRUE(first);
    const long long seeks = (*reader)->seekCount();
    // Playback at 1× and at 4× (every 4th frame) decodes on without seeking.
    for (long long i = 41; i < 80; ++i) {
        auto frame = (*reader)->frameAt(i);
        ASSERT_TRUE(frame);
        EXPECT_EQ(decodeFrameCode(*frame), i);
    }
    for (long long i = 80; i < 120; i += 4) {
        auto frame = (*reader)->frameAt(i);
        ASSERT_TRUE(frame);
        EXPECT_EQ(decodeFrameCode(*frame), i);
    }
    EXPECT_EQ((*reader)->seekCount(), seeks);
}

INSTANTIATE_TEST_SUITE_P(Codecs, VideoReaderCodecTest,
                         ::testing::Values(Codec{"MJPG", ".avi"}, Codec{"mp4v", ".mp4"}, Codec{"avc1", ".mp4"},
                                           Codec{"FFV1", ".avi"}),
                         [](const auto& info) { return std::string(info.param.fourcc); });

TEST(VideoReaderTest, MissingFileNamesTheFile) {
    auto reader = VideoReader::open(QStringLiteral("/nonexistent/clip.mp4"));
    ASSERT_FALSE(reader);
    EXPECT_TRUE(reader.message().contains(QLatin1String("/nonexistent/clip.mp4"))) << qPrintable(reader.message());
    EXPECT_TRUE(reader.message().contains(QLatin1String("does not exist")));
}

TEST(VideoReaderTest, GarbageIsNotAVideo) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("garbage.mp4"));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(QByteArray(20000, 'x'));
    f.close();
    auto reader = VideoReader::open(path);
    ASSERT_FALSE(reader);
    EXPECT_TRUE(reader.message().contains(QLatin1String("garbage.mp4"))) << qPrintable(reader.message());
    EXPECT_TRUE(reader.message().contains(QLatin1String("not a video"))) << qPrintable(reader.message());
}

TEST(VideoReaderTest, UnknownCodecIsNamed) {
    // An AVI whose video FourCC no FFmpeg decoder knows: the MJPG tags patched to "ZZZZ".
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("odd.avi"));
    FrameCodeVideo spec;
    spec.frames = 10;
    ASSERT_TRUE(writeFrameCodeVideo(path, spec));
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::ReadOnly));
    QByteArray bytes = f.readAll();
    f.close();
    const qsizetype header = bytes.indexOf("movi");
    ASSERT_GT(header, 0);
    QByteArray head = bytes.left(header);
    ASSERT_GT(head.count("MJPG"), 0);
    head.replace("MJPG", "ZZZZ");
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(head + bytes.mid(header));
    f.close();
    auto reader = VideoReader::open(path);
    ASSERT_FALSE(reader);
    EXPECT_TRUE(reader.message().contains(QLatin1String("odd.avi"))) << qPrintable(reader.message());
    EXPECT_TRUE(reader.message().contains(QLatin1String("ZZZZ"))) << qPrintable(reader.message());
    EXPECT_TRUE(reader.message().contains(QLatin1String("no decoder"))) << qPrintable(reader.message());
}

TEST(VideoReaderTest, FpsOverrideScalesTimeNotFrames) {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("slow.avi"));
    FrameCodeVideo spec;
    spec.frames = 60;
    spec.fps = 30;
    ASSERT_TRUE(writeFrameCodeVideo(path, spec));
    VideoReader::Params params;
    params.fpsOverride = 120;  // a 120 fps capture stored as 30 fps
    auto reader = VideoReader::open(path, params);
    ASSERT_TRUE(reader) << qPrintable(reader.message());
    EXPECT_DOUBLE_EQ((*reader)->info().fps, 120);
    EXPECT_NEAR((*reader)->info().duration(), 0.5, 1e-12);
    auto frame = (*reader)->frameAtTime(0.25);  // frame 30 at 120 fps
    ASSERT_TRUE(frame);
    EXPECT_EQ(decodeFrameCode(*frame), 30);
    auto back = (*reader)->frameAt(3);
    ASSERT_TRUE(back);
    EXPECT_EQ(decodeFrameCode(*back), 3);
}

}  // namespace
