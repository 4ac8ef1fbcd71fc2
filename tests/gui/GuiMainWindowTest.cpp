// The main window over a real project file: open, tree, plotting on selection, recent files,
// all-or-nothing import (also by drag and drop), title with '*', save and reopen.
#include "GuiTestSupport.h"
#include "ui/MainWindow.h"
#include "ui/ProjectTreeModel.h"
#include "ui/RecentProjects.h"
#include "ui/TimeSeriesPanel.h"
#include "ui/TrajectoryPanel.h"
#include "ui/UiEntry.h"

#include <QMimeData>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTextBrowser>
#include <QTreeView>
#include <QtTest>
#include <qcustomplot.h>

using namespace athlos;
using namespace athlos::ui;

namespace {

QString writeFile(const QString& path, const QByteArray& content) {
    QFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return {};
    file.write(content);
    return path;
}

}  // namespace

class GuiMainWindowTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase();
    void opensProjectAndPlotsSelection();
    void importIsAllOrNothing();
    void dropImportsAndSaveKeepsIt();
    void newProjectAndSaveAs();
    void openErrorsAreReported();
    void importsSharedRecordings();
    void versionsNameEveryLibrary();

private:
    QString saveDemoProject(const QString& name);
    QTemporaryDir dir_;
};

void GuiMainWindowTest::initTestCase() {
    QVERIFY(dir_.isValid());
    testing::isolateSettings(dir_.filePath(QStringLiteral("settings")));
    RecentProjects::clear();
}

QString GuiMainWindowTest::saveDemoProject(const QString& name) {
    const QString path = dir_.filePath(name);
    auto project = testing::makeProject(path);
    const Status saved = project->save();
    if (!saved) qWarning("save failed: %s", qPrintable(saved.message()));
    return saved ? path : QString();
}

void GuiMainWindowTest::opensProjectAndPlotsSelection() {
    const QString path = saveDemoProject(QStringLiteral("demo.athlos"));
    QVERIFY(!path.isEmpty());

    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.show();
    QVERIFY(window.openProject(path));
    QVERIFY(window.windowTitle().startsWith(QStringLiteral("demo")));
    QVERIFY(!window.isWindowModified());
    QCOMPARE(RecentProjects::list().value(0), QFileInfo(path).absoluteFilePath());

    ProjectTreeModel* model = window.treeModel();
    QCOMPARE(model->rowCount(), 2);
    QCOMPARE(model->rowCount(model->indexOf(QStringLiteral("run1"))), 3);

    // Opening shows the data at once: the first stream is selected and plotted, in stacked lanes.
    window.waitForPlots();
    QCOMPARE(window.timeSeriesPanel()->title(), window.firstStream());
    QVERIFY(window.timeSeriesPanel()->plot()->graphCount() > 0);

    // Selecting a stream plots it (samples load lazily from the file on a worker).
    QVERIFY(window.selectItem(QStringLiteral("run1/imu")));
    window.waitForPlots();
    TimeSeriesPanel* series = window.timeSeriesPanel();
    QCOMPARE(series->title(), QStringLiteral("run1/imu"));
    QCOMPARE(series->plot()->graphCount(), 6);
    QVERIFY(series->plottedPointCount() > 6 * 100);
    QVERIFY(window.detailsView()->toPlainText().contains(QStringLiteral("run1/imu")));

    // A position stream also goes to the trajectory panel.
    QVERIFY(window.selectItem(QStringLiteral("run1/lps")));
    window.waitForPlots();
    QCOMPARE(window.trajectoryPanel()->pointCount(), 800);
    QCOMPARE(series->plot()->graphCount(), 3);
    QCOMPARE(window.firstPositionStream(), QStringLiteral("run1/lps"));
    QCOMPARE(window.firstStream(), QStringLiteral("run1/imu"));

    // Tables and recordings show details but do not replace the plot.
    QVERIFY(window.selectItem(QStringLiteral("run1/beacons")));
    QVERIFY(window.detailsView()->toPlainText().contains(QStringLiteral("beacons")));
    QCOMPARE(series->title(), QStringLiteral("run1/lps"));

    // Provenance of a result in the details pane.
    QVERIFY(window.selectItem(QStringLiteral("run2/imu-filtered")));
    QVERIFY(window.detailsView()->toPlainText().contains(QStringLiteral("butterworth 1.0")));
}

void GuiMainWindowTest::importIsAllOrNothing() {
    const QString path = saveDemoProject(QStringLiteral("import.athlos"));
    QVERIFY(!path.isEmpty());
    const QString good = writeFile(dir_.filePath(QStringLiteral("good.csv")), "t,x,y\n0,1,2\n0.1,1.5,2.5\n0.2,2,3\n");
    const QString bad = writeFile(dir_.filePath(QStringLiteral("bad.csv")), "t,x,y\n0,1,2\n0.1,1.5,2.5\n0.2,oops,3\n");

    MainWindow window;
    window.setInteractive(false);
    QVERIFY(window.openProject(path));
    const QStringList before = window.project()->streamPaths();
    QSignalSpy errors(&window, &MainWindow::errorReported);

    QVERIFY(!window.importFiles({good, bad}));
    QCOMPARE(errors.count(), 1);
    const QString message = errors.at(0).at(0).toString();
    QVERIFY2(message.contains(QStringLiteral("bad.csv")) && message.contains(QStringLiteral(":4")),
             qPrintable(message));
    QCOMPARE(window.project()->streamPaths(), before);
    QVERIFY(!window.project()->isModified());
    QVERIFY(!window.isWindowModified());

    // A name that exists already: refused as a whole, too.
    QVERIFY(window.importFiles({good}));
    QVERIFY(!window.importFiles({good}));
    QCOMPARE(errors.count(), 2);
    QVERIFY(errors.at(1).at(0).toString().contains(QStringLiteral("good/lps")));
}

