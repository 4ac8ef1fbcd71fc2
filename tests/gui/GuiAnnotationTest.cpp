// The annotation tool: create (also by Shift+drag on the plot), edit, delete, undo/redo, review;
// save and reopen gives identical annotations; a crash (no save) loses nothing because the
// journal is replayed on open.
#include "GuiTestSupport.h"
#include "core/model/AnnotationJournal.h"
#include "ui/AnnotationEditor.h"
#include "ui/AnnotationLayer.h"
#include "ui/AnnotationPanel.h"
#include "ui/MainWindow.h"
#include "ui/TimeSeriesPanel.h"

#include <QTemporaryDir>
#include <QSignalSpy>
#include <QUndoStack>
#include <QtTest>
#include <qcustomplot.h>

using namespace athlos;
using namespace athlos::ui;

class GuiAnnotationTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void editUndoRedoSaveReopen();
    void journalReplaysAfterCrash();
    void shiftDragCreatesAndDeleteRemoves();
    void reviewAcceptsAndRejects();
    void replacedByAProcessorDropsUndo();
    void processorAnnotationsAreJournaled();
    void autosaveWritesTheFileAndDropsTheJournal();
    void editsRoundTripThroughJson();

private:
    QString saveProject(const QString& name, const QStringList& classes = {"run", "walk"});
    Annotations annotationsOf(const QString& path, const QString& recording);
    QTemporaryDir dir_;
};

void GuiAnnotationTest::initTestCase() {
    QVERIFY(dir_.isValid());
    testing::isolateSettings(dir_.filePath(QStringLiteral("settings")));
    AnnotationEditor::setAnnotator(QStringLiteral("tester"));
}

QString GuiAnnotationTest::saveProject(const QString& name, const QStringList& classes) {
    const QString path = dir_.filePath(name);
    auto project = testing::makeProject(path);
    project->annotationClasses() = classes;
    return project->save() ? path : QString();
}

Annotations GuiAnnotationTest::annotationsOf(const QString& path, const QString& recording) {
    auto project = Project::open(path);
    if (!project) return {};
    const Recording* rec = (*project)->recording(recording);
    return rec ? rec->annotations : Annotations{};
}

void GuiAnnotationTest::editUndoRedoSaveReopen() {
    const QString path = saveProject(QStringLiteral("undo.athlos"));
    QVERIFY(!path.isEmpty());
    MainWindow window;
    window.setInteractive(false);
    QVERIFY(window.openProject(path));
    AnnotationEditor* editor = window.annotationEditor();
    const QString rec = QStringLiteral("run1");

    editor->setCurrentClass(QStringLiteral("walk"));
    QVERIFY(editor->create(rec, 5.0, 7.0));
    QVERIFY(editor->selectClassByNumber(0));
    QCOMPARE(editor->currentClass(), QStringLiteral("run"));
    auto second = editor->create(rec, 2.0, 3.0);
    QVERIFY(second);
    QCOMPARE(*second, 0);  // sorted by start
    Annotations& list = window.project()->recording(rec)->annotations;
    QCOMPARE(int(list.size()), 2);
    QCOMPARE(list[0].label, QStringLiteral("run"));
    QCOMPARE(list[0].annotator, QStringLiteral("tester"));
    QVERIFY(window.isWindowModified());

    Annotation moved = list[1];
    moved.tEnd = 8.5;
    QVERIFY(editor->change(rec, 1, moved));
    QCOMPARE(list[1].tEnd, 8.5);
    QVERIFY(editor->remove(rec, 0));
    QCOMPARE(int(list.size()), 1);

    QUndoStack* stack = editor->undoStack();
    QCOMPARE(stack->count(), 4);
    stack->undo();  // delete
    QCOMPARE(int(list.size()), 2);
    stack->undo();  // edit
    QCOMPARE(list[1].tEnd, 7.0);
    stack->redo();
    QCOMPARE(list[1].tEnd, 8.5);
    const Annotations expected = list;

    QVERIFY(window.saveProject());
    QVERIFY(!QFileInfo::exists(AnnotationJournal::pathFor(path)));  // the save has it all
    QCOMPARE(annotationsOf(path, rec), expected);

    // One writer per project: the first window lets go of it before the second opens it.
    window.setProject(nullptr);
    MainWindow reopened;
    reopened.setInteractive(false);
    QVERIFY(reopened.openProject(path));
    QCOMPARE(reopened.project()->recording(rec)->annotations, expected);
    QCOMPARE(reopened.project()->annotationClasses(), (QStringList{"run", "walk"}));
}

