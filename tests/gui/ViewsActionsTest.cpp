// Action timeline: one lane per class with counts and mean durations, manual vs predicted drawing,
// the window's cursor and visible range, click to move the cursor, the tool and the `actions`
// screenshot view.
#include "GuiTestSupport.h"

#include "ui/AnnotationEditor.h"
#include "ui/MainWindow.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/UiEntry.h"
#include "ui/views/ActionTimeline.h"
#include "ui/views/ActionsView.h"

#include <QDockWidget>
#include <QImage>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QtTest>

using namespace athlos;
using namespace athlos::ui;

namespace {

Annotation manual(const QString& label, double a, double b) {
    return {label, a, b, QString(), 1.0, QStringLiteral("manual")};
}

// 3 manual "jump" intervals of 0.5 s, 6 predicted "stride left" of 1.1 s, 2 instants "mark".
Annotations sampleAnnotations() {
    Annotations a;
    for (int k = 0; k < 3; ++k) a.push_back(manual("jump", 2.0 + 4.0 * k, 2.5 + 4.0 * k));
    for (int k = 0; k < 6; ++k)
        a.push_back({"stride left", 1.0 + 1.1 * k, 2.1 + 1.1 * k, "run1/gait", 0.2 + 0.1 * k, "gait-events"});
    a.push_back(manual("mark", 3.0, 3.0));
    a.push_back(manual("mark", 9.0, 9.0));
    return a;
}

bool isCursorRed(const QColor& c) { return c.red() > 180 && c.green() < 90 && c.blue() < 90; }

}  // namespace

class ViewsActionsTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
    }

    void oneLanePerClassWithCounts() {
        auto project = testing::makeProject(dir_.filePath("a.athlos"));
        project->annotationClasses() = QStringList{"stride left", "jump"};
        TimeController time;
        time.setBounds(0, 20);
        ActionTimeline timeline(&time);
        timeline.setAnnotations(sampleAnnotations(), project.get());
        // Project classes first in their order, then other labels.
        QCOMPARE(timeline.lanes(), (QStringList{"stride left", "jump", "mark"}));
        const auto* strides = timeline.statsFor("stride left");
        QVERIFY(strides);
        QCOMPARE(strides->count, 6);
        QCOMPARE(strides->predicted, 6);
        QVERIFY(std::abs(strides->meanDuration - 1.1) < 1e-9);
        QVERIFY(std::abs(strides->meanConfidence - 0.45) < 1e-9);
        QCOMPARE(timeline.statsFor("jump")->count, 3);
        QCOMPARE(timeline.statsFor("jump")->predicted, 0);
        QVERIFY(std::abs(timeline.statsFor("jump")->meanDuration - 0.5) < 1e-9);
        QCOMPARE(timeline.statsFor("mark")->count, 2);
        QCOMPARE(timeline.statsFor("mark")->meanDuration, 0.0);  // instants have no duration
        QVERIFY(!timeline.statsFor("other"));
        // Same colours as the annotation layer's rule: project classes by index.
        QCOMPARE(ActionTimeline::colorFor(project.get(), "jump"), ActionTimeline::colorFor(project.get(), "jump"));
        QVERIFY(ActionTimeline::colorFor(project.get(), "jump") !=
                ActionTimeline::colorFor(project.get(), "stride left"));
    }

    void manualSolidPredictedTranslucent() {
        TimeController time;
        time.setBounds(0, 20);
        time.setVisibleRange(0, 20);
        ActionTimeline timeline(&time);
        Annotations a{
            manual("x", 2.0, 6.0), {"x", 10.0, 14.0, "p", 0.1, "detector"}, {"x", 15.0, 19.0, "p", 1.0, "detector"}};
        timeline.setAnnotations(a);
        timeline.resize(900, 120);
        time.setCursor(0.0);
        const QImage image = timeline.grab().toImage();
        const int y = timeline.laneRect(0).center().y();
        const QColor base = ActionTimeline::colorFor(nullptr, "x");
        const QColor manual = image.pixelColor(timeline.xAt(4.0), y);
        QCOMPARE(manual.rgb(), base.rgb());  // solid
        // Predicted bars are blended with the background: the low-confidence one is paler than
        // the confident one (sum of channels closer to white), and neither equals the solid colour.
        auto lightness = [&](double t) {
            int sum = 0;
            for (int dx = -6; dx <= 6; ++dx) {
                const QColor c = image.pixelColor(timeline.xAt(t) + dx, y + 1);
                sum += c.red() + c.green() + c.blue();
            }
            return sum;
        };
        QVERIFY(lightness(12.0) > lightness(17.0));
        QVERIFY(image.pixelColor(timeline.xAt(12.0), y).rgb() != base.rgb());
    }

    void followsCursorAndVisibleRange() {
        TimeController time;
        time.setBounds(0, 20);
        ActionTimeline timeline(&time);
        timeline.setAnnotations(sampleAnnotations());
        timeline.resize(1000, 160);
        const QRect area = timeline.timeArea();
        time.setVisibleRange(5, 10);
        QCOMPARE(timeline.xAt(5), area.left());
        QVERIFY(std::abs(timeline.xAt(10) - (area.left() + area.width())) <= 1);
        time.setCursor(7.5);
        QImage image = timeline.grab().toImage();
        const int y = timeline.laneRect(0).top() + 2;
        QVERIFY(isCursorRed(image.pixelColor(timeline.xAt(7.5), y)));
        QVERIFY(!isCursorRed(image.pixelColor(timeline.xAt(6.5), y)));
        // The cursor moves, the drawing follows (signals, no manual refresh).
        time.setCursor(6.5);
        image = timeline.grab().toImage();
        QVERIFY(isCursorRed(image.pixelColor(timeline.xAt(6.5), y)));
        QVERIFY(!isCursorRed(image.pixelColor(timeline.xAt(7.5), y)));
        // Zoom: the same time maps elsewhere and the cursor outside the range is not drawn.
        time.setVisibleRange(0, 5);
        QVERIFY(timeline.xAt(5) >= area.right() - 1);
        image = timeline.grab().toImage();
        for (int x = area.left(); x <= area.right(); x += 3) QVERIFY(!isCursorRed(image.pixelColor(x, y)));
    }

    void clickMovesCursor() {
        TimeController time;
        time.setBounds(0, 20);
        time.setVisibleRange(4, 12);
        ActionTimeline timeline(&time);
        timeline.setAnnotations(sampleAnnotations());
        timeline.resize(1000, 160);
        timeline.show();
        QVERIFY(QTest::qWaitForWindowExposed(&timeline));
        const int x = timeline.xAt(9.0);
        QTest::mouseClick(&timeline, Qt::LeftButton, {}, QPoint(x, timeline.laneRect(1).center().y()));
        QVERIFY2(std::abs(time.cursor() - 9.0) < 0.02, qPrintable(QString::number(time.cursor())));
        // A click on the label column does not move it.
        QTest::mouseClick(&timeline, Qt::LeftButton, {}, QPoint(20, timeline.laneRect(0).center().y()));
        QVERIFY(std::abs(time.cursor() - 9.0) < 0.02);
    }

    void viewTableAndSourceStream() {
        auto project = testing::makeProject(dir_.filePath("b.athlos"));
        project->recording("run1")->annotations = sampleAnnotations();
        QJsonObject prov{{"processor", "gait-events"}, {"inputs", QJsonArray{QJsonObject{{"name", "run1/imu"}}}}};
        project->recording("run1")->metadata["annotation_provenance"] = QJsonObject{{"run1/gait", prov}};
        QCOMPARE(ActionsView::annotatedRecordings(*project), QStringList{"run1"});
        QCOMPARE(ActionsView::sourceStream(*project, "run1"), QStringLiteral("run1/imu"));
        TimeController time;
        ActionsView view(project.get(), &time);
        QCOMPARE(view.recording(), QStringLiteral("run1"));
        QCOMPARE(view.statsTable()->rowCount(), 3);
        bool found = false;
        for (int row = 0; row < 3; ++row)
            if (view.statsTable()->item(row, 0)->text() == "stride left") {
                QCOMPARE(view.statsTable()->item(row, 1)->text(), QStringLiteral("6"));
                QCOMPARE(view.statsTable()->item(row, 2)->text(), QStringLiteral("6"));
                QCOMPARE(view.statsTable()->item(row, 3)->text(), QStringLiteral("1.100"));
                found = true;
            }
        QVERIFY(found);
        // An edit shows after refresh().
        project->recording("run1")->annotations.push_back(manual("jump", 15, 15.5));
        view.refresh();
        QCOMPARE(view.timeline()->statsFor("jump")->count, 4);
        QVERIFY(!view.setRecording("nope").ok());
    }

    void reviewStepsAcceptsAndRejects() {
        MainWindow window;
        window.setInteractive(false);
        auto shared = std::shared_ptr<Project>(testing::makeProject(dir_.filePath("r.athlos")));
        shared->recording("run1")->annotations = sampleAnnotations();
        window.setProject(shared);
        window.timeController()->setBounds(0, 20);  // as when run1/imu is plotted
        window.timeController()->setVisibleRange(5, 10);
        ActionsView view(shared.get(), window.timeController());
        view.setEditor(window.annotationEditor());
        auto& all = shared->recording("run1")->annotations;
        QCOMPARE(view.reviewIndex(), -1);
        QVERIFY(!view.acceptCurrent().ok());
        QVERIFY(!view.reviewPrevious());
        QVERIFY(view.reviewNext());
        int current = view.reviewIndex();
        QVERIFY(current >= 0);
        QCOMPARE(all[std::size_t(current)].label, QStringLiteral("stride left"));
        QCOMPARE(all[std::size_t(current)].tStart, 1.0);  // the earliest predicted one
        QVERIFY2(std::abs(window.timeController()->cursor() - 1.55) < 1e-9,
                 qPrintable(QString::number(window.timeController()->cursor())));
        // The visible range moved to show it, keeping its span.
        QVERIFY(window.timeController()->visibleBegin() <= 1.0);
        QVERIFY(std::abs(window.timeController()->visibleEnd() - window.timeController()->visibleBegin() - 5.0) < 1e-6);
        QCOMPARE(view.timeline()->highlighted(), current);
        QVERIFY(view.reviewNext());
        QCOMPARE(all[std::size_t(view.reviewIndex())].tStart, 2.1);
        QVERIFY(view.reviewPrevious());
        QCOMPARE(all[std::size_t(view.reviewIndex())].tStart, 1.0);

        // Accept: becomes manual, the review moves on to the next predicted one.
        QVERIFY(view.acceptCurrent().ok());
        QCOMPARE(all[std::size_t(current)].source, QStringLiteral("manual"));
        QCOMPARE(view.timeline()->statsFor("stride left")->predicted, 5);
        QCOMPARE(all[std::size_t(view.reviewIndex())].tStart, 2.1);
        // Reject: deleted, review moves on; undo brings it back.
        const std::size_t before = all.size();
        QVERIFY(view.rejectCurrent().ok());
        QCOMPARE(all.size(), before - 1);
        QCOMPARE(view.timeline()->statsFor("stride left")->count, 5);
        QVERIFY(view.reviewIndex() >= 0);
        QVERIFY(std::abs(all[std::size_t(view.reviewIndex())].tStart - 3.2) < 1e-9);
        window.annotationEditor()->undoStack()->undo();
        QCOMPARE(all.size(), before);
        QCOMPARE(view.timeline()->statsFor("stride left")->count, 6);
    }

    void toolOpensDockAndScreenshotViewRenders() {
        const auto& tools = registeredTools();
        auto tool =
            std::find_if(tools.begin(), tools.end(), [](const ToolEntry& t) { return t.id == "action-timeline"; });
        QVERIFY(tool != tools.end());
        QCOMPARE(QByteArray(tool->menu), QByteArray("View"));

        auto project = testing::makeProject(dir_.filePath("c.athlos"));
        project->recording("run1")->annotations = sampleAnnotations();
        QVERIFY(project->save().ok());
        {
            MainWindow window;
            window.setInteractive(false);
            window.setProject(std::shared_ptr<Project>(Project::open(dir_.filePath("c.athlos")).value().release()));
            window.resize(1200, 800);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QAction* action = window.toolAction("action-timeline");
            QVERIFY(action);
            action->trigger();
            auto* dock = window.findChild<QDockWidget*>("actionTimelineDock");
            QVERIFY(dock);
            auto* view = qobject_cast<ActionsView*>(dock->widget());
            QVERIFY(view);
            QCOMPARE(view->timeline()->lanes().size(), 3);
            action->trigger();  // a second launch reuses the dock
            QCOMPARE(window.findChildren<QDockWidget*>("actionTimelineDock").size(), 1);
            // The timeline shares the window's cursor.
            window.timeController()->setCursor(3.25);
            QTest::mouseClick(view->timeline(), Qt::LeftButton, {},
                              QPoint(view->timeline()->xAt(window.timeController()->visibleBegin() + 1.0),
                                     view->timeline()->laneRect(0).center().y()));
            QVERIFY(std::abs(window.timeController()->cursor() - (window.timeController()->visibleBegin() + 1.0)) <
                    0.1);
        }
        QVERIFY(screenshotViews().contains("actions"));
        const QString png = dir_.filePath("actions.png");
        const Status status = renderScreenshot(dir_.filePath("c.athlos"), "actions", png, QSize(1280, 800));
        QVERIFY2(status.ok(), status.ok() ? "" : qPrintable(status.message()));
        const QImage image(png);
        QCOMPARE(image.size(), QSize(1280, 800));
        // No annotations at all: a clear error instead of an empty picture.
        auto empty = testing::makeProject(dir_.filePath("d.athlos"));
        QVERIFY(empty->save().ok());
        QVERIFY(!renderScreenshot(dir_.filePath("d.athlos"), "actions", dir_.filePath("d.png"), QSize(1280, 800)).ok());
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(ViewsActionsTest)
#include "ViewsActionsTest.moc"
