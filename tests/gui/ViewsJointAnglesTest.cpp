// Joint angles view: plots the stream in degrees with the reference and the RMSE per angle, follows
// the window's TimeController (visible range both ways, cursor line, read-out), and is registered as
// a tool and as the screenshot view "joint-angles".
#include "GuiTestSupport.h"

#include "ui/MainWindow.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/views/JointAnglesView.h"

#include <QDockWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>
#include <numbers>

using namespace athlos;
using namespace athlos::ui;

namespace {

constexpr double kRad = std::numbers::pi / 180.0;

// Flexion 30 + 20 sin t, abduction 2 cos t, rotation 5 sin 2t (deg); the estimate adds a constant
// error (1, −0.5, 2) deg, so the RMSE per angle is exactly that error.
Stream angleStream(bool reference, double rate = 50.0, int rows = 500, const char* side = "right") {
    StreamInfo info;
    info.kind = QStringLiteral("joint-angles");
    info.frame = QStringLiteral("segment");
    info.columns = {{"flexion", "rad"}, {"abduction", "rad"}, {"rotation", "rad"}};
    info.attributes = QJsonObject{{"joint", "knee"}, {"side", side}};
    if (reference) info.attributes.insert("reference", true);
    StreamData d(std::size_t(rows), 3);
    const double err[3] = {reference ? 0.0 : 1.0, reference ? 0.0 : -0.5, reference ? 0.0 : 2.0};
    for (int k = 0; k < rows; ++k) {
        const double t = k / rate;
        d.t[std::size_t(k)] = t;
        d.at(std::size_t(k), 0) = (30 + 20 * std::sin(t) + err[0]) * kRad;
        d.at(std::size_t(k), 1) = (2 * std::cos(t) + err[1]) * kRad;
        d.at(std::size_t(k), 2) = (5 * std::sin(2 * t) + err[2]) * kRad;
    }
    return Stream(info, d);
}

void addTrial(Project& project) {
    project.putStream("knee/angles", angleStream(false));
    project.putStream("knee/reference", angleStream(true));
}

}  // namespace

class ViewsJointAnglesTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
    }

    void plotsDegreesWithReferenceAndRmse() {
        auto project = testing::makeProject(dir_.filePath("a.athlos"));
        addTrial(*project);
        QCOMPARE(JointAnglesView::jointAngleStreams(*project), QStringList{"knee/angles"});
        QCOMPARE(JointAnglesView::referenceFor(*project, "knee/angles"), QStringLiteral("knee/reference"));
        JointAnglesView view(project.get());
        QVERIFY(view.setStream("knee/angles").ok());
        QVERIFY(!view.setStream("run1/imu").ok());
        QCOMPARE(view.reference(), QStringLiteral("knee/reference"));
        const double expected[3] = {1.0, 0.5, 2.0};
        QCOMPARE(view.rmse().size(), std::size_t(3));
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(view.plot(i)->graphCount(), 2);
            QCOMPARE(view.plot(i)->graph(0)->dataCount(), 500);
            QVERIFY2(std::abs(view.rmse()[std::size_t(i)] - expected[i]) < 1e-9,
                     qPrintable(QString::number(view.rmse()[std::size_t(i)])));
            QVERIFY(view.plot(i)->graph(1)->name().contains(QString::number(expected[i], 'f', 2)));
        }
        // Values in degrees: flexion at t = 0 is 30 + 1.
        QVERIFY(std::abs(view.plot(0)->graph(0)->data()->at(0)->value - 31.0) < 1e-9);
        QVERIFY(std::abs(view.plot(2)->graph(1)->data()->at(25)->value - 5 * std::sin(1.0)) < 1e-9);
    }

    void followsTheTimeController() {
        auto project = testing::makeProject(dir_.filePath("b.athlos"));
        addTrial(*project);
        TimeController time;
        time.setBounds(0.0, 10.0);
        JointAnglesView view(project.get());
        view.setTimeController(&time);
        time.setVisibleRange(2.0, 5.0);
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(view.plot(i)->xAxis->range().lower, 2.0);
            QCOMPARE(view.plot(i)->xAxis->range().upper, 5.0);
        }
        time.setCursor(3.3);
        for (int i = 0; i < 3; ++i) {
            QVERIFY(view.cursorLine(i)->visible());
            QCOMPARE(view.cursorLine(i)->point1->coords().x(), 3.3);
        }
        const auto v = view.valuesAt(3.3);
        QVERIFY(std::abs(v[0] - (31 + 20 * std::sin(3.3))) < 0.05);  // linear interpolation between 50 Hz samples
        QVERIFY(view.readoutText().contains(QString::number(v[0], 'f', 1)));
        QVERIFY(view.readoutText().contains("3.30"));
        // Zooming one plot moves the window's range, and the other plots follow.
        view.plot(1)->xAxis->setRange(4.0, 6.0);
        QCOMPARE(time.visibleBegin(), 4.0);
        QCOMPARE(time.visibleEnd(), 6.0);
        QCOMPARE(view.plot(0)->xAxis->range().lower, 4.0);
        QCOMPARE(view.plot(2)->xAxis->range().upper, 6.0);
    }

    void registeredAsToolAndScreenshotView() {
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) {
            return t.id == "joint-angles-view" && QByteArray(t.menu) == "Inertial" &&
                   QByteArray(t.text) == "Joint angles…";
        }));
        const auto& views = registeredViews();
        auto it = std::find_if(views.begin(), views.end(), [](const ViewEntry& v) { return v.name == "joint-angles"; });
        QVERIFY(it != views.end());

        MainWindow window;
        window.setInteractive(false);
        window.resize(1280, 800);
        auto shared = std::shared_ptr<Project>(testing::makeProject(dir_.filePath("c.athlos")));
        window.setProject(shared);
        QVERIFY(!it->prepare(window).ok());
        addTrial(*shared);
        const Status status = it->prepare(window);
        QVERIFY2(status.ok(), status.ok() ? "" : qPrintable(status.message()));
        auto* dock = window.findChild<QDockWidget*>("jointAnglesDock");
        QVERIFY(dock);
        auto* view = dock->findChild<JointAnglesView*>();
        QVERIFY(view);
        QCOMPARE(view->stream(), QStringLiteral("knee/angles"));
        QCOMPARE(view->plot(0)->graphCount(), 2);
        // The view shares the window's cursor.
        window.timeController()->setCursor(1.25);
        QCOMPARE(view->cursorLine(0)->point1->coords().x(), window.timeController()->cursor());
        QCOMPARE(view->plot(2)->xAxis->range().lower, window.timeController()->visibleBegin());
        // It renders: the plot area is not blank.
        const QImage image = dock->grab().toImage();
        QVERIFY(image.width() > 200 && image.height() > 200);
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 4)
            for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 10);
    }

    void overlaysTheOtherSide() {
        auto project = testing::makeProject(dir_.filePath("o.athlos"));
        addTrial(*project);
        QVERIFY(JointAnglesView::otherSideFor(*project, "knee/angles").isEmpty());
        project->putStream("knee/left-angles", angleStream(false, 50.0, 400, "left"));
        project->putStream("knee/left-reference", angleStream(true, 50.0, 400, "left"));
        project->putStream("other/left-angles", angleStream(false, 50.0, 400, "left"));  // another recording
        QCOMPARE(JointAnglesView::otherSideFor(*project, "knee/angles"), QStringLiteral("knee/left-angles"));
        QCOMPARE(JointAnglesView::otherSideFor(*project, "knee/left-angles"), QStringLiteral("knee/angles"));
        JointAnglesView view(project.get());
        QVERIFY(view.setStream("knee/angles").ok());
        QCOMPARE(view.otherSide(), QStringLiteral("knee/left-angles"));
        for (int i = 0; i < 3; ++i) {
            QCOMPARE(view.plot(i)->graphCount(), 3);  // estimate, reference, other side
            QCOMPARE(view.plot(i)->graph(2)->dataCount(), 400);
            QCOMPARE(view.plot(i)->graph(2)->name(), QStringLiteral("left knee"));
        }
        view.setOtherSideShown(false);
        QVERIFY(view.otherSide().isEmpty());
        QCOMPARE(view.plot(0)->graphCount(), 2);
        view.setOtherSideShown(true);
        QCOMPARE(view.plot(0)->graphCount(), 3);
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(ViewsJointAnglesTest)
#include "ViewsJointAnglesTest.moc"