void GuiAnnotationTest::journalReplaysAfterCrash() {
    const QString path = saveProject(QStringLiteral("crash.athlos"));
    QVERIFY(!path.isEmpty());
    Annotations expected;
    {
        MainWindow window;
        window.setInteractive(false);
        window.setAutosaveDelay(0);
        QVERIFY(window.openProject(path));
        AnnotationEditor* editor = window.annotationEditor();
        QVERIFY(editor->addClass(QStringLiteral("jump")));
        editor->setCurrentClass(QStringLiteral("jump"));
        QVERIFY(editor->create(QStringLiteral("run1"), 1.0, 1.5));
        QVERIFY(editor->create(QStringLiteral("run1"), 4.0, 6.0));
        QVERIFY(editor->remove(QStringLiteral("run1"), 0));
        editor->undoStack()->undo();
        expected = window.project()->recording(QStringLiteral("run1"))->annotations;
        QCOMPARE(int(expected.size()), 2);
        // "Crash": the window goes away without saving (non-interactive: nobody is asked).
    }
    QVERIFY(annotationsOf(path, QStringLiteral("run1")).empty());  // the file never got them
    QVERIFY(AnnotationJournal::hasPendingEdits(path));

    MainWindow window;
    window.setInteractive(false);
    QVERIFY(window.openProject(path));
    QCOMPARE(window.project()->recording(QStringLiteral("run1"))->annotations, expected);
    QVERIFY(window.project()->annotationClasses().contains(QStringLiteral("jump")));
    QVERIFY(window.project()->isModified());
    QVERIFY(window.saveProject());
    QVERIFY(!AnnotationJournal::hasPendingEdits(path));
    QCOMPARE(annotationsOf(path, QStringLiteral("run1")), expected);

    // A torn last line (killed while writing) is ignored, earlier lines still count.
    const QString journal = AnnotationJournal::pathFor(path);
    QFile file(journal);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(
        QJsonDocument(AnnotationEdit::addClass(QStringLiteral("sprint")).toJson()).toJson(QJsonDocument::Compact) +
        "\n");
    file.write("{\"op\":\"insert\",\"rec\":\"ru");
    file.close();
    auto edits = AnnotationJournal::read(journal);
    QVERIFY(edits);
    QCOMPARE(int(edits->size()), 1);
}

void GuiAnnotationTest::shiftDragCreatesAndDeleteRemoves() {
    const QString path = saveProject(QStringLiteral("mouse.athlos"));
    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&window));
    QVERIFY(window.openProject(path));
    QVERIFY(window.selectItem(QStringLiteral("run1/imu")));
    window.showTimeSeriesView();
    window.waitForPlots();
    QCOMPARE(window.annotationLayer()->recording(), QStringLiteral("run1"));

    QCustomPlot* plot = window.timeSeriesPanel()->plot();
    const QRect area = plot->axisRect()->rect();
    const QPoint from(area.left() + area.width() / 4, area.center().y());
    const QPoint to(area.left() + area.width() / 2, area.center().y());
    const double t0 = plot->xAxis->pixelToCoord(from.x()), t1 = plot->xAxis->pixelToCoord(to.x());
    const QCPRange rangeBefore = plot->xAxis->range();
    QTest::mousePress(plot, Qt::LeftButton, Qt::ShiftModifier, from);
    QTest::mouseMove(plot, to);
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::ShiftModifier, to);

    const Annotations& list = window.project()->recording(QStringLiteral("run1"))->annotations;
    QCOMPARE(int(list.size()), 1);
    QCOMPARE(list[0].label, QStringLiteral("run"));
    QVERIFY(std::abs(list[0].tStart - t0) < 1e-9 && std::abs(list[0].tEnd - t1) < 1e-9);
    QCOMPARE(plot->xAxis->range(), rangeBefore);  // the drag annotated, it did not pan
    QCOMPARE(window.annotationLayer()->spanCount(), 1);
    QCOMPARE(window.annotationLayer()->selected(), 0);
    // acc and gyr are stacked lanes: the span shades the gyr lane too, over the same interval.
    QCOMPARE(plot->axisRectCount(), 2);
    QCOMPARE(int(window.annotationLayer()->shades(0).size()), 1);
    QCPItemRect* shade = window.annotationLayer()->shades(0).front();
    QCOMPARE(shade->clipAxisRect(), plot->axisRect(1));
    QVERIFY(std::abs(shade->topLeft->coords().x() - t0) < 1e-9 &&
            std::abs(shade->bottomRight->coords().x() - t1) < 1e-9);

    // Dragging the end edge moves it, in the lower lane as well.
    const QRect lower = plot->axisRect(1)->rect();
    const QPoint edge(int(plot->xAxis->coordToPixel(t1)), lower.center().y());
    const QPoint further(area.left() + 3 * area.width() / 4, lower.center().y());
    QTest::mousePress(plot, Qt::LeftButton, Qt::ShiftModifier, edge);
    QTest::mouseMove(plot, further);
    QTest::mouseRelease(plot, Qt::LeftButton, Qt::ShiftModifier, further);
    QCOMPARE(int(list.size()), 1);
    QVERIFY(std::abs(list[0].tEnd - plot->xAxis->pixelToCoord(further.x())) < 1e-9);
    QVERIFY(std::abs(list[0].tStart - t0) < 1e-9);

    // Number keys pick the class, Delete removes the selected span, Ctrl+Z brings it back.
    window.timeSeriesPanel()->setFocus();
    QTest::keyClick(window.timeSeriesPanel(), Qt::Key_2);
    QCOMPARE(window.annotationEditor()->currentClass(), QStringLiteral("walk"));
    QTest::keyClick(window.timeSeriesPanel(), Qt::Key_Delete);
    QCOMPARE(int(list.size()), 0);
    QCOMPARE(window.annotationLayer()->spanCount(), 0);
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
    QCOMPARE(int(list.size()), 1);
    QCOMPARE(window.annotationLayer()->spanCount(), 1);
    QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
    QCOMPARE(int(list.size()), 0);
}

