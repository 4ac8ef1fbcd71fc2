// The "Calibrate LPS" wizard offscreen: beacon import, the requests it sends, and that accepting
// keeps the result items while retrying (or cancelling) removes them from the project again.
#include "GuiTestSupport.h"
#include "WizardTestSupport.h"

#include "core/processing/ProcessorRegistry.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/venue/TrackOverlay.h"
#include "ui/venue/VenuePlot.h"
#include "ui/wizards/LpsCalibrationWizard.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLineEdit>
#include <QPushButton>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>

using namespace athlos;
using namespace athlos::ui;
using athlos::testing::child;

namespace {

// Records requests and stores made-up outputs shaped like the LPS processors' (table + "-report";
// a walk position stream; an aligned table).
class RecordingWorkspace : public testing::WorkspaceDouble {
public:
    using WorkspaceDouble::WorkspaceDouble;

    Expected<RunOutcome> runProcessor(const RunRequest& r) override {
        requests.append(r);
        if (r.processorId == failProcessor) return makeError(QStringLiteral("%1 failed").arg(r.processorId));
        if (r.processorId == "lps-calibration") {
            Table beacons = *project_->table(r.inputs[1]);
            for (TableColumn& c : beacons.columns)
                if (c.name == "x")
                    for (double& v : c.numbers) v += 0.5;
            beacons.provenance.processorId = r.processorId;
            project_->putTable(r.output, beacons);
            Table report;
            report.kind = "report";
            report.attributes = QJsonObject{{"nrmsr_initial", 1.5}, {"nrmsr_calibrated", 0.08}, {"converged", true}};
            const long long n = beacons.rows();
            report.columns = {TableColumn{"id", {}, true, {}, beacons.column("id")->texts},
                              TableColumn{"rms_residual_initial", "m", false, std::vector<double>(n, 1.2), {}},
                              TableColumn{"rms_residual", "m", false, std::vector<double>(n, 0.1), {}},
                              TableColumn{"shift", "m", false, std::vector<double>(n, 0.5), {}}};
            project_->putTable(r.output + "-report", report);
            return testing::wrote({r.output, r.output + "-report"});
        }
        if (r.processorId == "lps-positioning") {
            StreamInfo info;
            info.kind = "lps-position";
            info.columns = {{"x", "m"}, {"y", "m"}};
            StreamData d(5, 2);
            for (int k = 0; k < 5; ++k) {
                d.t[k] = k;
                d.at(k, 0) = k;
                d.at(k, 1) = -k;
            }
            project_->putStream(r.output, Stream(info, d));
            return testing::wrote({r.output});
        }
        if (r.processorId == "lps-align") {
            project_->putTable(r.output, *project_->table(r.inputs[0]));
            return testing::wrote({r.output});
        }
        return makeError("unexpected processor " + r.processorId);
    }

    QString failProcessor;
};

Stream makeTdoa() {
    StreamInfo info;
    info.kind = "lps-tdoa";
    info.columns = {{"dt_B1", "s"}, {"dt_B2", "s"}};
    StreamData d(10, 2);
    for (int k = 0; k < 10; ++k) d.t[k] = 0.1 * k;
    return Stream(info, d);
}

}  // namespace

class WizardLpsCalibrationTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
        auto calibration = ProcessorRegistry::instance().find("lps-calibration");
        auto align = ProcessorRegistry::instance().find("lps-align");
        QVERIFY2(calibration && align, "lps plugin not found; build athlos_plugin_lps");
        calibrationSpecs_ = calibration->parameters();
        alignSpecs_ = align->parameters();
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) {
            return t.id == "lps-calibration-wizard" && QByteArray(t.menu) == "Positioning";
        }));
    }

    void init() {
        project_ = testing::makeProject(dir_.filePath("p.athlos"));
        project_->putStream("walk/tdoa", makeTdoa());
    }

    void importsBeaconsAndDrawsThem() {
        RecordingWorkspace ws(project_.get());
        LpsCalibrationWizard wizard(ws, nullptr, calibrationSpecs_, alignSpecs_);
        wizard.show();
        auto* beacons = child<QComboBox>(&wizard, "beaconCombo");
        QCOMPARE(beacons->currentText(), QStringLiteral("run1/beacons"));
        QCOMPARE(wizard.beaconView()->beaconCurve("initial")->dataCount(), 2);
        QVERIFY(wizard.importBeacons(QStringLiteral(ATHLOS_TEST_DATA_DIR "/beacons.csv"), "venue/initial"));
        QVERIFY(project_->table("venue/initial"));
        QCOMPARE(project_->table("venue/initial")->kind, QStringLiteral("beacons"));
        QCOMPARE(beacons->currentText(), QStringLiteral("venue/initial"));
        QCOMPARE(ws.modifications, 1);
        QCOMPARE(wizard.beaconView()->beaconCurve("initial")->dataCount(), 4);
        QVERIFY(!wizard.beaconView()->overlay()->curves().isEmpty());
        QVERIFY(!wizard.importBeacons(QStringLiteral(ATHLOS_TEST_DATA_DIR "/no-such-file.csv"), "venue/x"));
    }

    void retryRemovesAndAcceptKeeps() {
        RecordingWorkspace ws(project_.get());
        LpsCalibrationWizard wizard(ws, nullptr, calibrationSpecs_, alignSpecs_);
        wizard.show();
        child<QComboBox>(&wizard, "trackCombo")->setCurrentText("indoor-200m");
        wizard.next();
        QCOMPARE(wizard.currentId(), int(LpsCalibrationWizard::WalkPage));
        child<QLineEdit>(&wizard, "param_alpha")->setText("0.01");
        child<QComboBox>(&wizard, "param_outlier_test")->setCurrentText("mad");
        wizard.next();  // runs calibration + walk positioning
        QCOMPARE(wizard.currentId(), int(LpsCalibrationWizard::ResultPage));
        QCOMPARE(ws.requests.size(), 2);
        const RunRequest& r = ws.requests[0];
        QCOMPARE(r.processorId, QStringLiteral("lps-calibration"));
        QCOMPARE(r.inputs, (QStringList{"walk/tdoa", "run1/beacons"}));
        QCOMPARE(r.output, QStringLiteral("walk/beacons-calibrated"));
        QCOMPARE(r.parameters.value("alpha").toDouble(), 0.01);
        QCOMPARE(r.parameters.value("outlier_test").toString(), QStringLiteral("mad"));
        QVERIFY(!r.parameters.contains("walk_height"));  // optional and empty: estimated
        QCOMPARE(r.parameters.value("track").toString(), QStringLiteral("indoor-200m"));  // the drawn venue
        const auto validated = validateParameters(calibrationSpecs_, r.parameters);
        QVERIFY2(validated.ok(), validated.ok() ? "" : qPrintable(validated.message()));
        QCOMPARE(ws.requests[1].processorId, QStringLiteral("lps-positioning"));
        QCOMPARE(ws.requests[1].inputs, (QStringList{"walk/tdoa", "walk/beacons-calibrated"}));
        const QStringList items{"walk/beacons-calibrated", "walk/beacons-calibrated-report",
                                "walk/beacons-calibrated-walk"};
        QCOMPARE(wizard.resultItems(), items);
        QCOMPARE(wizard.residualPlot()->plottableCount(), 2);  // before and after bars
        QCOMPARE(wizard.resultView()->beaconCurve("calibrated")->dataCount(), 2);
        QCOMPARE(wizard.resultView()->walkCurve()->dataCount(), 5);

        const int modificationsBefore = ws.modifications;
        child<QPushButton>(&wizard, "retryButton")->click();
        QCOMPARE(wizard.currentId(), int(LpsCalibrationWizard::WalkPage));
        for (const QString& item : items) QVERIFY2(!project_->stream(item) && !project_->table(item), qPrintable(item));
        QCOMPARE(ws.modifications, modificationsBefore + 1);

        child<QLineEdit>(&wizard, "param_alpha")->setText("0.02");
        child<QCheckBox>(&wizard, "walkCheck")->setChecked(false);
        wizard.next();
        QCOMPARE(ws.requests.size(), 3);
        QCOMPARE(ws.requests[2].parameters.value("alpha").toDouble(), 0.02);
        wizard.next();
        QCOMPARE(wizard.currentId(), int(LpsCalibrationWizard::SavePage));
        QCOMPARE(child<QLineEdit>(&wizard, "saveEdit")->text(), QStringLiteral("walk/beacons-calibrated"));
        child<QLineEdit>(&wizard, "saveEdit")->setText("walk/beacons-final");
        wizard.button(QWizard::FinishButton)->click();
        QCOMPARE(wizard.result(), int(QDialog::Accepted));
        QVERIFY(project_->table("walk/beacons-final"));
        QVERIFY(!project_->table("walk/beacons-calibrated"));
        QVERIFY(project_->table("walk/beacons-calibrated-report"));
        QCOMPARE(project_->table("walk/beacons-final")->provenance.processorId, QStringLiteral("lps-calibration"));
    }

    void alignsToMarks() {
        RecordingWorkspace ws(project_.get());
        LpsCalibrationWizard wizard(ws, nullptr, calibrationSpecs_, alignSpecs_);
        wizard.show();
        wizard.next();
        wizard.next();
        wizard.next();
        child<QCheckBox>(&wizard, "alignCheck")->setChecked(true);
        child<QLineEdit>(&wizard, "marksEdit")->setText("0,0,0>1,1,0; 10,0,0>11,1,0");
        child<QComboBox>(&wizard, "modeCombo")->setCurrentText("yaw");
        // Aligning in place is refused: the aligned table needs its own name.
        wizard.button(QWizard::FinishButton)->click();
        QVERIFY(wizard.isVisible());
        child<QLineEdit>(&wizard, "saveEdit")->setText("walk/aligned");
        wizard.button(QWizard::FinishButton)->click();
        const RunRequest& r = ws.requests.back();
        QCOMPARE(r.processorId, QStringLiteral("lps-align"));
        QCOMPARE(r.inputs, QStringList{"walk/beacons-calibrated"});
        QCOMPARE(r.output, QStringLiteral("walk/aligned"));
        QCOMPARE(r.parameters.value("marks").toString(), QStringLiteral("0,0,0>1,1,0; 10,0,0>11,1,0"));
        QCOMPARE(r.parameters.value("mode").toString(), QStringLiteral("yaw"));
        QVERIFY(validateParameters(alignSpecs_, r.parameters).ok());
        QVERIFY(project_->table("walk/aligned"));
        QVERIFY(project_->table("walk/beacons-calibrated"));
    }

    void cancelAfterRunLeavesProjectUnchanged() {
        RecordingWorkspace ws(project_.get());
        const QStringList tablesBefore = project_->tablePaths(), streamsBefore = project_->streamPaths();
        LpsCalibrationWizard wizard(ws, nullptr, calibrationSpecs_, alignSpecs_);
        wizard.show();
        wizard.next();
        wizard.next();
        QVERIFY(project_->table("walk/beacons-calibrated"));
        wizard.reject();
        QCOMPARE(project_->tablePaths(), tablesBefore);
        QCOMPARE(project_->streamPaths(), streamsBefore);
    }

    void calibrationErrorStaysOnPage() {
        RecordingWorkspace ws(project_.get());
        ws.failProcessor = "lps-calibration";
        LpsCalibrationWizard wizard(ws, nullptr, calibrationSpecs_, alignSpecs_);
        wizard.show();
        wizard.next();
        wizard.next();
        QCOMPARE(wizard.currentId(), int(LpsCalibrationWizard::WalkPage));
        QCOMPARE(wizard.lastError(), QStringLiteral("lps-calibration failed"));
        QVERIFY(wizard.resultItems().isEmpty());
    }

private:
    QTemporaryDir dir_;
    ParameterSpecs calibrationSpecs_, alignSpecs_;
    std::unique_ptr<Project> project_;
};

QTEST_MAIN(WizardLpsCalibrationTest)
#include "WizardLpsCalibrationTest.moc"
