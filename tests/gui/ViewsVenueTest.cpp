// Venues from coordinates in the playback view: a pitch placed by its corners (rotated in the
// project's ENU frame) is the default venue, drawn with its real length and width (markings of
// fixed size by the laws unchanged), and GNSS positions (ENU) are shown in the pitch frame.
#include "GuiTestSupport.h"

#include "core/geometry/PitchGeometry.h"
#include "ui/TimeController.h"
#include "ui/views/PlaybackCanvas.h"
#include "ui/views/PlaybackTracks.h"
#include "ui/views/PlaybackView.h"

#include <Eigen/Geometry>
#include <QComboBox>
#include <QImage>
#include <QPainter>
#include <QTemporaryDir>
#include <QtTest>

using namespace athlos;
using namespace athlos::ui;

namespace {

constexpr double kRotation = 0.5236;  // rad, about 30°
const Eigen::Vector2d kCentre(20.0, 10.0);

PitchGeometry surveyedPitch() {
    std::vector<Eigen::Vector2d> corners;
    for (const auto& q :
         {Eigen::Vector2d(-50, -32), Eigen::Vector2d(50, -32), Eigen::Vector2d(50, 32), Eigen::Vector2d(-50, 32)})
        corners.push_back(kCentre + Eigen::Rotation2Dd(kRotation) * q);
    auto pitch = PitchGeometry::fit(corners, PitchGeometry::Kind::Football, {}, QStringLiteral("main"));
    return *pitch;
}

// A GNSS athlete (x, y in the project's ENU frame) running along the pitch's x axis at y = 10 m in
// the pitch frame, from x = −30 m at 6 m/s, 0–10 s at 10 Hz.
Stream gnssAthlete(const PitchGeometry& pitch) {
    StreamInfo info;
    info.kind = QStringLiteral("gnss");
    info.frame = QStringLiteral("WGS84");
    info.columns = {{"lat", "deg"}, {"lon", "deg"}, {"x", "m"}, {"y", "m"}};
    info.attributes =
        QJsonObject{{"label", "G"}, {"team", "home"}, {"enu_origin", QJsonObject{{"lat", 53.3}, {"lon", -6.2}}}};
    StreamData d(101, 4);
    for (std::size_t k = 0; k < d.rows(); ++k) {
        d.t[k] = 0.1 * double(k);
        const Eigen::Vector2d p = pitch.toEnu({-30.0 + 6.0 * d.t[k], 10.0});
        d.at(k, 0) = 53.3;
        d.at(k, 1) = -6.2;
        d.at(k, 2) = p.x();
        d.at(k, 3) = p.y();
    }
    return Stream(info, d);
}

QImage frame(PlaybackCanvas* canvas) {
    QImage image(canvas->size(), QImage::Format_ARGB32_Premultiplied);
    QPainter painter(&image);
    canvas->paintFrame(painter);
    return image;
}

bool isGrass(QColor c) { return c.green() > 135 && c.green() < 160 && c.red() < 95; }       // both stripe colours
bool isSurround(QColor c) { return c.green() >= 118 && c.green() <= 130 && c.red() < 72; }  // outside the lines

}  // namespace

class ViewsVenueTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
    }

    void sizesAndBounds() {
        QCOMPARE(VenueDrawing::sizeOf(VenueDrawing::Venue::Football), (VenueDrawing::Size{105.0, 68.0}));
        QCOMPARE(VenueDrawing::sizeOf(VenueDrawing::Venue::Football, {100.0, 64.0}), (VenueDrawing::Size{100.0, 64.0}));
        QCOMPARE(VenueDrawing::bounds(VenueDrawing::Venue::Football, {100.0, 64.0}), QRectF(-53, -35, 106, 70));
        // Rugby: the in-goal (10 m) stays outside the surveyed field of play.
        QCOMPARE(VenueDrawing::bounds(VenueDrawing::Venue::Rugby, {96.0, 68.0}).width(), 96.0 + 2 * 10.0 + 4.0);
        QCOMPARE(VenueDrawing::ofPitch(PitchGeometry::Kind::Rectangle), VenueDrawing::Venue::Rectangle);
        QCOMPARE(VenueDrawing::fromId("rectangle"), std::optional(VenueDrawing::Venue::Rectangle));
    }

    void surveyedPitchIsTheVenueInThePitchFrame() {
        const PitchGeometry pitch = surveyedPitch();
        QVERIFY(std::abs(pitch.length() - 100.0) < 1e-9 && std::abs(pitch.width() - 64.0) < 1e-9);
        auto project = testing::makeProject(dir_.filePath("a.athlos"));
        project->geometry()["main"] = pitch.toJson();
        project->putStream("session/g", gnssAthlete(pitch));
        // A stream in another frame (a simulated match, already in the pitch frame) is not moved.
        StreamInfo local;
        local.kind = QStringLiteral("lps-position");
        local.frame = QStringLiteral("pitch");
        local.columns = {{"x", "m"}, {"y", "m"}};
        StreamData ld(2, 2);
        ld.t = {0.0, 10.0};
        ld.at(0, 0) = 5.0, ld.at(0, 1) = -5.0, ld.at(1, 0) = 5.0, ld.at(1, 1) = -5.0;
        project->putStream("session/l", Stream(local, ld));

        QCOMPARE(PlaybackView::venueFor(*project, "session"), VenueDrawing::Venue::Football);
        TimeController time;
        time.setBounds(0.0, 10.0);
        PlaybackView view(project.get());
        view.setAttribute(Qt::WA_DontShowOnScreen);
        view.resize(900, 640);
        view.show();
        view.setTimeController(&time);
        QVERIFY(view.setRecording("session").ok());
        QCoreApplication::processEvents();
        PlaybackCanvas* canvas = view.canvas();
        canvas->frameAll();
        QCOMPARE(view.venue(), VenueDrawing::Venue::Football);
        QCOMPARE(canvas->venueSize(), (VenueDrawing::Size{pitch.length(), pitch.width()}));
        QCOMPARE(view.venueCombo()->currentText(), QStringLiteral("Pitch 'main' 100.0 × 64.0 m"));

        // Positions in the pitch frame: the GNSS athlete runs along x at y = 10 m.
        QCOMPARE(int(canvas->tracks().size()), 2);
        const AthleteTrack& g = canvas->tracks()[0].path == "session/g" ? canvas->tracks()[0] : canvas->tracks()[1];
        const AthleteTrack& l = canvas->tracks()[0].path == "session/l" ? canvas->tracks()[0] : canvas->tracks()[1];
        QVERIFY(std::abs(g.x[50] - 0.0f) < 1e-3f && std::abs(g.y[50] - 10.0f) < 1e-3f);
        QVERIFY(std::abs(g.x[100] - 30.0f) < 1e-3f && std::abs(g.y[100] - 10.0f) < 1e-3f);
        QCOMPARE(l.x[0], 5.0f);
        QCOMPARE(l.y[0], -5.0f);

        // The real 100 m length: grass 1.5 m inside the goal line, surround 1.5 m outside it (still inside a
        // 105 m pitch); the markings of fixed size keep it: the penalty area is 16.5 m deep from the line.
        time.setCursor(0.0);
        const QImage image = frame(canvas);
        for (const double s : {-1.0, 1.0}) {
            const QColor inside = image.pixelColor(canvas->toScreen(s * 48.5, 26.0).toPoint());
            const QColor outside = image.pixelColor(canvas->toScreen(s * 51.5, 26.0).toPoint());
            QVERIFY2(isGrass(inside), qPrintable(inside.name()));
            QVERIFY2(isSurround(outside), qPrintable(outside.name()));
            // Touch line at y = ±32 m (not ±34 m).
            QVERIFY2(isSurround(image.pixelColor(canvas->toScreen(10.0, s * 33.2).toPoint())),
                     "outside the touch line");
            QVERIFY2(isGrass(image.pixelColor(canvas->toScreen(10.0, s * 30.8).toPoint())), "inside the touch line");
        }
        // A white line of the penalty area (16.5 m from the goal line at x = 50 → x = 33.5), at y = 10.
        auto brightest = [&](QPointF p) {
            int best = 0;
            for (int dx = -2; dx <= 2; ++dx) best = std::max(best, image.pixelColor(p.toPoint() + QPoint(dx, 0)).red());
            return best;
        };
        QVERIFY2(brightest(canvas->toScreen(33.5, 10.0)) > 150, "penalty area line");
        QVERIFY2(brightest(canvas->toScreen(36.0, 10.0)) < 110, "no line 2.5 m further");

        // Another venue chosen: its standard size.
        view.setVenue(VenueDrawing::Venue::Rugby);
        QCOMPARE(canvas->venueSize(), VenueDrawing::Size{});
        view.setVenue(VenueDrawing::Venue::Football);
        QCOMPARE(canvas->venueSize(), (VenueDrawing::Size{pitch.length(), pitch.width()}));
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(ViewsVenueTest)
#include "ViewsVenueTest.moc"