void GuiAnnotationTest::reviewAcceptsAndRejects() {
    const QString path = dir_.filePath(QStringLiteral("review.athlos"));
    {
        auto project = testing::makeProject(path);
        project->annotationClasses() = {QStringLiteral("stride")};
        Annotations& list = project->recording(QStringLiteral("run1"))->annotations;
        list.push_back({QStringLiteral("stride"), 1.0, 2.0, QStringLiteral("someone"), 1.0, QStringLiteral("manual")});
        list.push_back({QStringLiteral("stride"), 3.0, 4.0, {}, 0.8, QStringLiteral("stride-detector")});
        list.push_back({QStringLiteral("stride"), 5.0, 6.0, {}, 0.4, QStringLiteral("stride-detector")});
        QVERIFY(project->save());
    }
    MainWindow window;
    window.setInteractive(false);
    QVERIFY(window.openProject(path));
    QVERIFY(window.selectItem(QStringLiteral("run1/imu")));
    AnnotationPanel* panel = window.annotationPanel();
    QVERIFY(panel->reviewNext());
    QCOMPARE(window.annotationLayer()->selected(), 1);
    panel->acceptSelected();  // and moves on to the next one to review
    const Annotations& list = window.project()->recording(QStringLiteral("run1"))->annotations;
    QCOMPARE(list[1].source, QStringLiteral("manual"));
    QCOMPARE(list[1].annotator, QStringLiteral("tester"));
    QCOMPARE(window.annotationLayer()->selected(), 2);
    panel->rejectSelected();
    QCOMPARE(int(list.size()), 2);
    QVERIFY(!panel->reviewNext());  // nothing left

    window.annotationEditor()->undoStack()->undo();
    QCOMPARE(int(list.size()), 3);
    window.annotationEditor()->undoStack()->undo();
    QCOMPARE(list[1].source, QStringLiteral("stride-detector"));
}

// A processor run that writes annotations (ProcessorLauncher) leaves undo steps that index the old
// list: they must go, and the views must hear about the change.
void GuiAnnotationTest::replacedByAProcessorDropsUndo() {
    const QString path = saveProject(QStringLiteral("replaced.athlos"));
    QVERIFY(!path.isEmpty());
    MainWindow window;
    window.setInteractive(false);
    QVERIFY(window.openProject(path));
    AnnotationEditor* editor = window.annotationEditor();
    editor->setCurrentClass(QStringLiteral("walk"));
    QVERIFY(editor->create(QStringLiteral("run1"), 5.0, 7.0));
    QCOMPARE(editor->undoStack()->count(), 1);
    QSignalSpy changed(editor, &AnnotationEditor::annotationsChanged);
    const QByteArray digest = AnnotationJournal::stateDigest(*window.project());
    std::map<QString, Annotations> before{
        {QStringLiteral("run1"), window.project()->recording(QStringLiteral("run1"))->annotations}};
    editor->annotationsReplaced({QStringLiteral("run1")}, before, digest);
    QCOMPARE(editor->undoStack()->count(), 0);
    QCOMPARE(changed.count(), 1);
    QCOMPARE(changed.front().front().toString(), QStringLiteral("run1"));
}

