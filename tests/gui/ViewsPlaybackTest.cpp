// Team playback view: athletes follow the window's time cursor (their dots are where the data puts
// them at the cursor time, through the view's world → screen transform), the trail covers exactly
// the chosen seconds, trails are coloured by speed, the venue choice persists in the recording's
// metadata, and the screenshot views `playback` and `trajectory` draw the team on its venue.
#include "GuiTestSupport.h"

#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/UiEntry.h"
#include "ui/views/PlaybackCanvas.h"
#include "ui/views/PlaybackTracks.h"
#include "ui/views/PlaybackView.h"

#include <QComboBox>
#include <QImage>
#include <QPainter>
#include <QTemporaryDir>
#include <QtTest>

using namespace athlos;
using namespace athlos::ui;

namespace {

constexpr double kFast = 8.0, kSlow = 1.5;  // m/s

// An athlete running along x at constant speed from x0, at height y, 0–10 s at 10 Hz.
Stream athlete(const QString& label, const QString& team, double x0, double y, double speed) {
    StreamInfo info;
    info.kind = QStringLiteral("lps-position");
    info.frame = QStringLiteral("pitch");
    info.columns = {{"x", "m"}, {"y", "m"}};
    info.attributes = QJsonObject{{"label", label}, {"team", team}};
    StreamData d(101, 2);
    for (std::size_t k = 0; k < d.rows(); ++k) {
        d.t[k] = 0.1 * double(k);
        d.at(k, 0) = x0 + speed * d.t[k];
        d.at(k, 1) = y;
    }
    return Stream(info, d);
}

std::unique_ptr<Project> teamProject(const QString& path) {
    auto project = testing::makeProject(path);
    project->putStream("team/fast", athlete("F", "home", -30.0, 10.0, kFast));
    project->putStream("team/slow", athlete("S", "away", 20.0, -15.0, kSlow));
    return project;
}

QImage frame(PlaybackCanvas* canvas) {
    QImage image(canvas->size(), QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    canvas->paintFrame(painter);
    return image;
}

bool near(QColor a, QColor b, int tolerance = 12) {
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

QColor pixelAt(const QImage& image, QPointF p) { return image.pixelColor(p.toPoint()); }

}  // namespace

class ViewsPlaybackTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
    }

    void followsTheCursor() {
        auto project = teamProject(dir_.filePath("a.athlos"));
        QCOMPARE(PlaybackTracks::teamRecording(*project, 2), QStringLiteral("team"));
        TimeController time;
        time.setBounds(0.0, 10.0);
        PlaybackView view(project.get());
        view.setAttribute(Qt::WA_DontShowOnScreen);
        view.resize(900, 640);
        view.show();
        view.setTimeController(&time);
        QVERIFY(view.setRecording("team").ok());
        QVERIFY(!view.setRecording("nothing").ok());
        QCoreApplication::processEvents();
        PlaybackCanvas* canvas = view.canvas();
        canvas->frameAll();
        QCOMPARE(int(canvas->tracks().size()), 2);
        QVERIFY(canvas->width() > 800 && canvas->height() > 500);

        const QColor home(250, 250, 250);  // the home team's dot
        QPointF before;
        for (const double t : {3.0, 6.05}) {
            time.setCursor(t);
            QCOMPARE(canvas->time(), t);
            const QImage image = frame(canvas);
            // Where the data is at the cursor (interpolated between samples at 6.05 s).
            const QPointF p = canvas->toScreen(-30.0 + kFast * t, 10.0);
            QVERIFY2(near(pixelAt(image, p), home), qPrintable(pixelAt(image, p).name()));
            const QPointF slow = canvas->toScreen(20.0 + kSlow * t, -15.0);
            QVERIFY(near(pixelAt(image, slow), QColor(25, 25, 25), 20));
            if (!before.isNull()) {
                QVERIFY((p - before).manhattanLength() > 50);  // it moved with the cursor
                QVERIFY(!near(pixelAt(image, before), home));  // and is gone from there
            }
            before = p;
        }
        // Same scale on both axes, y up.
        const QTransform w = canvas->worldToScreen();
        QCOMPARE(w.m11(), -w.m22());
        QVERIFY(w.m11() > 0);
    }

