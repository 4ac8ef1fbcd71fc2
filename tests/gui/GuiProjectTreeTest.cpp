// The project tree model: recordings → streams and tables with kind, rows, columns/units, and
// provenance of results in the tooltip.
#include "GuiTestSupport.h"
#include "core/model/Table.h"
#include "ui/ItemDescription.h"
#include "ui/ProjectTreeModel.h"

#include <QAbstractItemModelTester>
#include <QtTest>
#include <cmath>

using namespace athlos;
using namespace athlos::ui;

class GuiProjectTreeTest : public QObject {
    Q_OBJECT

private slots:
    void showsRecordingsAndItems();
    void resultsShowProvenance();
    void refreshFollowsProjectChanges();
    void smallTablesShowTheirValues();
};

void GuiProjectTreeTest::showsRecordingsAndItems() {
    auto project = testing::makeProject(QDir::temp().filePath(QStringLiteral("tree.athlos")));
    ProjectTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setProject(project.get());

    QCOMPARE(model.rowCount(), 2);
    const QModelIndex run1 = model.index(0, 0);
    QCOMPARE(run1.data().toString(), QStringLiteral("run1"));
    QCOMPARE(model.pathOf(run1), QStringLiteral("run1"));
    QCOMPARE(model.nodeType(run1), ProjectTreeModel::NodeType::Recording);
    QCOMPARE(model.rowCount(run1), 3);  // imu, lps (streams) and beacons (table)

    const QModelIndex imu = model.indexOf(QStringLiteral("run1/imu"));
    QVERIFY(imu.isValid());
    QCOMPARE(imu.parent(), run1);
    QCOMPARE(model.nodeType(imu), ProjectTreeModel::NodeType::Stream);
    QCOMPARE(imu.siblingAtColumn(ProjectTreeModel::KindColumn).data().toString(), QStringLiteral("imu"));
    QCOMPARE(imu.siblingAtColumn(ProjectTreeModel::RowsColumn).data().toString(), QLocale().toString(2000));
    const QString columns = imu.siblingAtColumn(ProjectTreeModel::ColumnsColumn).data().toString();
    QVERIFY2(columns.startsWith(QStringLiteral("acc_x [m/s^2], acc_y [m/s^2]")), qPrintable(columns));
    QVERIFY(columns.contains(QStringLiteral("gyr_z [rad/s]")));
    QVERIFY(!imu.data(Qt::DecorationRole).value<QIcon>().isNull());

    const QModelIndex beacons = model.indexOf(QStringLiteral("run1/beacons"));
    QCOMPARE(model.nodeType(beacons), ProjectTreeModel::NodeType::Table);
    QCOMPARE(beacons.siblingAtColumn(ProjectTreeModel::KindColumn).data().toString(), QStringLiteral("beacons"));
    QCOMPARE(beacons.siblingAtColumn(ProjectTreeModel::RowsColumn).data().toString(), QStringLiteral("2"));
    QVERIFY(
        beacons.siblingAtColumn(ProjectTreeModel::ColumnsColumn).data().toString().contains(QStringLiteral("x [m]")));

    QCOMPARE(model.headerData(ProjectTreeModel::KindColumn, Qt::Horizontal).toString(), QStringLiteral("Kind"));
}

