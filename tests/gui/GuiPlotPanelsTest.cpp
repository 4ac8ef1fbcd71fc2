// The plot panels: graphs per column with units, decimated point counts at full range, raw
// samples when zoomed in, peaks kept, y auto-fit, load errors; the trajectory with equal scaling
// and start/end markers.
#include "GuiTestSupport.h"
#include "ui/PlotLanes.h"
#include "ui/TimeSeriesPanel.h"
#include "ui/TrajectoryPanel.h"

#include <QSignalSpy>
#include <QtTest>
#include <qcustomplot.h>

using namespace athlos;
using namespace athlos::ui;

namespace {

std::shared_ptr<const Stream> shared(Stream stream) { return std::make_shared<const Stream>(std::move(stream)); }

// n samples at 1 kHz of a slow sine with one +100 spike at `spikeAt`.
Stream bigStream(std::size_t n, std::size_t spikeAt) {
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.columns = {{"acc_x", "m/s^2"}};
    StreamData data(n, 1);
    for (std::size_t i = 0; i < n; ++i) {
        data.t[i] = 1e-3 * double(i);
        data.at(i, 0) = std::sin(1e-4 * double(i));
    }
    data.at(spikeAt, 0) = 100.0;
    return Stream(std::move(info), std::move(data));
}

}  // namespace

class GuiPlotPanelsTest : public QObject {
    Q_OBJECT

private slots:
    void plotsEveryColumnWithUnits();
    void groupsColumnsIntoLanes();
    void stacksLanesSharingTheTimeAxis();
    void labelsTheTimeAxisWithClockTime();
    void decimatesLargeStreamsWithoutLosingPeaks();
    void choosesColumns();
    void reportsLoadErrors();
    void trajectoryHasEqualScalingAndMarkers();
    void recognisesPositionStreams();
};

void GuiPlotPanelsTest::plotsEveryColumnWithUnits() {
    TimeSeriesPanel panel;
    panel.resize(1000, 600);
    panel.show();
    QSignalSpy loaded(&panel, &TimeSeriesPanel::loaded);
    panel.setStream(shared(testing::makeImuStream()), QStringLiteral("run1/imu"));
    QVERIFY(panel.isLoading());
    QVERIFY(loaded.wait(10000));
    QVERIFY(!panel.isLoading());

    QCustomPlot* plot = panel.plot();
    QCOMPARE(plot->graphCount(), 6);
    QCOMPARE(plot->graph(0)->name(), QStringLiteral("acc_x [m/s^2]"));
    QCOMPARE(plot->graph(5)->name(), QStringLiteral("gyr_z [rad/s]"));
    // acc and gyr in two lanes: the time axis is labelled once, under the bottom lane.
    QCOMPARE(panel.laneCount(), 2);
    QCOMPARE(panel.laneRect(1)->axis(QCPAxis::atBottom)->label(), QStringLiteral("t [s]"));
    QVERIFY(plot->xAxis->label().isEmpty());
    QVERIFY(plot->legend->visible());
    QCOMPARE(plot->xAxis->range().lower, 0.0);
    QCOMPARE(plot->xAxis->range().upper, 19.99);
    // 2000 samples over ~900 px: decimated to at most 2 points per pixel column (+2 neighbours).
    plot->replot();
    const int width = plot->axisRect()->width();
    QVERIFY(width > 500);
    for (int g = 0; g < plot->graphCount(); ++g) {
        QVERIFY(plot->graph(g)->dataCount() > 0);
        QVERIFY(plot->graph(g)->dataCount() <= 2 * width + 2);
    }
    QCOMPARE(panel.visibleColumns().size(), 6);
}

