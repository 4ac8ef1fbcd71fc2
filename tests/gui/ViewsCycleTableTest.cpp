// Stride and cycle table: which tables it offers (numeric start and end), the rows with units and the
// mean/SD rows, the row under the cursor selected as the cursor moves, a selected row moving the cursor
// and the visible range to its cycle, and the tool and screenshot registration.
#include "GuiTestSupport.h"

#include "ui/MainWindow.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/views/CycleTableView.h"

#include <QDockWidget>
#include <QHeaderView>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>

using namespace athlos;
using namespace athlos::ui;

namespace {

// Three strides of 1.0, 1.2, 1.2 s, lengths 1.2, 1.3, 1.5 m (mean 1.3333, SD 0.15275), a foot label.
Table strideTable() {
    Table t;
    t.kind = QStringLiteral("gait-parameters");
    t.columns = {TableColumn{QStringLiteral("start"), QStringLiteral("s"), false, {1.0, 2.0, 3.2}, {}},
                 TableColumn{QStringLiteral("end"), QStringLiteral("s"), false, {2.0, 3.2, 4.4}, {}},
                 TableColumn{QStringLiteral("stride_length"), QStringLiteral("m"), false, {1.2, 1.3, 1.5}, {}},
                 TableColumn{QStringLiteral("foot"),
                             {},
                             true,
                             {},
                             {QStringLiteral("left"), QStringLiteral("left"), QStringLiteral("left")}}};
    t.provenance.inputs = {{QStringLiteral("run1/imu"), QByteArray("0123")}};
    return t;
}

}  // namespace

class ViewsCycleTableTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
    }

    void offersTablesWithStartAndEnd() {
        auto project = testing::makeProject(dir_.filePath("a.athlos"));
        QVERIFY(CycleTableView::cycleTables(*project).isEmpty());  // run1/beacons has no start/end
        project->putTable(QStringLiteral("run1/strides"), strideTable());
        Table textStart = strideTable();
        textStart.columns[0].isText = true;  // a text "start" is not a time
        textStart.columns[0].texts = {QStringLiteral("a"), QStringLiteral("b"), QStringLiteral("c")};
        project->putTable(QStringLiteral("run1/notes"), textStart);
        QCOMPARE(CycleTableView::cycleTables(*project), QStringList{QStringLiteral("run1/strides")});

        const Table& t = *project->table(QStringLiteral("run1/strides"));
        QCOMPARE(CycleTableView::rowAt(t, 0.5), -1);
        QCOMPARE(CycleTableView::rowAt(t, 1.0), 0);
        QCOMPARE(CycleTableView::rowAt(t, 2.0), 1);  // half-open: a shared border belongs to the later stride
        QCOMPARE(CycleTableView::rowAt(t, 4.39), 2);
        QCOMPARE(CycleTableView::rowAt(t, 4.4), -1);
        const auto s = CycleTableView::summary(t.columns[2]);
        QCOMPARE(s.count, 3);
        QVERIFY(std::abs(s.mean - 4.0 / 3.0) < 1e-12);
        QVERIFY(std::abs(s.sd - std::sqrt(0.07 / 3.0)) < 1e-12);  // Σ(x − x̄)² = 0.14/3, n − 1 = 2
        TableColumn withNaN{QStringLiteral("x"), QStringLiteral("m"), false, {1.0, std::nan(""), 3.0}, {}};
        QCOMPARE(CycleTableView::summary(withNaN).count, 2);
        QVERIFY(std::abs(CycleTableView::summary(withNaN).mean - 2.0) < 1e-12);
    }

    void rowsFollowTheCursorBothWays() {
        auto project = testing::makeProject(dir_.filePath("b.athlos"));
        project->putTable(QStringLiteral("run1/strides"), strideTable());
        CycleTableView view(project.get());
        QVERIFY(!view.setTable(QStringLiteral("run1/beacons")).ok());
        QVERIFY(view.setTable(QStringLiteral("run1/strides")).ok());
        QTableWidget* grid = view.tableWidget();
        QCOMPARE(grid->rowCount(), 5);  // three strides, mean, SD
        QCOMPARE(grid->columnCount(), 4);
        QCOMPARE(grid->horizontalHeaderItem(2)->text(), QStringLiteral("stride_length\n[m]"));
        QCOMPARE(grid->horizontalHeaderItem(3)->text(), QStringLiteral("foot"));
        QCOMPARE(grid->item(1, 2)->text(), QStringLiteral("1.300"));
        QCOMPARE(grid->item(2, 3)->text(), QStringLiteral("left"));
        QCOMPARE(grid->verticalHeaderItem(3)->text(), QStringLiteral("mean"));
        QCOMPARE(grid->item(3, 2)->text(), QStringLiteral("1.333"));
        QCOMPARE(grid->item(4, 2)->text(), QStringLiteral("0.1528"));
        QCOMPARE(grid->item(3, 3)->text(), QString());  // no mean of a text column

        TimeController time;
        time.setBounds(0.0, 10.0);
        view.setTimeController(&time);
        QCOMPARE(view.currentRow(), -1);
        time.setCursor(2.5);
        QCOMPARE(view.currentRow(), 1);
        QCOMPARE(time.cursor(), 2.5);  // following the cursor does not move it to the stride's start
        time.setCursor(9.0);
        QCOMPARE(view.currentRow(), -1);
        time.setCursor(1.5);
        QCOMPARE(view.currentRow(), 0);

        // Selecting a stride shows it: the cursor at its start, a quarter of its duration either side.
        grid->selectRow(2);
        QCOMPARE(view.currentRow(), 2);
        QVERIFY(std::abs(time.cursor() - 3.2) < 1e-12);
        QVERIFY(std::abs(time.visibleBegin() - 2.9) < 1e-9);
        QVERIFY(std::abs(time.visibleEnd() - 4.7) < 1e-9);
        // The mean and SD rows cannot be selected.
        grid->selectRow(3);
        QVERIFY(view.currentRow() != 3);
    }

    void registeredAsToolAndScreenshotView() {
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) { return t.id == "cycle-table-view"; }));
        const auto& views = registeredViews();
        auto it = std::find_if(views.begin(), views.end(), [](const ViewEntry& v) { return v.name == "cycle-table"; });
        QVERIFY(it != views.end());
        MainWindow window;
        window.setInteractive(false);
        window.resize(1280, 800);
        auto shared = std::shared_ptr<Project>(testing::makeProject(dir_.filePath("c.athlos")));
        window.setProject(shared);
        QVERIFY(!it->prepare(window).ok());
        shared->putTable(QStringLiteral("run1/strides"), strideTable());
        const Status status = it->prepare(window);
        QVERIFY2(status.ok(), status.ok() ? "" : qPrintable(status.message()));
        auto* dock = window.findChild<QDockWidget*>("cycleTableDock");
        QVERIFY(dock);
        auto* view = dock->findChild<CycleTableView*>();
        QVERIFY(view);
        QCOMPARE(view->currentRow(), 2);
        QVERIFY(std::abs(window.timeController()->cursor() - 3.2) < 1e-12);
        window.timeController()->setCursor(1.2);
        QCOMPARE(view->currentRow(), 0);
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(ViewsCycleTableTest)
#include "ViewsCycleTableTest.moc"