void GuiMainWindowTest::dropImportsAndSaveKeepsIt() {
    const QString path = saveDemoProject(QStringLiteral("drop.athlos"));
    QVERIFY(!path.isEmpty());
    const QString csv =
        writeFile(dir_.filePath(QStringLiteral("sprint.csv")), "t,x,y\n0,0,0\n0.5,3,0.1\n1,7,0.2\n1.5,11,0.2\n");
    MainWindow window;
    window.setInteractive(false);
    window.show();
    QVERIFY(window.openProject(path));

    QMimeData mime;
    mime.setUrls({QUrl::fromLocalFile(csv)});
    QDragEnterEvent enter(QPoint(600, 400), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&window, &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(QPointF(600, 400), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(&window, &drop);
    QTRY_VERIFY(window.project()->stream(QStringLiteral("sprint/lps")) != nullptr);
    QVERIFY(window.isWindowModified());
    QCOMPARE(window.currentItem(), QStringLiteral("sprint/lps"));
    window.waitForPlots();
    QCOMPARE(window.trajectoryPanel()->pointCount(), 4);

    QVERIFY(window.saveProject());
    QVERIFY(!window.isWindowModified());
    auto reopened = Project::open(path);
    QVERIFY2(reopened.ok(), reopened.ok() ? "" : qPrintable(reopened.message()));
    const Stream* stream = reopened.value()->stream(QStringLiteral("sprint/lps"));
    QVERIFY(stream);
    QCOMPARE(stream->info().rows, 4);
    QCOMPARE(stream->data().value()->at(3, 0), 11.0);
}

void GuiMainWindowTest::newProjectAndSaveAs() {
    MainWindow window;
    window.setInteractive(false);
    const QString created = dir_.filePath(QStringLiteral("fresh.athlos"));
    QVERIFY(window.newProject(created));
    QVERIFY(QFileInfo::exists(created));
    QVERIFY(!window.isWindowModified());
    QCOMPARE(window.treeModel()->rowCount(), 0);

    window.project()->putStream(QStringLiteral("r/imu"), testing::makeImuStream(50));
    const QString copy = dir_.filePath(QStringLiteral("copy.athlos"));
    QVERIFY(window.saveProjectAs(copy));
    QVERIFY(window.windowTitle().startsWith(QStringLiteral("copy")));
    QCOMPARE(RecentProjects::list().value(0), QFileInfo(copy).absoluteFilePath());
    auto reopened = Project::open(copy);
    QVERIFY(reopened.ok());
    QVERIFY(reopened.value()->stream(QStringLiteral("r/imu")));
    QVERIFY(RecentProjects::list().size() <= RecentProjects::kMaxEntries);
}

void GuiMainWindowTest::openErrorsAreReported() {
    MainWindow window;
    window.setInteractive(false);
    QSignalSpy errors(&window, &MainWindow::errorReported);
    const QString notAProject = writeFile(dir_.filePath(QStringLiteral("notes.athlos")), "just text");
    QVERIFY(!window.openProject(notAProject));
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.at(0).at(0).toString().contains(QStringLiteral("notes.athlos")));
    QVERIFY(window.project() == nullptr);
    QVERIFY(!window.importFiles({notAProject}));  // no project open
}

void GuiMainWindowTest::importsSharedRecordings() {
    const QString broad = QStringLiteral(ATHLOS_SHARED_DATA_DIR "/broad/02_undisturbed_slow_rotation_B.hdf5");
    const QString gaitmap = QStringLiteral(ATHLOS_SHARED_DATA_DIR "/gaitmap/imu_sample_ic_stride.csv");
    if (!QFileInfo::exists(broad) || !QFileInfo::exists(gaitmap)) QSKIP("shared recordings not available");
    MainWindow window;
    window.setInteractive(false);
    window.resize(1280, 800);
    window.show();
    QVERIFY(window.newProject(dir_.filePath(QStringLiteral("shared.athlos"))));
    QSignalSpy errors(&window, &MainWindow::errorReported);
    QVERIFY2(window.importFiles({broad, gaitmap}), errors.isEmpty() ? "" : qPrintable(errors.at(0).at(0).toString()));
    QStringList recordings = window.project()->recordingNames();
    QVERIFY2(recordings.contains(QStringLiteral("02_undisturbed_slow_rotation_B")), qPrintable(recordings.join(',')));
    QVERIFY(recordings.contains(QStringLiteral("imu_sample_ic_stride")));
    QVERIFY(window.isWindowModified());

    // The first imported stream is selected and plotted.
    window.waitForPlots();
    QVERIFY(window.currentItem().startsWith(QStringLiteral("02_undisturbed_slow_rotation_B/")));
    QVERIFY(window.timeSeriesPanel()->plot()->graphCount() > 0);
    QVERIFY(window.timeSeriesPanel()->plottedPointCount() > 100);
    QVERIFY(window.saveProject());
}

void GuiMainWindowTest::versionsNameEveryLibrary() {
    const QString versions = ui::libraryVersions();
    for (const char* library : {"Athlos", "Qt", "Eigen", "Ceres", "OpenCV", "HDF5", "QCustomPlot 2.1"})
        QVERIFY2(versions.contains(QLatin1String(library)), library);
}

QTEST_MAIN(GuiMainWindowTest)
#include "GuiMainWindowTest.moc"