void GuiPlotPanelsTest::groupsColumnsIntoLanes() {
    QCOMPARE(PlotLanes::family(QStringLiteral("acc_x")), QStringLiteral("acc"));
    QCOMPARE(PlotLanes::family(QStringLiteral("left_gyr_z")), QStringLiteral("left_gyr"));
    QCOMPARE(PlotLanes::family(QStringLiteral("Q.W")), QStringLiteral("q"));
    QCOMPARE(PlotLanes::family(QStringLiteral("pos_e")), QStringLiteral("pos"));
    QCOMPARE(PlotLanes::family(QStringLiteral("x")), QString());
    QCOMPARE(PlotLanes::family(QStringLiteral("speed")), QString());
    QCOMPARE(PlotLanes::family(QStringLiteral("max")), QString());

    // Family and unit: acc | gyr | x, y [m] | lat, lon [deg] | hdop.
    const auto gnssImu = PlotLanes::assign({{"acc_x", "m/s^2"},
                                            {"acc_y", "m/s^2"},
                                            {"gyr_x", "rad/s"},
                                            {"x", "m"},
                                            {"y", "m"},
                                            {"lat", "deg"},
                                            {"lon", "deg"},
                                            {"hdop", "1"}});
    QCOMPARE(gnssImu.laneOf, (std::vector<int>{0, 0, 1, 2, 2, 3, 3, 4}));
    QCOMPARE(gnssImu.unit, (std::vector<QString>{"m/s^2", "rad/s", "m", "deg", "1"}));
    // The same unit in another family is another lane (acc in g beside acc in m/s^2 too).
    const auto twoFeet =
        PlotLanes::assign({{"left_acc_x", "m/s^2"}, {"right_acc_x", "m/s^2"}, {"left_acc_y", "m/s^2"}});
    QCOMPARE(twoFeet.laneOf, (std::vector<int>{0, 1, 0}));
    // More families than lanes: grouped by unit alone.
    std::vector<PlotLanes::Column> many;
    for (int i = 0; i < 8; ++i) many.push_back({QStringLiteral("s%1_x").arg(i), i % 2 ? "m" : "m/s"});
    const auto byUnit = PlotLanes::assign(many);
    QCOMPARE(byUnit.count(), 2);
    QCOMPARE(byUnit.laneOf[2], 0);
    QCOMPARE(byUnit.laneOf[3], 1);
    // More units than lanes: the last lane takes the rest and shows no single unit.
    std::vector<PlotLanes::Column> units;
    for (const char* u : {"m", "s", "Hz", "K", "Pa", "V", "A", "lx"}) units.push_back({QStringLiteral("v"), u});
    const auto capped = PlotLanes::assign(units);
    QCOMPARE(capped.count(), PlotLanes::kMaxLanes);
    QCOMPARE(capped.laneOf.back(), PlotLanes::kMaxLanes - 1);
    QVERIFY(capped.unit.back().isEmpty());
    QCOMPARE(capped.unit.front(), QStringLiteral("m"));
}

void GuiPlotPanelsTest::stacksLanesSharingTheTimeAxis() {
    TimeSeriesPanel panel;
    panel.resize(1000, 700);
    panel.show();
    QSignalSpy loaded(&panel, &TimeSeriesPanel::loaded);
    panel.setStream(shared(testing::makeImuStream()), QStringLiteral("run1/imu"));
    QVERIFY(loaded.wait(10000));
    QCustomPlot* plot = panel.plot();
    QCOMPARE(panel.laneCount(), 2);
    QCOMPARE(panel.laneRect(0), plot->axisRect());
    for (int g = 0; g < 3; ++g) QCOMPARE(panel.laneOfGraph(g), 0);
    for (int g = 3; g < 6; ++g) QCOMPARE(panel.laneOfGraph(g), 1);
    QCOMPARE(plot->graph(4)->valueAxis(), panel.laneRect(1)->axis(QCPAxis::atLeft));
    QCOMPARE(plot->yAxis->label(), QStringLiteral("[m/s^2]"));
    QCOMPARE(panel.laneRect(1)->axis(QCPAxis::atLeft)->label(), QStringLiteral("[rad/s]"));
    // Each lane's y axis fits its own graphs: every plotted value of a lane lies inside its range.
    for (int g = 0; g < plot->graphCount(); ++g) {
        const QCPRange y = plot->graph(g)->valueAxis()->range();
        for (auto it = plot->graph(g)->data()->constBegin(); it != plot->graph(g)->data()->constEnd(); ++it)
            QVERIFY2(y.contains(it->value), qPrintable(plot->graph(g)->name()));
    }
    QVERIFY(plot->yAxis->range() != panel.laneRect(1)->axis(QCPAxis::atLeft)->range());
    // One time axis: zooming the lower lane moves the upper one and re-decimates both.
    panel.laneRect(1)->axis(QCPAxis::atBottom)->setRange(2.0, 4.0);
    QCOMPARE(plot->xAxis->range().lower, 2.0);
    QCOMPARE(plot->xAxis->range().upper, 4.0);
    QVERIFY(plot->graph(0)->data()->constBegin()->key >= 1.9);
    plot->xAxis->setRange(5.0, 6.0);
    QCOMPARE(panel.laneRect(1)->axis(QCPAxis::atBottom)->range().lower, 5.0);
    // A single family (one column chosen): one lane again, the time axis labelled on it.
    panel.setVisibleColumns({QStringLiteral("gyr_x")});
    QCOMPARE(panel.laneCount(), 1);
    QCOMPARE(plot->xAxis->label(), QStringLiteral("t [s]"));
    QCOMPARE(plot->axisRectCount(), 1);
}

