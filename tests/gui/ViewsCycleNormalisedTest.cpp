// Cycle-normalised curves: mean ± SD over annotated cycles resampled to 0–100 % (double turns to
// 0–200 %), the labels offered, the plot, and the tool and screenshot registration.
#include "GuiTestSupport.h"

#include "ui/MainWindow.h"
#include "ui/ToolRegistry.h"
#include "ui/views/CycleNormalisedView.h"

#include <QDockWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>
#include <cmath>
#include <numbers>

using namespace athlos;
using namespace athlos::ui;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Cycles of 1.0, 1.5, 2.0 s with amplitudes 1, 2, 3: v = A_k sin(2π (t − a_k) / T_k), annotated "xc cycle";
// and the same intervals alternately "turn left" / "turn right".
void addCycles(Project& project) {
    const double starts[4] = {1.0, 2.0, 3.5, 5.5};
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.columns = {{"gyr_y", "rad/s"}};
    const std::size_t n = 700;
    StreamData d(n, 1);
    for (std::size_t i = 0; i < n; ++i) {
        const double t = 0.01 * double(i);
        d.t[i] = t;
        for (int k = 0; k < 3; ++k)
            if (t >= starts[k] && t < starts[k + 1])
                d.at(i, 0) = double(k + 1) * std::sin(kTwoPi * (t - starts[k]) / (starts[k + 1] - starts[k]));
    }
    project.putStream(QStringLiteral("xc/ski"), Stream(info, d));
    Recording& rec = project.recordings()[QStringLiteral("xc")];
    for (int k = 0; k < 3; ++k) {
        Annotation a;
        a.label = QStringLiteral("xc cycle");
        a.tStart = starts[k];
        a.tEnd = starts[k + 1];
        rec.annotations.push_back(a);
        a.label = k % 2 ? QStringLiteral("turn right") : QStringLiteral("turn left");
        rec.annotations.push_back(a);
    }
}

}  // namespace

class ViewsCycleNormalisedTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
    }

    void meanAndSdOverCycles() {
        auto project = testing::makeProject(dir_.filePath("a.athlos"));
        addCycles(*project);
        const Recording* rec = project->recording(QStringLiteral("xc"));
        const QStringList labels = CycleNormalisedView::cycleLabels(rec->annotations);
        QCOMPARE(labels.front(), QString::fromLatin1(CycleNormalisedView::kDoubleTurn));
        QVERIFY(labels.contains(QStringLiteral("xc cycle")));
        QVERIFY(!labels.contains(QStringLiteral("turn right")));  // a single right turn is not a set of cycles

        CycleNormalisedView view(project.get());
        QVERIFY(!view.show("xc", "xc/ski", "gyr_x", "xc cycle").ok());
        QVERIFY(view.show("xc", "xc/ski", "gyr_y", "xc cycle").ok());
        const NormalisedCurves& c = view.curves();
        QCOMPARE(c.cycles, 3);
        QCOMPARE(c.percent.size(), std::size_t(101));
        // At 25 %: sin = 1, amplitudes 1, 2, 3 → mean 2, SD 1 (linear interpolation of 100 Hz samples).
        QVERIFY2(std::abs(c.mean[25] - 2.0) < 0.01, qPrintable(QString::number(c.mean[25])));
        QVERIFY2(std::abs(c.sd[25] - 1.0) < 0.01, qPrintable(QString::number(c.sd[25])));
        QVERIFY(std::abs(c.mean[50]) < 0.05);
        QCOMPARE(view.plot()->graphCount(), 3);  // band upper, band lower, mean

        // A double turn: left 1.0–2.0 s joined to right 2.0–3.5 s is 0–200 %.
        const auto doubles = CycleNormalisedView::cyclesOf(rec->annotations, CycleNormalisedView::kDoubleTurn);
        QCOMPARE(doubles.size(), std::size_t(1));
        QCOMPARE(doubles.front().first, 1.0);
        QCOMPARE(doubles.front().second, 3.5);
        QVERIFY(view.show("xc", "xc/ski", "gyr_y", CycleNormalisedView::kDoubleTurn).ok());
        QCOMPARE(view.curves().percent.back(), 200.0);
        QCOMPARE(view.plot()->xAxis->range().upper, 200.0);
    }

    void registeredAsToolAndScreenshotView() {
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(),
                            [](const ToolEntry& t) { return t.id == "cycle-normalised-view"; }));
        const auto& views = registeredViews();
        auto it =
            std::find_if(views.begin(), views.end(), [](const ViewEntry& v) { return v.name == "cycle-normalised"; });
        QVERIFY(it != views.end());
        MainWindow window;
        window.setInteractive(false);
        window.resize(1280, 800);
        auto shared = std::shared_ptr<Project>(testing::makeProject(dir_.filePath("b.athlos")));
        window.setProject(shared);
        QVERIFY(!it->prepare(window).ok());
        addCycles(*shared);
        const Status status = it->prepare(window);
        QVERIFY2(status.ok(), status.ok() ? "" : qPrintable(status.message()));
        auto* dock = window.findChild<QDockWidget*>("cycleNormalisedDock");
        QVERIFY(dock);
        QCOMPARE(dock->findChild<CycleNormalisedView*>()->curves().cycles, 1);  // the double turn comes first
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(ViewsCycleNormalisedTest)
#include "ViewsCycleNormalisedTest.moc"