void GuiProjectTreeTest::resultsShowProvenance() {
    auto project = testing::makeProject(QDir::temp().filePath(QStringLiteral("tree.athlos")));
    ProjectTreeModel model;
    model.setProject(project.get());
    const QModelIndex result = model.indexOf(QStringLiteral("run2/imu-filtered"));
    QVERIFY(result.isValid());
    const QString tip = result.data(Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(QStringLiteral("butterworth 1.0")), qPrintable(tip));
    QVERIFY(tip.contains(QStringLiteral("run1/imu")));
    QVERIFY(tip.contains(QStringLiteral("\"cutoff\":5")));
    QVERIFY(tip.contains(QStringLiteral("0.1.0")));
    QVERIFY(tip.contains(QStringLiteral("2024-05-01T12:00:00Z")));

    const QString html = ItemDescription::streamHtml(QStringLiteral("run2/imu-filtered"),
                                                     project->stream(QStringLiteral("run2/imu-filtered"))->info());
    QVERIFY(html.contains(QStringLiteral("Provenance")));
    QVERIFY(html.contains(QStringLiteral("butterworth 1.0")));
    QVERIFY(html.contains(QStringLiteral("&quot;order&quot;: 4")));
    QVERIFY(html.contains(QStringLiteral("0123456789ab")));
    // Imported or hand-made streams are not results.
    QVERIFY(!model.indexOf(QStringLiteral("run1/imu"))
                 .data(Qt::ToolTipRole)
                 .toString()
                 .contains(QStringLiteral("Result of")));
}

void GuiProjectTreeTest::refreshFollowsProjectChanges() {
    auto project = testing::makeProject(QDir::temp().filePath(QStringLiteral("tree.athlos")));
    ProjectTreeModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    model.setProject(project.get());
    project->putStream(QStringLiteral("run3/imu"), testing::makeImuStream(10));
    model.refresh();
    QCOMPARE(model.rowCount(), 3);
    QVERIFY(model.indexOf(QStringLiteral("run3/imu")).isValid());
    model.setProject(nullptr);
    QCOMPARE(model.rowCount(), 0);
    QVERIFY(!model.indexOf(QStringLiteral("run1/imu")).isValid());
}

void GuiProjectTreeTest::smallTablesShowTheirValues() {
    // A summary (more columns than rows) is shown one column per line, the feet side by side; NaN is an
    // empty cell.
    Table summary;
    summary.kind = QStringLiteral("gait-summary");
    summary.columns = {
        TableColumn{QStringLiteral("foot"), QString(), true, {}, {QStringLiteral("left"), QStringLiteral("right")}},
        TableColumn{QStringLiteral("used"), QStringLiteral("1"), false, {24, 23}, {}},
        TableColumn{QStringLiteral("stride_length_mean"), QStringLiteral("m"), false, {1.37594, 1.3882}, {}},
        TableColumn{QStringLiteral("stride_length_si"), QStringLiteral("%"), false, {std::nan(""), 0.887061}, {}}};
    QString html = ItemDescription::tableHtml(QStringLiteral("walk/summary"), summary);
    QVERIFY2(html.contains(QStringLiteral("Values")), qPrintable(html));
    QVERIFY(html.contains(QStringLiteral("stride_length_mean [m]</td>")));
    QVERIFY(html.contains(QLocale().toString(1.37594, 'g', 5)));
    QVERIFY(html.contains(QLocale().toString(0.887061, 'g', 5)));
    QVERIFY(html.contains(QStringLiteral(">used</td>")));  // a count: no unit "1"
    QVERIFY(!html.contains(QStringLiteral("nan"), Qt::CaseInsensitive));
    // A list (more rows than columns) keeps its columns as the header.
    Table list;
    list.kind = QStringLiteral("beacons");
    list.columns = {TableColumn{QStringLiteral("x"), QStringLiteral("m"), false, {1, 2, 3}, {}},
                    TableColumn{QStringLiteral("y"), QStringLiteral("m"), false, {4, 5, 6}, {}}};
    html = ItemDescription::tableHtml(QStringLiteral("run/beacons"), list);
    QVERIFY2(html.contains(QStringLiteral("<th>x [m]</th><th>y [m]</th>")), qPrintable(html));
    // A large table is described, not listed.
    list.columns[0].numbers.assign(3000, 1.0);
    list.columns[1].numbers.assign(3000, 2.0);
    QVERIFY(!ItemDescription::tableHtml(QStringLiteral("run/beacons"), list).contains(QStringLiteral("Values")));
}

QTEST_MAIN(GuiProjectTreeTest)
#include "GuiProjectTreeTest.moc"