// Annotations a processor run wrote in the GUI are journaled like manual edits: after a crash the
// journal brings them back onto the file as it was last saved.
void GuiAnnotationTest::processorAnnotationsAreJournaled() {
    const QString path = saveProject(QStringLiteral("journaled.athlos"));
    QVERIFY(!path.isEmpty());
    Annotations predicted;
    {
        MainWindow window;
        window.setInteractive(false);
        window.setAutosaveDelay(0);
        QVERIFY(window.openProject(path));
        Project* project = window.project();
        const QByteArray digest = AnnotationJournal::stateDigest(*project);
        std::map<QString, Annotations> before{
            {QStringLiteral("run1"), project->recording(QStringLiteral("run1"))->annotations}};
        // What runProcessor does with an annotation output: replace the predicted ones.
        Annotations& list = project->recording(QStringLiteral("run1"))->annotations;
        list.push_back(
            {QStringLiteral("stride"), 1.0, 1.5, QStringLiteral("run1/strides"), 0.75, QStringLiteral("gait-events")});
        list.push_back(
            {QStringLiteral("stride"), 1.5, 2.0, QStringLiteral("run1/strides"), 0.5, QStringLiteral("gait-events")});
        predicted = list;
        window.annotationEditor()->annotationsReplaced({QStringLiteral("run1")}, before, digest);
        QVERIFY(AnnotationJournal::hasPendingEdits(path));
        window.project()->setModified(false);  // "crash": leave without saving
    }
    auto reopened = Project::open(path);
    QVERIFY(reopened);
    QVERIFY(AnnotationJournal::belongsTo(**reopened));
    auto replayed = AnnotationJournal::replay(**reopened);
    QVERIFY2(replayed, qPrintable(replayed ? QString() : replayed.message()));
    QCOMPARE(*replayed, 1);
    QVERIFY((*reopened)->recording(QStringLiteral("run1"))->annotations == predicted);
}

void GuiAnnotationTest::autosaveWritesTheFileAndDropsTheJournal() {
    const QString path = saveProject(QStringLiteral("autosave.athlos"));
    MainWindow window;
    window.setInteractive(false);
    window.setAutosaveDelay(50);
    QVERIFY(window.openProject(path));
    QVERIFY(window.annotationEditor()->create(QStringLiteral("run1"), 1.0, 2.0));
    QVERIFY(AnnotationJournal::hasPendingEdits(path));
    // After the idle delay the project is saved in the background; the window never went busy.
    QTRY_VERIFY_WITH_TIMEOUT(!window.project()->isModified(), 5000);
    QVERIFY(!QFileInfo::exists(AnnotationJournal::pathFor(path)));
    QCOMPARE(int(annotationsOf(path, QStringLiteral("run1")).size()), 1);
    QVERIFY(!window.isWindowModified());
    // Undo after the save journals the inverse, which fits the saved file.
    window.annotationEditor()->undoStack()->undo();
    auto edits = AnnotationJournal::read(AnnotationJournal::pathFor(path));
    QVERIFY(edits);
    QCOMPARE(int(edits->size()), 1);
    QCOMPARE(edits->front().kind, AnnotationEdit::Kind::Remove);
}

void GuiAnnotationTest::editsRoundTripThroughJson() {
    const Annotation a{QStringLiteral("run"), 0.1 + 0.2, 1.0 / 3.0, QStringLiteral("ä"), 0.75, QStringLiteral("x")};
    const Annotation b{QStringLiteral("walk"), 2.0, 3.0, QStringLiteral("b"), 1.0, QStringLiteral("manual")};
    for (const AnnotationEdit& edit :
         {AnnotationEdit::insert(QStringLiteral("r"), 2, a), AnnotationEdit::replace(QStringLiteral("r"), 1, a, b),
          AnnotationEdit::remove(QStringLiteral("r"), 0, b), AnnotationEdit::addClass(QStringLiteral("c"))}) {
        const QByteArray line = QJsonDocument(edit.toJson()).toJson(QJsonDocument::Compact);
        auto back = AnnotationEdit::fromJson(QJsonDocument::fromJson(line).object());
        QVERIFY(back);
        QVERIFY(*back == edit);
    }
}

QTEST_MAIN(GuiAnnotationTest)
#include "GuiAnnotationTest.moc"
