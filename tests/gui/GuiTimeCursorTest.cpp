// One time cursor for all panels: linked x ranges, cursor line and read-out (value at the cursor,
// statistics of the visible range), click sets the cursor, transport keys (space, arrows, J/K/L)
// and speeds, and the dock layout saved in the project and restored on open.
#include "GuiTestSupport.h"
#include "ui/MainWindow.h"
#include "ui/RangeStatistics.h"
#include "ui/TimeController.h"
#include "ui/TimeSeriesPanel.h"
#include "ui/TrajectoryPanel.h"

#include <QDockWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

using namespace athlos;
using namespace athlos::ui;

class GuiTimeCursorTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void panelsShareTheVisibleRange();
    void clickSetsCursorAndReadoutFollows();
    void transportKeys();
    void statisticsOfARange();
    void layoutIsSavedWithTheProject();
    void trajectoryMarkerFollowsCursor();

private:
    QTemporaryDir dir_;
};

void GuiTimeCursorTest::initTestCase() {
    QVERIFY(dir_.isValid());
    testing::isolateSettings(dir_.filePath(QStringLiteral("settings")));
}

void GuiTimeCursorTest::panelsShareTheVisibleRange() {
    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.show();
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("link.athlos"))));
    QVERIFY(window.selectItem(QStringLiteral("run1/imu")));
    TimeSeriesPanel* second = window.addTimeSeriesPanel(QStringLiteral("run1/lps"));
    QVERIFY(second);
    window.waitForPlots();
    QCOMPARE(window.timeSeriesPanels().size(), 2);

    TimeController* time = window.timeController();
    // Bounds: the union of both streams (imu 0–19.99 s, lps 0–79.9 s).
    QCOMPARE(time->begin(), 0.0);
    QVERIFY(std::abs(time->end() - 79.9) < 1e-9);
    QVERIFY(std::abs(time->step() - 0.01) < 1e-9);  // the main stream's sample interval

    window.timeSeriesPanel()->plot()->xAxis->setRange(3.0, 5.0);
    QCOMPARE(second->plot()->xAxis->range(), QCPRange(3.0, 5.0));
    QCOMPARE(time->visibleBegin(), 3.0);
    second->plot()->xAxis->setRange(10.0, 12.5);
    QCOMPARE(window.timeSeriesPanel()->plot()->xAxis->range(), QCPRange(10.0, 12.5));
    time->zoomToSelection(8.0, 6.0);
    QCOMPARE(second->plot()->xAxis->range(), QCPRange(6.0, 8.0));
    QCOMPARE(window.timeSeriesPanel()->plot()->xAxis->range(), QCPRange(6.0, 8.0));

    time->setCursor(7.0);
    QCOMPARE(window.timeSeriesPanel()->cursorLine()->point1->coords().x(), 7.0);
    QCOMPARE(second->cursorLine()->point1->coords().x(), 7.0);
    QVERIFY(second->cursorLine()->visible());
}

void GuiTimeCursorTest::clickSetsCursorAndReadoutFollows() {
    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("click.athlos"))));
    QVERIFY(window.selectItem(QStringLiteral("run1/imu")));
    window.showTimeSeriesView();
    window.waitForPlots();
    TimeSeriesPanel* panel = window.timeSeriesPanel();
    QCustomPlot* plot = panel->plot();
    const QRect area = plot->axisRect()->rect();
    const QPoint at(area.left() + area.width() / 3, area.center().y());
    QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, at);
    const double t = plot->xAxis->pixelToCoord(at.x());
    QVERIFY(std::abs(window.timeController()->cursor() - t) < 1e-9);

    // gyr_y is constant -0.3: at the cursor, mean, min and max all read -0.3, SD 0.
    const QString readout = panel->readoutText();
    QVERIFY2(readout.contains(QStringLiteral("gyr_y")), qPrintable(readout));
    QVERIFY2(readout.contains(QStringLiteral("-0.3")), qPrintable(readout));
    QVERIFY2(readout.contains(QStringLiteral("mean")), qPrintable(readout));
    // The read-out shows the interpolated value of acc_x = sin(2πt) at the cursor.
    const QString expected = QLocale().toString(RangeStatistics::valueAt(*panel->data(), 0, t), 'g', 5);
    QVERIFY2(readout.contains(expected), qPrintable(expected + QStringLiteral(" in ") + readout));
}

