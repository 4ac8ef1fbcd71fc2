// The gait report (ui/report/GaitReport, File ▸ Export gait report…) offscreen on hand-made stride
// tables: which tables it takes (refusing two of one foot unless named), the dialog's choice and
// parameters, the summary (the real gait-summary processor) against the values worked out here, and
// the PDF (summary page and stride pages; a cancelled report leaves an older file as it was).
#include "GuiTestSupport.h"

#include "core/processing/ProcessorRegistry.h"
#include "ui/ParameterForm.h"
#include "ui/ToolRegistry.h"
#include "ui/report/GaitReport.h"
#include "ui/report/GaitReportDialog.h"

#include <QComboBox>
#include <QTemporaryDir>
#include <QtTest>
#include <numeric>

using namespace athlos;
using namespace athlos::ui;

// QVERIFY2 evaluates its message even when the statement holds: only ask an error for its message.
#define VERIFY_OK(e) QVERIFY2(bool(e), bool(e) ? "" : qPrintable((e).message()))

namespace {

// n adjacent straight strides of one foot (1.1 s each), stride k long 1.30 + 0.01 k m.
Table strides(const QString& foot, int n, double firstStart) {
    Table t;
    t.kind = QStringLiteral("gait-parameters");
    t.attributes = QJsonObject{{QStringLiteral("foot"), foot}, {QStringLiteral("method"), QStringLiteral("rts")}};
    const QStringList names{"start",        "end",        "stride_length", "stride_height", "stride_time",
                            "stance_time",  "swing_time", "cadence",       "gait_speed",    "max_toe_clearance",
                            "turning_angle"};
    const QStringList units{"s", "s", "m", "m", "s", "s", "s", "steps/min", "m/s", "m", "rad"};
    for (int c = 0; c < names.size(); ++c) t.columns.push_back(TableColumn{names[c], units[c], false, {}, {}});
    for (int k = 0; k < n; ++k) {
        const double start = firstStart + 1.1 * k, length = 1.30 + 0.01 * k;
        const double values[] = {start, start + 1.1, length,       0.0,  1.1, 0.66,
                                 0.44,  120.0 / 1.1, length / 1.1, 0.12, 0.0};
        for (int c = 0; c < names.size(); ++c) t.columns[std::size_t(c)].numbers.push_back(values[c]);
    }
    return t;
}

double cellOf(const Table& t, const QString& column, const QString& foot) {
    const int row = int(t.column(QStringLiteral("foot"))->texts.indexOf(foot));
    return row < 0 ? std::nan("") : t.column(column)->numbers[std::size_t(row)];
}

int pdfPages(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return -1;
    const QByteArray bytes = f.readAll();
    int pages = 0;
    for (qsizetype at = bytes.indexOf("/Type /Page"); at >= 0; at = bytes.indexOf("/Type /Page", at + 1))
        pages += bytes.mid(at + 11, 1) != "s";
    return bytes.startsWith("%PDF-") ? pages : -1;
}

}  // namespace

class GuiGaitReportTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
        QVERIFY2(ProcessorRegistry::instance().find("gait-summary"), "events plugin not found");
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) {
            return t.id == "export-gait-report" && QByteArray(t.menu) == "File";
        }));
    }

    void init() {
        project_ = testing::makeProject(dir_.filePath("p.athlos"));
        project_->putTable("walk/left-a", strides("left", 12, 0.5));
        project_->putTable("walk/left-b", strides("left", 40, 0.5));
        project_->putTable("walk/right-a", strides("right", 12, 1.05));
    }

    void takesOneTablePerFootOrTheNamedOnes() {
        auto ambiguous = GaitReport::strideTables(*project_, "walk");
        QVERIFY(!ambiguous);
        QVERIFY2(ambiguous.message().contains("'walk' has 2 gait-parameters tables of the left foot (left-a, left-b)"),
                 qPrintable(ambiguous.message()));
        auto none = GaitReport::strideTables(*project_, "run1");
        QVERIFY(!none);
        QVERIFY2(none.message().contains("'run1' has no gait-parameters table"), qPrintable(none.message()));
        QVERIFY(!GaitReport::strideTables(*project_, "nope"));
        auto sameFoot = GaitReport::strideTables(*project_, {}, {"walk/left-a", "walk/left-b"});
        QVERIFY(!sameFoot);
        QVERIFY(sameFoot.message().contains("both of the left foot"));
        QVERIFY(!GaitReport::strideTables(*project_, {}, {"run1/beacons"}));  // not a stride table
        QCOMPARE(GaitReport::defaultRecording(*project_, "run1"), QString("walk"));  // the only one with strides
        QCOMPARE(GaitReport::defaultRecording(*project_, "walk"), QString("walk"));
        project_->putTable("walk2/right-a", strides("right", 5, 0.0));
        QCOMPARE(GaitReport::defaultRecording(*project_, "run1"), QString());  // two: the user selects one
        QCOMPARE(GaitReport::defaultRecording(*project_, "walk2"), QString("walk2"));
        project_->removeItem("walk2/right-a");
        project_->removeItem("walk/left-b");
        auto found = GaitReport::strideTables(*project_, {});  // the only recording with stride tables
        VERIFY_OK(found);
        QCOMPARE(found->recording, QString("walk"));
        QCOMPARE(found->strides, QStringList({"walk/left-a", "walk/right-a"}));  // left first
    }

    void dialogChoosesTablesAndParameters() {
        GaitReportDialog dialog(*project_, GaitReportInput{"walk", {"walk/left-b"}});
        QCOMPARE(dialog.footCombo(0)->currentData().toString(), QString("walk/left-b"));
        QCOMPARE(dialog.footCombo(1)->currentData().toString(), QString("walk/right-a"));
        QCOMPARE(dialog.input().strides, QStringList({"walk/left-b", "walk/right-a"}));
        QCOMPARE(dialog.parameters().value("terrain").toString(), QString("all"));
        dialog.footCombo(1)->setCurrentIndex(dialog.footCombo(1)->findData(QString()));  // "(none)"
        QCOMPARE(dialog.input().strides, QStringList({"walk/left-b"}));
    }

    void summaryAndPdf() {
        const GaitReportInput input{"walk", {"walk/left-a", "walk/right-a"}};
        auto summary = GaitReport::summary(*project_, input, {{"edge_strides", 2}});
        VERIFY_OK(summary);
        // Twelve adjacent straight strides, two left out at each end: strides 2…9, 1.32…1.39 m.
        QCOMPARE(cellOf(*summary, "used", "left"), 8.0);
        QVERIFY(std::abs(cellOf(*summary, "stride_length_mean", "left") - 1.355) < 1e-12);
        QVERIFY(std::abs(cellOf(*summary, "stride_length_si", "both")) < 1e-12);  // the same strides both sides
        QVERIFY(!project_->table("walk/gait-report"));                            // nothing stored
        // An imported item under the run's label does not stop the report.
        Stream imported = testing::makeImuStream(10);
        imported.info().provenance.processorId = "import:csv";
        project_->putStream("walk/gait-report", std::move(imported));
        VERIFY_OK(GaitReport::summary(*project_, input));

        const QString pdf = dir_.filePath("gait.pdf");
        QVERIFY2(GaitReport::writePdf(*project_, input, *summary, pdf), "report not written");
        QCOMPARE(pdfPages(pdf), 2);  // summary; 24 strides fit on one page
        project_->putTable("walk/left-a", strides("left", 150, 0.5));
        auto longer = GaitReport::summary(*project_, input);
        QVERIFY(longer);
        QVERIFY(GaitReport::writePdf(*project_, input, *longer, pdf));
        QVERIFY2(pdfPages(pdf) >= 4, qPrintable(QString::number(pdfPages(pdf))));  // 162 strides over pages

        // Cancelled: the older PDF stays as it was.
        QFile old(pdf);
        QVERIFY(old.open(QIODevice::ReadOnly));
        const QByteArray before = old.readAll();
        old.close();
        CancelToken token;
        token.cancel();
        const Status cancelled = GaitReport::writePdf(*project_, input, *longer, pdf, Progress({}, token));
        QVERIFY(!cancelled);
        QCOMPARE(cancelled.message(), QString("cancelled"));
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), before);
    }

private:
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
};

QTEST_MAIN(GuiGaitReportTest)
#include "GuiGaitReportTest.moc"