void GuiPlotPanelsTest::labelsTheTimeAxisWithClockTime() {
    TimeSeriesPanel panel;
    panel.resize(1000, 500);
    panel.show();
    QSignalSpy loaded(&panel, &TimeSeriesPanel::loaded);
    // 20 s of samples from 10:00:00.25 UTC: ticks fall on whole clock seconds, i.e. t = k + 0.75.
    Stream stream = bigStream(20000, 10);
    stream.info().attributes.insert(QStringLiteral("t0_utc"), QStringLiteral("2024-05-01T10:00:00.25Z"));
    panel.setStream(shared(std::move(stream)), QStringLiteral("watch/imu"));
    QVERIFY(loaded.wait(10000));
    QVERIFY(panel.canShowClockTime());
    QCPAxis* x = panel.laneRect(panel.laneCount() - 1)->axis(QCPAxis::atBottom);
    panel.plot()->replot();
    QVERIFY(!x->tickVectorLabels().isEmpty());
    QVERIFY(!x->tickVectorLabels().front().contains(QLatin1Char(':')));  // elapsed seconds first
    panel.setClockTime(true);
    panel.plot()->replot();
    QCOMPARE(x->label(), QStringLiteral("time of day (UTC)"));
    const QVector<double> ticks = x->tickVector();
    const QVector<QString> labels = x->tickVectorLabels();
    QVERIFY(ticks.size() >= 3);
    for (int i = 0; i < ticks.size(); ++i) {
        const double clock = ticks[i] + 0.25;  // seconds after 10:00:00
        QVERIFY2(std::abs(clock - std::round(clock)) < 1e-6, qPrintable(QString::number(ticks[i])));
        const int s = int(std::lround(clock));
        QCOMPARE(labels[i], QStringLiteral("10:00:%1").arg(s, 2, 10, QLatin1Char('0')));
    }
    // Zoomed into one second: milliseconds.
    panel.plot()->xAxis->setRange(5.0, 5.5);
    panel.plot()->replot();
    QVERIFY(x->tickVectorLabels().front().startsWith(QStringLiteral("10:00:05.")));
    // A stream without an absolute start cannot show clock time and falls back to seconds.
    panel.setStream(shared(bigStream(1000, 10)), QStringLiteral("plain"));
    QVERIFY(loaded.wait(10000));
    QVERIFY(!panel.canShowClockTime());
    panel.plot()->replot();
    QCOMPARE(panel.laneRect(panel.laneCount() - 1)->axis(QCPAxis::atBottom)->label(), QStringLiteral("t [s]"));
}

void GuiPlotPanelsTest::decimatesLargeStreamsWithoutLosingPeaks() {
    const std::size_t n = 2'000'000, spike = 1'234'567;
    TimeSeriesPanel panel;
    panel.resize(1200, 500);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setStream(shared(bigStream(n, spike)));
    panel.waitForLoad();
    QCustomPlot* plot = panel.plot();
    plot->replot();
    QCOMPARE(plot->graphCount(), 1);
    const int width = plot->axisRect()->width();
    QCOMPARE(panel.decimationWidth(), width);
    QCPGraph* graph = plot->graph(0);
    QVERIFY2(graph->dataCount() <= 2 * width + 2, qPrintable(QString::number(graph->dataCount())));
    QVERIFY(graph->dataCount() >= width);
    bool spikeShown = false;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it) spikeShown |= it->value == 100.0;
    QVERIFY(spikeShown);
    // Auto-fit y includes the spike at full range.
    QVERIFY(plot->yAxis->range().upper >= 100.0);

    // Zoomed to 100 samples around the spike: raw samples (+1 neighbour each side), with markers.
    const double t = 1e-3 * double(spike);
    plot->xAxis->setRange(t - 0.0495, t + 0.0505);
    QCOMPARE(graph->dataCount(), 100 + 2);
    QVERIFY(graph->scatterStyle().shape() != QCPScatterStyle::ssNone);
    QCOMPARE(graph->data()->at(1)->key, 1e-3 * double(spike - 49));

    // Zoomed away from the spike, auto-fit y follows the visible samples only.
    plot->xAxis->setRange(100.0, 110.0);
    QVERIFY(plot->yAxis->range().upper < 2.0);
    QVERIFY(graph->dataCount() <= 2 * width + 2);

    // Without auto-fit the y range stays where it is.
    panel.setAutoFitY(false);
    const QCPRange y = plot->yAxis->range();
    plot->xAxis->setRange(1000.0, 1200.0);
    QCOMPARE(plot->yAxis->range().lower, y.lower);
    QCOMPARE(plot->yAxis->range().upper, y.upper);

    panel.showFullRange();
    QCOMPARE(plot->xAxis->range().upper, 1e-3 * double(n - 1));
}

