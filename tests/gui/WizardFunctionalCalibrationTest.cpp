// The "Functional calibration" wizard offscreen on a simulated protocol recording: the sensors are
// assigned by stream name, Next runs the real functional-calibration processor (the CLI's code),
// the result page lists the movements and the quality of all eight segments, Back discards the
// tables, Finish keeps them, and a run without any sensor is refused on the first page.
#include "GuiTestSupport.h"
#include "WizardTestSupport.h"

#include "core/processing/ProcessorRegistry.h"
#include "ui/ToolRegistry.h"
#include "ui/wizards/FunctionalCalibrationWizard.h"

#include <QComboBox>
#include <QLabel>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace athlos;
using namespace athlos::ui;

namespace {

// Runs the registered processors for real.
class RunningWorkspace : public testing::WorkspaceDouble {
public:
    using WorkspaceDouble::WorkspaceDouble;
    Expected<RunOutcome> runProcessor(const RunRequest& r) override {
        requests.append(r);
        auto processor = ProcessorRegistry::instance().find(r.processorId);
        if (!processor) return makeError("no processor " + r.processorId);
        return athlos::runProcessor(*project_, *processor, r);
    }
};

}  // namespace

class WizardFunctionalCalibrationTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
        QVERIFY2(ProcessorRegistry::instance().find("functional-calibration"),
                 "inertial plugin not found; build athlos_plugin_inertial");
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) {
            return t.id == "functional-calibration-wizard" && QByteArray(t.menu) == "Processing";
        }));
    }

    void init() {
        project_ = testing::makeProject(dir_.filePath("p.athlos"));
        auto sim = ProcessorRegistry::instance().find("simulate-body");
        QVERIFY(sim);
        auto done = athlos::runProcessor(*project_, *sim,
                                         RunRequest{"simulate-body",
                                                    {},
                                                    "cal/imu",
                                                    {{"scenario", "squats"},
                                                     {"motion_duration", 4.0},
                                                     {"trunk_rotations", 3},
                                                     {"hip_abductions", 3},
                                                     {"seed", 5}}});
        if (!done) QFAIL(qPrintable(done.message()));
    }

    void assignsFindsAndKeeps() {
        RunningWorkspace ws(project_.get());
        FunctionalCalibrationWizard wizard(ws, nullptr);
        wizard.recordingCombo()->setCurrentText("cal");
        QCOMPARE(wizard.segmentCombo(0)->currentData().toString(), QString("imu"));
        QCOMPARE(wizard.segmentCombo(2)->currentData().toString(), QString("imu-right-thigh"));
        QCOMPARE(wizard.segmentCombo(7)->currentData().toString(), QString("imu-left-foot"));
        // The upper body's segments are offered too; simulate-body has no sensor there.
        QVERIFY(wizard.segmentCombo(13));
        QCOMPARE(wizard.segmentCombo(13)->objectName(), QString("left-forearmCombo"));
        QVERIFY(wizard.segmentCombo(9)->currentData().toString().isEmpty());
        wizard.show();
        wizard.next();
        QVERIFY2(wizard.lastError().isEmpty(), qPrintable(wizard.lastError()));
        QCOMPARE(wizard.currentId(), int(FunctionalCalibrationWizard::ResultPage));
        QCOMPARE(ws.requests.size(), 1);
        QCOMPARE(ws.requests[0].inputs.size(), 8);
        QVERIFY(project_->table("cal/functional-calibration"));
        QVERIFY(project_->table("cal/functional-calibration-quality"));
        QCOMPARE(wizard.qualityTable()->rowCount(), 8);
        QStringList movements;
        for (int r = 0; r < wizard.movementTable()->rowCount(); ++r)
            movements << wizard.movementTable()->item(r, 0)->text();
        for (const char* m : {"upright", "squats", "trunk-rotations", "right-abduction", "left-abduction"})
            QVERIFY2(movements.contains(m), m);
        // Back discards; Next runs again; Finish keeps.
        wizard.back();
        QVERIFY(!project_->table("cal/functional-calibration"));
        QVERIFY(!project_->table("cal/functional-calibration-quality"));
        wizard.next();
        QCOMPARE(wizard.currentId(), int(FunctionalCalibrationWizard::ResultPage));
        wizard.accept();
        QVERIFY(project_->table("cal/functional-calibration"));
        QVERIFY(project_->table("cal/functional-calibration-right"));
    }

    void refusesWithoutSensorsAndCancelRemoves() {
        RunningWorkspace ws(project_.get());
        {
            FunctionalCalibrationWizard wizard(ws, nullptr);
            wizard.recordingCombo()->setCurrentText("cal");
            for (int i = 0; i < 8; ++i) wizard.segmentCombo(i)->setCurrentIndex(0);
            wizard.show();
            wizard.next();
            QCOMPARE(wizard.currentId(), int(FunctionalCalibrationWizard::SensorPage));
            QVERIFY(!wizard.lastError().isEmpty());
            QVERIFY(ws.requests.isEmpty());
        }
        FunctionalCalibrationWizard wizard(ws, nullptr);
        wizard.recordingCombo()->setCurrentText("cal");
        wizard.show();
        wizard.next();
        QCOMPARE(wizard.currentId(), int(FunctionalCalibrationWizard::ResultPage));
        wizard.reject();
        QVERIFY(!project_->table("cal/functional-calibration"));
        QVERIFY(!project_->table("cal/functional-calibration-movements"));
    }

private:
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
};

QTEST_MAIN(WizardFunctionalCalibrationTest)
#include "WizardFunctionalCalibrationTest.moc"