void GuiTimeCursorTest::transportKeys() {
    MainWindow window;
    window.setInteractive(false);
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("keys.athlos"))));
    QVERIFY(window.selectItem(QStringLiteral("run1/imu")));
    window.waitForPlots();
    TimeController* time = window.timeController();
    TimeSeriesPanel* panel = window.timeSeriesPanel();
    time->setCursor(1.0);

    QTest::keyClick(panel, Qt::Key_Right);
    QVERIFY(std::abs(time->cursor() - 1.01) < 1e-9);
    QTest::keyClick(panel, Qt::Key_Left);
    QTest::keyClick(panel, Qt::Key_Left);
    QVERIFY(std::abs(time->cursor() - 0.99) < 1e-9);

    QTest::keyClick(panel, Qt::Key_Space);
    QVERIFY(time->isPlaying());
    QCOMPARE(time->direction(), 1);
    time->advance(0.5);
    QVERIFY(std::abs(time->cursor() - 1.49) < 1e-9);
    QTest::keyClick(panel, Qt::Key_Space);
    QVERIFY(!time->isPlaying());

    QTest::keyClick(panel, Qt::Key_L);
    QVERIFY(time->isPlaying());
    QCOMPARE(time->speed(), 1.0);
    QTest::keyClick(panel, Qt::Key_L);
    QCOMPARE(time->speed(), 2.0);
    for (int i = 0; i < 4; ++i) QTest::keyClick(panel, Qt::Key_L);
    QCOMPARE(time->speed(), TimeController::kMaxSpeed);
    QTest::keyClick(panel, Qt::Key_K);
    QVERIFY(!time->isPlaying());

    const double before = time->cursor();
    QTest::keyClick(panel, Qt::Key_J);
    QVERIFY(time->isPlaying());
    QCOMPARE(time->direction(), -1);
    QCOMPARE(time->speed(), 1.0);
    time->advance(0.25);
    QVERIFY(std::abs(time->cursor() - (before - 0.25)) < 1e-9);
    time->setSpeed(0.01);
    QCOMPARE(time->speed(), TimeController::kMinSpeed);
    // Backward playback stops at the start.
    time->advance(1000.0);
    QCOMPARE(time->cursor(), time->begin());
    QVERIFY(!time->isPlaying());

    // Real playback through the timer moves forward.
    time->setCursor(2.0);
    QTest::keyClick(panel, Qt::Key_L);
    QTest::qWait(150);
    QTest::keyClick(panel, Qt::Key_K);
    QVERIFY(time->cursor() > 2.05);
}

void GuiTimeCursorTest::statisticsOfARange() {
    StreamData data(5, 1);
    const double values[] = {1.0, 2.0, 3.0, 4.0, std::nan("")};
    for (int i = 0; i < 5; ++i) {
        data.t[std::size_t(i)] = i;
        data.at(std::size_t(i), 0) = values[i];
    }
    const RangeStatistics s = RangeStatistics::compute(data, 0, 0.5, 10.0);
    QCOMPARE(s.count, std::size_t(3));  // 2, 3, 4 (NaN skipped)
    QCOMPARE(s.mean, 3.0);
    QCOMPARE(s.sd, 1.0);
    QCOMPARE(s.min, 2.0);
    QCOMPARE(s.max, 4.0);
    QCOMPARE(RangeStatistics::valueAt(data, 0, 1.25), 2.25);
    QVERIFY(std::isnan(RangeStatistics::valueAt(data, 0, -1.0)));
}

void GuiTimeCursorTest::layoutIsSavedWithTheProject() {
    const QString path = dir_.filePath(QStringLiteral("layout.athlos"));
    {
        auto project = testing::makeProject(path);
        QVERIFY(project->save());
    }
    {
        MainWindow window;
        window.setInteractive(false);
        window.resize(1280, 800);
        window.show();
        QVERIFY(window.openProject(path));
        QVERIFY(window.addTimeSeriesPanel(QStringLiteral("run1/lps")));
        QDockWidget* details = window.findChild<QDockWidget*>(QStringLiteral("detailsDock"));
        QVERIFY(details);
        details->hide();  // a layout change to remember
        QVERIFY(window.saveProject());
    }
    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.show();
    QVERIFY(window.openProject(path));
    QCOMPARE(window.timeSeriesPanels().size(), 2);
    QCOMPARE(window.timeSeriesPanels().at(1)->title(), QStringLiteral("run1/lps"));
    QVERIFY(window.project()->meta().extra.contains(QStringLiteral("ui_layout")));
    QDockWidget* details = window.findChild<QDockWidget*>(QStringLiteral("detailsDock"));
    QVERIFY(details && !details->isVisible());
}

void GuiTimeCursorTest::trajectoryMarkerFollowsCursor() {
    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.setProject(testing::makeProject(dir_.filePath(QStringLiteral("marker.athlos"))));
    QVERIFY(window.selectItem(QStringLiteral("run1/lps")));
    window.showTrajectoryView();
    window.waitForPlots();
    // makeTrackStream: sample i at t = 0.1 i, evenly spaced along the lap; the first 84.39 m run
    // along y = -36.8 from x = -42.195.
    const double lap = 2 * 84.39 + 2 * std::numbers::pi * 36.8;
    window.timeController()->setCursor(2.05);
    const QPointF p = window.trajectoryPanel()->cursorPosition();
    const double expectedX = -42.195 + lap / 800.0 * (2.05 / 0.1);
    QVERIFY2(std::abs(p.x() - expectedX) < 1e-9, qPrintable(QStringLiteral("%1 vs %2").arg(p.x()).arg(expectedX)));
    QVERIFY(std::abs(p.y() + 36.8) < 1e-9);
    window.timeController()->setCursor(1000.0);  // clamped to the end of the recording
    QVERIFY(!std::isnan(window.trajectoryPanel()->cursorPosition().x()));
}

QTEST_MAIN(GuiTimeCursorTest)
#include "GuiTimeCursorTest.moc"