void GuiPlotPanelsTest::choosesColumns() {
    TimeSeriesPanel panel;
    panel.resize(800, 400);
    panel.setStream(shared(testing::makeImuStream()), QStringLiteral("run1/imu"), {QStringLiteral("gyr_x")});
    panel.waitForLoad();
    QCOMPARE(panel.plot()->graphCount(), 1);
    QCOMPARE(panel.plot()->graph(0)->name(), QStringLiteral("gyr_x [rad/s]"));
    QCOMPARE(panel.plot()->yAxis->label(), QStringLiteral("[rad/s]"));

    panel.setVisibleColumns({QStringLiteral("acc_x"), QStringLiteral("acc_z")});
    QCOMPARE(panel.plot()->graphCount(), 2);
    QCOMPARE(panel.visibleColumns(), QStringList({QStringLiteral("acc_x"), QStringLiteral("acc_z")}));
    QVERIFY(panel.plottedPointCount() > 0);

    panel.clear();
    QCOMPARE(panel.plot()->graphCount(), 0);
    QVERIFY(!panel.isLoading());
}

void GuiPlotPanelsTest::reportsLoadErrors() {
    StreamInfo info;
    info.name = QStringLiteral("broken");
    info.kind = QStringLiteral("imu");
    info.columns = {{"acc_x", "m/s^2"}};
    info.rows = 10;
    auto stream = std::make_shared<const Stream>(
        info, FileSource{QStringLiteral("/nonexistent.athlos"), QStringLiteral("/recordings/r/broken")},
        [] { return Expected<StreamData>(makeError(QStringLiteral("/nonexistent.athlos: cannot open"))); });
    TimeSeriesPanel panel;
    QSignalSpy failed(&panel, &TimeSeriesPanel::loadFailed);
    panel.setStream(stream);
    QVERIFY(failed.wait(10000) || failed.count() == 1);
    QVERIFY(panel.errorString().contains(QStringLiteral("cannot open")));
    QCOMPARE(panel.plot()->graphCount(), 0);
}

void GuiPlotPanelsTest::trajectoryHasEqualScalingAndMarkers() {
    TrajectoryPanel panel;
    panel.resize(1000, 500);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    Stream track = testing::makeTrackStream();
    const StreamData expected = *track.data().value();
    panel.setStream(shared(std::move(track)), QStringLiteral("run1/lps"));
    panel.waitForLoad();
    QCustomPlot* plot = panel.plot();
    plot->replot();
    QCOMPARE(panel.pointCount(), 800);
    QCOMPARE(plot->xAxis->label(), QStringLiteral("x [m]"));

    // Start and end markers sit on the first and last sample.
    QCOMPARE(plot->graph(0)->dataCount(), 1);
    QCOMPARE(plot->graph(0)->data()->at(0)->key, expected.at(0, 0));
    QCOMPARE(plot->graph(0)->data()->at(0)->value, expected.at(0, 1));
    QCOMPARE(plot->graph(1)->data()->at(0)->key, expected.at(799, 0));
    QCOMPARE(plot->graph(1)->data()->at(0)->value, expected.at(799, 1));

    // Equal scaling: metres per pixel are the same on both axes, and the whole track is visible.
    const QRect rect = plot->axisRect()->rect();
    const double sx = plot->xAxis->range().size() / rect.width();
    const double sy = plot->yAxis->range().size() / rect.height();
    QVERIFY2(std::abs(sx / sy - 1.0) < 0.01, qPrintable(QStringLiteral("%1 vs %2").arg(sx).arg(sy)));
    QVERIFY(plot->xAxis->range().lower < -79.0 && plot->xAxis->range().upper > 79.0);
    QVERIFY(plot->yAxis->range().lower < -36.8 && plot->yAxis->range().upper > 36.8);

    // Still equal after a resize.
    panel.resize(600, 700);
    QCoreApplication::processEvents();
    plot->replot();
    const QRect r2 = plot->axisRect()->rect();
    QVERIFY(std::abs((plot->xAxis->range().size() / r2.width()) / (plot->yAxis->range().size() / r2.height()) - 1.0) <
            0.01);
}

void GuiPlotPanelsTest::recognisesPositionStreams() {
    QVERIFY(TrajectoryPanel::isPositionStream(testing::makeTrackStream(5).info()));
    QVERIFY(!TrajectoryPanel::isPositionStream(testing::makeImuStream(5).info()));
    StreamInfo gnss;
    gnss.kind = QStringLiteral("gnss");
    gnss.columns = {{"lat", "deg"}, {"lon", "deg"}};
    QVERIFY(!TrajectoryPanel::isPositionStream(gnss));  // geodetic only: no x/y to draw
    gnss.columns.push_back({"x", "m"});
    gnss.columns.push_back({"y", "m"});
    QVERIFY(TrajectoryPanel::isPositionStream(gnss));
}

QTEST_MAIN(GuiPlotPanelsTest)
#include "GuiPlotPanelsTest.moc"