    void trailLengthAndSpeedColours() {
        auto project = teamProject(dir_.filePath("b.athlos"));
        TimeController time;
        time.setBounds(0.0, 10.0);
        PlaybackView view(project.get());
        view.setAttribute(Qt::WA_DontShowOnScreen);
        view.resize(900, 640);
        view.show();
        view.setTimeController(&time);
        QVERIFY(view.setRecording("team").ok());
        QCoreApplication::processEvents();
        PlaybackCanvas* canvas = view.canvas();
        canvas->frameAll();
        time.setCursor(8.0);
        const QColor fast = PlaybackTracks::binColor(PlaybackTracks::binOf(kFast));
        const QColor slow = PlaybackTracks::binColor(PlaybackTracks::binOf(kSlow));
        QVERIFY(!near(fast, slow, 40));
        auto fastAt = [&](double secondsBack) { return canvas->toScreen(-30.0 + kFast * (8.0 - secondsBack), 10.0); };

        view.setTrailSeconds(2.0);
        QCOMPARE(canvas->trailSeconds(), 2.0);
        QImage image = frame(canvas);
        QVERIFY2(near(pixelAt(image, fastAt(1.0)), fast), qPrintable(pixelAt(image, fastAt(1.0)).name()));
        QVERIFY2(near(pixelAt(image, fastAt(1.9)), fast), qPrintable(pixelAt(image, fastAt(1.9)).name()));
        QVERIFY(!near(pixelAt(image, fastAt(2.6)), fast, 40));  // older than the trail
        QVERIFY(!near(pixelAt(image, fastAt(4.0)), fast, 40));

        view.setTrailSeconds(5.0);
        image = frame(canvas);
        QVERIFY(near(pixelAt(image, fastAt(2.6)), fast));
        QVERIFY(near(pixelAt(image, fastAt(4.5)), fast));
        QVERIFY(!near(pixelAt(image, fastAt(5.6)), fast, 40));
        // The slow athlete's trail has the slow colour.
        const QPointF slowPoint = canvas->toScreen(20.0 + kSlow * (8.0 - 4.0), -15.0);
        QVERIFY2(near(pixelAt(image, slowPoint), slow), qPrintable(pixelAt(image, slowPoint).name()));

        view.setTrailSeconds(0.0);
        image = frame(canvas);
        QVERIFY(!near(pixelAt(image, fastAt(1.0)), fast, 40));
    }

    void venuePersistsInMetadata() {
        const QString path = dir_.filePath("c.athlos");
        auto project = teamProject(path);
        {
            PlaybackView view(project.get());
            QVERIFY(view.setRecording("team").ok());
            // Guessed from the data extent (80 × 25 m, inside a football pitch).
            QCOMPARE(view.venue(), VenueDrawing::Venue::Football);
            QVERIFY(!project->recording("team")->metadata.contains("venue"));
            project->setModified(false);
            view.venueCombo()->setCurrentIndex(view.venueCombo()->findData("rugby"));
            QCOMPARE(view.venue(), VenueDrawing::Venue::Rugby);
            QCOMPARE(project->recording("team")->metadata.value("venue").toString(), QStringLiteral("rugby"));
            QVERIFY(project->isModified());
        }
        PlaybackView again(project.get());
        QVERIFY(again.setRecording("team").ok());
        QCOMPARE(again.venue(), VenueDrawing::Venue::Rugby);
        QVERIFY(project->save().ok());
        auto reopened = Project::open(path);
        QVERIFY(reopened.ok());
        QCOMPARE(PlaybackView::venueFor(**reopened, "team"), VenueDrawing::Venue::Rugby);
        // A stream's own venue attribute wins over the extent.
        Stream onTrack = athlete("T", "", -30.0, 40.0, 5.0);
        onTrack.info().attributes["venue"] = "track";
        project->putStream("other/t", onTrack);
        QCOMPARE(PlaybackView::venueFor(*project, "other"), VenueDrawing::Venue::Track);
    }

    void venueGuessFromExtent() {
        QCOMPARE(VenueDrawing::guess(QRectF(-50, -30, 100, 60)), VenueDrawing::Venue::Football);
        QCOMPARE(VenueDrawing::guess(QRectF(-59, -34, 118, 68)), VenueDrawing::Venue::Rugby);
        QCOMPARE(VenueDrawing::guess(QRectF(-85, -45, 170, 90)), VenueDrawing::Venue::Track);
        QCOMPARE(VenueDrawing::guess(QRectF(0, 0, 5, 5)), VenueDrawing::Venue::None);
        QCOMPARE(VenueDrawing::guess(QRectF(-500, -30, 1000, 60)), VenueDrawing::Venue::None);
    }

    void registeredToolAndScreenshotViews() {
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) {
            return t.id == "team-playback" && QByteArray(t.menu) == "View" && QByteArray(t.text) == "Team playback…";
        }));
        QVERIFY(screenshotViews().contains("playback"));

        const QString path = dir_.filePath("d.athlos");
        auto project = teamProject(path);
        QVERIFY(project->save().ok());
        const QColor grass(76, 141, 72);
        for (const QString& view : {QStringLiteral("playback"), QStringLiteral("trajectory")}) {
            const QString png = dir_.filePath(view + ".png");
            const Status s = renderScreenshot(path, view, png, QSize(1280, 800));
            QVERIFY2(s.ok(), s.ok() ? "" : qPrintable(s.message()));
            const QImage image(png);
            QCOMPARE(image.size(), QSize(1280, 800));
            int grassPixels = 0, homeDot = 0, fastTrail = 0;
            const QColor fast = PlaybackTracks::binColor(PlaybackTracks::binOf(kFast));
            for (int y = 0; y < image.height(); y += 2)
                for (int x = 0; x < image.width(); x += 2) {
                    const QColor c = image.pixelColor(x, y);
                    grassPixels += near(c, grass, 4);
                    homeDot += near(c, QColor(250, 250, 250), 3);
                    fastTrail += near(c, fast, 6);
                }
            QVERIFY2(grassPixels > 20000, qPrintable(QString::number(grassPixels)));  // the pitch is drawn
            QVERIFY2(fastTrail > 5, qPrintable(QString::number(fastTrail)));          // with a trail mid-recording
            QVERIFY(homeDot > 0);
        }
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(ViewsPlaybackTest)
#include "ViewsPlaybackTest.moc"
