// Stick figure view: finds body-com joint streams, draws the current sample with its CoM, follows the window's
// TimeController, rotates with the mouse, and is registered as a tool and as the screenshot view "stick-figure".
#include "GuiTestSupport.h"

#include "ui/MainWindow.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/views/StickFigureView.h"

#include <QDockWidget>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace athlos;
using namespace athlos::ui;

namespace {

const char* const kJoints[15] = {"lumbar",      "cervical",      "head-vertex", "right-shoulder", "right-elbow",
                                 "right-wrist", "left-shoulder", "left-elbow",  "left-wrist",     "right-hip",
                                 "right-knee",  "right-ankle",   "left-hip",    "left-knee",      "left-ankle"};

// A standing figure facing heading ψ(t) = 0.1 t (rad), joints relative to the lumbar joint; the CoM 5 cm below it.
void addBodyCom(Project& project, int rows = 300, double rate = 50.0) {
    StreamInfo info;
    info.kind = QStringLiteral("joint-centres");
    info.frame = QStringLiteral("pelvis-ENU");
    info.attributes = QJsonObject{{"origin", "lumbar joint centre"}};
    for (const char* j : kJoints)
        for (const char* a : {"_x", "_y", "_z"}) info.columns.push_back({QLatin1String(j) + QLatin1String(a), "m"});
    // Body-frame positions: x forward, y left, z up.
    const double body[15][3] = {{0, 0, 0},          {0, 0, 0.5},         {0, 0, 0.78},         {0, -0.18, 0.46},
                                {0, -0.2, 0.18},    {0.05, -0.2, -0.05}, {0, 0.18, 0.46},      {0, 0.2, 0.18},
                                {0.05, 0.2, -0.05}, {0, -0.09, -0.15},   {0.02, -0.09, -0.57}, {0, -0.09, -0.97},
                                {0, 0.09, -0.15},   {0.02, 0.09, -0.57}, {0, 0.09, -0.97}};
    StreamData d(std::size_t(rows), 45);
    StreamInfo cinfo;
    cinfo.kind = QStringLiteral("centre-of-mass");
    cinfo.frame = QStringLiteral("pelvis-ENU");
    cinfo.columns = {{"com_x", "m"}, {"com_y", "m"}, {"com_z", "m"}, {"fore_aft", "m"}, {"above_ankles", "m"}};
    StreamData c(std::size_t(rows), 5);
    for (int k = 0; k < rows; ++k) {
        const double t = k / rate, psi = 0.1 * t, cs = std::cos(psi), sn = std::sin(psi);
        d.t[std::size_t(k)] = c.t[std::size_t(k)] = t;
        for (int j = 0; j < 15; ++j) {
            const double* b = body[j];
            d.at(std::size_t(k), 3 * j) = cs * b[0] - sn * b[1];
            d.at(std::size_t(k), 3 * j + 1) = sn * b[0] + cs * b[1];
            d.at(std::size_t(k), 3 * j + 2) = b[2];
        }
        c.at(std::size_t(k), 0) = 0.0;
        c.at(std::size_t(k), 1) = 0.0;
        c.at(std::size_t(k), 2) = -0.05;
        c.at(std::size_t(k), 3) = 0.01;
        c.at(std::size_t(k), 4) = 0.92;
    }
    project.putStream("ski/com-joints", Stream(info, d));
    project.putStream("ski/com", Stream(cinfo, c));
}

}  // namespace

class ViewsStickFigureTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
    }

    void drawsTheCurrentSampleAndFollowsTheCursor() {
        auto project = testing::makeProject(dir_.filePath("a.athlos"));
        addBodyCom(*project);
        QCOMPARE(StickFigureView::jointStreams(*project), QStringList{"ski/com-joints"});
        StickFigureView view(project.get());
        QVERIFY(view.setStream("ski/com-joints").ok());
        QVERIFY(!view.setStream("ski/com").ok());
        QCOMPARE(view.sampleCount(), std::size_t(300));
        TimeController time;
        time.setBounds(0.0, 6.0);
        view.setTimeController(&time);
        time.setCursor(3.0);
        QCOMPARE(view.currentSample(), 150LL);
        QVERIFY(std::abs(view.com().z() + 0.05) < 1e-12);
        QVERIFY(view.readoutText().contains("3.00") && view.readoutText().contains("-50"));
        // Following the heading, the view is from the side whatever the direction: the knee is ahead of the
        // hip by 2 cm on screen, the head vertex 0.78 m up (elevation 0).
        view.setViewAngles(0.0, 0.0);
        const QPointF hip = view.project(view.joint(9)), knee = view.project(view.joint(10));
        QVERIFY2(std::abs(knee.x() - hip.x() - 0.02) < 1e-9, qPrintable(QString::number(knee.x() - hip.x())));
        QVERIFY(std::abs(view.project(view.joint(2)).y() - 0.78) < 1e-9);
        time.setCursor(5.0);
        QCOMPARE(view.currentSample(), 250LL);
        QVERIFY(std::abs(view.project(view.joint(10)).x() - view.project(view.joint(9)).x() - 0.02) < 1e-9);
        // Not following: the projection turns with the athlete.
        view.setFollowHeading(false);
        QVERIFY(std::abs(view.project(view.joint(10)).x() - view.project(view.joint(9)).x() - 0.02) > 1e-3);
        view.setFollowHeading(true);
        // A drag rotates the view.
        view.resize(400, 400);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const double azimuth = view.azimuth();
        QWidget* canvas = view.canvas();
        QTest::mousePress(canvas, Qt::LeftButton, {}, QPoint(100, 100));
        QMouseEvent move(QEvent::MouseMove, QPointF(150, 110), canvas->mapToGlobal(QPointF(150, 110)), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(canvas, &move);
        QTest::mouseRelease(canvas, Qt::LeftButton, {}, QPoint(150, 110));
        QVERIFY(std::abs(view.azimuth() - (azimuth - 0.5)) < 1e-9);
        // The figure is drawn: bones in blue and the CoM in orange.
        const QImage image = canvas->grab().toImage();
        int orange = 0, blue = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor px = image.pixelColor(x, y);
                orange += px.red() > 180 && px.green() < 120 && px.blue() < 60;
                blue += px.blue() > 150 && px.red() < 60;
            }
        QVERIFY2(orange > 20 && blue > 100, qPrintable(QStringLiteral("%1 %2").arg(orange).arg(blue)));
    }

    void registeredAsToolAndScreenshotView() {
        const auto& tools = registeredTools();
        QVERIFY(
            std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) { return t.id == "stick-figure-view"; }));
        const auto& views = registeredViews();
        auto it = std::find_if(views.begin(), views.end(), [](const ViewEntry& v) { return v.name == "stick-figure"; });
        QVERIFY(it != views.end());
        MainWindow window;
        window.setInteractive(false);
        window.resize(1280, 800);
        auto shared = std::shared_ptr<Project>(testing::makeProject(dir_.filePath("c.athlos")));
        window.setProject(shared);
        QVERIFY(!it->prepare(window).ok());
        addBodyCom(*shared);
        const Status status = it->prepare(window);
        QVERIFY2(status.ok(), status.ok() ? "" : qPrintable(status.message()));
        auto* dock = window.findChild<QDockWidget*>("stickFigureDock");
        QVERIFY(dock);
        auto* view = dock->findChild<StickFigureView*>();
        QVERIFY(view);
        window.timeController()->setCursor(1.0);
        QCOMPARE(view->currentSample(), 50LL);
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(ViewsStickFigureTest)
#include "ViewsStickFigureTest.moc"
