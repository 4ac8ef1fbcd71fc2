// Video dock: the frame on screen is the one at cursor − offset (read back from the picture's
// frame-index pattern, not from the dock's bookkeeping), the placeholder outside the video, frame
// steps, the two-mark synchronisation with undo, and the screenshot view.
#include "GuiTestSupport.h"

#include "core/video/FrameCodePattern.h"
#include "core/video/VideoLink.h"
#include "ui/MainWindow.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/views/VideoDock.h"

#include <QDoubleSpinBox>
#include <QLabel>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>
#include <cmath>

using namespace athlos;
using namespace athlos::ui;

namespace {

// The index carried by the picture the dock shows.
long long indexOnScreen(const VideoDock& dock) {
    const QImage image = dock.shownImage().convertToFormat(QImage::Format_RGB888);
    if (image.isNull()) return -1;
    return decodeFrameCode(image.constBits(), image.width(), image.height(), 3, int(image.bytesPerLine()));
}

}  // namespace

class ViewsVideoDockTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.filePath(QStringLiteral("settings")));
        // 25 fps, 8 s, inter-coded (mp4v, GOP 12) when available, else MJPG.
        FrameCodeVideo spec;
        spec.fps = 25;
        spec.frames = 200;
        spec.fourcc = QStringLiteral("mp4v");
        video_ = dir_.filePath(QStringLiteral("clip.mp4"));
        if (!writeFrameCodeVideo(video_, spec)) {
            spec.fourcc = QStringLiteral("MJPG");
            video_ = dir_.filePath(QStringLiteral("clip.avi"));
            QVERIFY(writeFrameCodeVideo(video_, spec));
        }
    }

    void frameFollowsCursorAndOffset() {
        MainWindow window;
        window.setInteractive(false);
        window.resize(1280, 800);
        window.show();
        auto project = testing::makeProject(dir_.filePath(QStringLiteral("v.athlos")));
        QVERIFY(VideoLink::attach(*project, QStringLiteral("run1"), video_, 2.0));
        window.setProject(std::move(project));
        QVERIFY(window.selectItem(QStringLiteral("run1/imu")));  // cursor range 0 … 19.99 s
        window.waitForPlots();
        TimeController* time = window.timeController();

        auto* dock = new VideoDock(window);
        window.addDock(dock, Qt::RightDockWidgetArea);
        QCOMPARE(dock->recording(), QStringLiteral("run1"));
        QVERIFY(dock->hasVideo());
        QCOMPARE(dock->offset(), 2.0);

        // Cursor t shows frame floor((t − offset) · 25).
        for (double t : {2.0, 2.039, 2.04, 5.5, 3.0, 9.96, 2.5, 7.123}) {
            time->setCursor(t);
            QVERIFY(dock->waitForFrame());
            const long long expected = static_cast<long long>(std::floor((t - 2.0) * 25 + 1e-6));
            QCOMPARE(dock->wantedFrame(), expected);
            QCOMPARE(dock->shownFrame(), expected);
            QCOMPARE(indexOnScreen(*dock), expected);
            QVERIFY(dock->positionLabel()->text().contains(QString::number(expected)));
        }
        // Before the video starts and after it ends: a placeholder naming the covered span.
        for (double t : {1.99, 10.0, 15.0}) {
            time->setCursor(t);
            QVERIFY(dock->waitForFrame());
            QCOMPARE(dock->shownFrame(), -1LL);
            QVERIFY(dock->shownImage().isNull());
            QVERIFY2(dock->placeholderText().contains(QLatin1String("2.000")), qPrintable(dock->placeholderText()));
        }

        // A different offset: the same cursor shows another frame.
        time->setCursor(6.0);
        dock->setOffset(-1.5);
        QVERIFY(dock->waitForFrame());
        QCOMPARE(indexOnScreen(*dock), 187LL);  // (6.0 + 1.5) · 25
        QCOMPARE(VideoLink::of(*window.project(), QStringLiteral("run1"))->offset, -1.5);
        QVERIFY(window.project()->isModified());
        QCOMPARE(dock->offsetBox()->value(), -1.5);
        dock->undoStack()->undo();
        QVERIFY(dock->waitForFrame());
        QCOMPARE(dock->offset(), 2.0);
        QCOMPARE(indexOnScreen(*dock), 100LL);  // (6.0 − 2.0) · 25

        // Frame steps move the cursor by exactly one video frame.
        dock->stepFrame(+1);
        QVERIFY(dock->waitForFrame());
        QCOMPARE(indexOnScreen(*dock), 101LL);
        dock->stepFrame(-3);
        QVERIFY(dock->waitForFrame());
        QCOMPARE(indexOnScreen(*dock), 98LL);

        // Playback at 0.25×, 1× and 4×: each frame on screen matches the cursor, and the decoder
        // reads on without seeking.
        time->setCursor(2.5);
        QVERIFY(dock->waitForFrame());
        const long long seeks = dock->decoderSeeks();
        time->setManualClock(true);  // only advance() moves the cursor: each frame's instant is known
        for (double speed : {0.25, 1.0, 4.0}) {
            time->setSpeed(speed);
            time->setPlaying(true);
            for (int tick = 0; tick < 12; ++tick) {
                time->advance(1.0 / 60.0);  // one display refresh of wall-clock time
                QVERIFY(dock->waitForFrame());
                const long long expected = static_cast<long long>(std::floor((time->cursor() - 2.0) * 25 + 1e-6));
                QCOMPARE(indexOnScreen(*dock), expected);
            }
            time->setPlaying(false);
        }
        QCOMPARE(dock->decoderSeeks(), seeks);

        // Scrubbing: many requests, only the newest matters.
        for (int k = 0; k < 60; ++k) time->setCursor(2.0 + 0.13 * k);
        QVERIFY(dock->waitForFrame());
        QCOMPARE(indexOnScreen(*dock), static_cast<long long>(std::floor(0.13 * 59 * 25 + 1e-6)));
    }

    void markingAnEventPairSetsTheOffset() {
        MainWindow window;
        window.setInteractive(false);
        window.resize(1280, 800);
        window.show();
        auto project = testing::makeProject(dir_.filePath(QStringLiteral("sync.athlos")));
        QVERIFY(VideoLink::attach(*project, QStringLiteral("run1"), video_, 0.0));
        window.setProject(std::move(project));
        QVERIFY(window.selectItem(QStringLiteral("run1/imu")));
        window.waitForPlots();
        TimeController* time = window.timeController();
        auto* dock = new VideoDock(window);
        window.addDock(dock);

        // The clap is in video frame 80 (3.2 s); the spike in the signal is at 11.7 s.
        time->setCursor(3.2);
        QVERIFY(dock->waitForFrame());
        QCOMPARE(indexOnScreen(*dock), 80LL);
        dock->markVideoEvent();
        time->setCursor(11.7);
        dock->markSignalEvent();
        QVERIFY(std::abs(dock->offset() - 8.5) < 1e-9);
        QVERIFY(std::abs(VideoLink::of(*window.project(), QStringLiteral("run1"))->offset - 8.5) < 1e-9);
        // The video now shows the clap frame at the spike.
        QVERIFY(dock->waitForFrame());
        QCOMPARE(indexOnScreen(*dock), 80LL);
        dock->undoStack()->undo();
        QCOMPARE(dock->offset(), 0.0);
        dock->undoStack()->redo();
        QVERIFY(std::abs(dock->offset() - 8.5) < 1e-9);

        // Saved with the project and read back.
        QVERIFY(window.saveProject());
        auto reopened = Project::open(dir_.filePath(QStringLiteral("sync.athlos")));
        QVERIFY(reopened);
        QVERIFY(std::abs(VideoLink::of(**reopened, QStringLiteral("run1"))->offset - 8.5) < 1e-9);
    }

    void missingVideoShowsAMessage() {
        MainWindow window;
        window.setInteractive(false);
        auto project = testing::makeProject(dir_.filePath(QStringLiteral("gone.athlos")));
        const QString copy = dir_.filePath(QStringLiteral("copy.avi"));
        FrameCodeVideo spec;
        spec.frames = 10;
        QVERIFY(writeFrameCodeVideo(copy, spec));
        QVERIFY(VideoLink::attach(*project, QStringLiteral("run1"), copy));
        QVERIFY(QFile::remove(copy));
        window.setProject(std::move(project));
        VideoDock dock(window);
        QVERIFY(!dock.hasVideo());
        QVERIFY2(dock.placeholderText().contains(QLatin1String("copy.avi")), qPrintable(dock.placeholderText()));
        QVERIFY(VideoLink::of(*window.project(), QStringLiteral("run1")).has_value());
    }

    void toolAndScreenshotViewAreRegistered() {
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) {
            return t.id == QLatin1String("video") && QLatin1String(t.menu) == QLatin1String("View");
        }));
        const auto& views = registeredViews();
        auto it = std::find_if(views.begin(), views.end(),
                               [](const ViewEntry& v) { return v.name == QLatin1String("video"); });
        QVERIFY(it != views.end());

        MainWindow window;
        window.setInteractive(false);
        window.resize(1280, 800);
        window.show();
        auto project = testing::makeProject(dir_.filePath(QStringLiteral("shot.athlos")));
        Project* raw = project.get();
        window.setProject(std::move(project));
        QVERIFY(!it->prepare(window).ok());  // no video yet
        QVERIFY(VideoLink::attach(*raw, QStringLiteral("run1"), video_, 1.0));
        const Status status = it->prepare(window);
        QVERIFY2(status.ok(), status.ok() ? "" : qPrintable(status.message()));
        auto* dock = window.findChild<VideoDock*>();
        QVERIFY(dock);
        QVERIFY(dock->shownFrame() >= 0);
        QCOMPARE(indexOnScreen(*dock), dock->shownFrame());
    }

private:
    QTemporaryDir dir_;
    QString video_;
};

QTEST_MAIN(ViewsVideoDockTest)
#include "ViewsVideoDockTest.moc"
