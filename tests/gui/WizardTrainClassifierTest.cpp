// The "Train classifier" wizard offscreen: it lists the annotated recordings and their labels,
// cross-validates on a worker (confusion heat map, balanced accuracy of clearly separable
// simulated activities), stores the model on Finish, and Cancel stops a running training.
#include "GuiTestSupport.h"
#include "WizardTestSupport.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/ProcessorRunner.h"
#include "core/processing/ProcessorRegistry.h"
#include "ui/wizards/TrainClassifierWizard.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QLineEdit>
#include <QListWidget>
#include <QSignalSpy>
#include <QSpinBox>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <qcustomplot.h>
#include <random>

using namespace athlos;
using namespace athlos::ui;

namespace {

class TestWorkspace : public testing::WorkspaceDouble {
public:
    using WorkspaceDouble::WorkspaceDouble;
    Expected<RunOutcome> runProcessor(const RunRequest&) override { return makeError(QStringLiteral("unused")); }
};

// A wrist IMU at 50 Hz alternating 10 s of "rest" (gravity and noise) and "shake" (3 Hz oscillation
// of 6 m/s² and 2 rad/s), annotated as imported ground truth.
void addRecording(Project& project, const QString& name, const QString& athlete, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 0.2);
    const std::size_t n = 50 * 80;
    StreamData data(n, 6);
    Annotations truth;
    for (std::size_t i = 0; i < n; ++i) {
        const double t = double(i) / 50.0;
        const bool shake = int(t / 10.0) % 2 == 1;
        const double s = shake ? std::sin(2.0 * M_PI * 3.0 * t) : 0.0;
        data.t[i] = t;
        data.at(i, 0) = 6.0 * s + noise(rng);
        data.at(i, 1) = noise(rng);
        data.at(i, 2) = 9.81 + noise(rng);
        data.at(i, 3) = 2.0 * s + 0.1 * noise(rng);
        data.at(i, 4) = 0.1 * noise(rng);
        data.at(i, 5) = 0.1 * noise(rng);
    }
    for (int k = 0; k < 8; ++k) {
        Annotation a;
        a.label = k % 2 ? QStringLiteral("shake") : QStringLiteral("rest");
        a.tStart = 10.0 * k;
        a.tEnd = 10.0 * (k + 1);
        a.source = QStringLiteral("import");
        truth.push_back(a);
    }
    const QStringList columns{QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z"),
                              QStringLiteral("gyr_x"), QStringLiteral("gyr_y"), QStringLiteral("gyr_z")};
    const QStringList units{QStringLiteral("m/s^2"), QStringLiteral("m/s^2"), QStringLiteral("m/s^2"),
                            QStringLiteral("rad/s"), QStringLiteral("rad/s"), QStringLiteral("rad/s")};
    project.putStream(name + QStringLiteral("/imu"), outputStream(QStringLiteral("imu"), QStringLiteral("sensor"),
                                                                  columnsOf(columns, units), std::move(data)));
    Recording& r = *project.recording(name);
    r.metadata[QStringLiteral("athlete")] = athlete;
    r.annotations = truth;
}

}  // namespace

class WizardTrainClassifierTest : public QObject {
    Q_OBJECT

private slots:
    void init() {
        QVERIFY(dir_.isValid());
        project_ = Project::create(dir_.filePath(QStringLiteral("p.athlos")));
        for (unsigned k = 1; k <= 3; ++k)
            addRecording(*project_, QStringLiteral("r%1").arg(k), QStringLiteral("athlete %1").arg(k), k);
    }

    void trainsCrossValidatesAndSaves() {
        TestWorkspace workspace(project_.get());
        TrainClassifierWizard wizard(workspace);
        QCOMPARE(wizard.streamCombo()->currentText(), QStringLiteral("imu"));
        QCOMPARE(wizard.recordingList()->count(), 3);
        QCOMPARE(wizard.classList()->count(), 2);
        wizard.show();
        wizard.classifierCombo()->setCurrentText(QStringLiteral("decision-tree"));
        QSignalSpy finished(&wizard, &TrainClassifierWizard::evaluationFinished);
        wizard.next();  // settings
        wizard.next();  // cross-validation: starts the training
        QCOMPARE(wizard.currentId(), int(TrainClassifierWizard::EvaluationPage));
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        QCOMPARE(finished.first().first().toBool(), true);
        QVERIFY2(wizard.balancedAccuracy() > 0.9, qPrintable(wizard.metricsText()));
        QVERIFY(wizard.metricsText().contains(QStringLiteral("leave-one-athlete-out")));
        QCOMPARE(wizard.confusionPlot()->plottableCount(), 1);
        QVERIFY(qobject_cast<QCPColorMap*>(wizard.confusionPlot()->plottable(0)));
        wizard.next();  // save
        QCOMPARE(wizard.currentId(), int(TrainClassifierWizard::SavePage));
        wizard.nameEdit()->setText(QStringLiteral("a/b"));
        wizard.button(QWizard::FinishButton)->click();
        QVERIFY(!project_->model(QStringLiteral("a/b")));
        wizard.nameEdit()->setText(QStringLiteral("shaking"));
        wizard.button(QWizard::FinishButton)->click();
        QVERIFY(project_->model(QStringLiteral("shaking")));
        QCOMPARE(workspace.modifications, 1);
        QCOMPARE(project_->model(QStringLiteral("shaking"))->description.value(QStringLiteral("input")).toString(),
                 QStringLiteral("imu"));
    }

    // Class balancing and mutual-information feature selection go through to the training, as
    // `athlos train --balance smote --select-features 12`: the stored model reads the 12 selected
    // features and records the choices in its parameters.
    // Multi-athlete interaction features as `athlos train --input 'sim-imu-*' --segmentation events:tackle
    // --interaction k=3`: the wizard offers the team session's stream pattern, the opponents spin box is
    // enabled with event segmentation, and the stored model describes its interaction features.
    void interactionFeaturesOfATeamSession() {
        auto simulate = ProcessorRegistry::instance().find(QStringLiteral("simulate-rugby"));
        QVERIFY2(simulate, "activity plugin not found; build athlos_plugin_activity");
        for (int m = 1; m <= 2; ++m) {
            auto run = athlos::runProcessor(*project_, *simulate,
                                            RunRequest{simulate->id(),
                                                       {},
                                                       QStringLiteral("m%1/sim").arg(m),
                                                       {{QStringLiteral("seed"), m},
                                                        {QStringLiteral("duration"), 255.0},
                                                        {QStringLiteral("scrums"), 0},
                                                        {QStringLiteral("tackles"), 4},
                                                        {QStringLiteral("contacts"), 3},
                                                        {QStringLiteral("falls"), 2},
                                                        {QStringLiteral("imu_rate"), 100.0},
                                                        {QStringLiteral("position_rate"), 20.0}}});
            if (!run.ok()) QFAIL(qPrintable(run.message()));
        }
        TestWorkspace workspace(project_.get());
        TrainClassifierWizard wizard(workspace);
        wizard.show();
        QVERIFY(wizard.streamCombo()->findText(QStringLiteral("sim-imu-*")) >= 0);
        wizard.streamCombo()->setCurrentText(QStringLiteral("sim-imu-*"));
        QCOMPARE(wizard.recordingList()->count(), 2);
        QVERIFY(!wizard.interactionSpin()->isEnabled());
        wizard.next();
        wizard.segmentationCombo()->setCurrentText(QStringLiteral("events:tackle"));
        QVERIFY(wizard.interactionSpin()->isEnabled());
        wizard.interactionSpin()->setValue(3);
        wizard.windowSpin()->setValue(4.0);
        QSignalSpy finished(&wizard, &TrainClassifierWizard::evaluationFinished);
        wizard.next();
        QVERIFY(finished.count() == 1 || finished.wait(120000));
        QVERIFY2(finished.first().first().toBool(), qPrintable(wizard.metricsText()));
        QVERIFY2(wizard.metricsText().contains(QStringLiteral("253 features")), qPrintable(wizard.metricsText()));
        wizard.next();
        wizard.nameEdit()->setText(QStringLiteral("tackles"));
        wizard.button(QWizard::FinishButton)->click();
        const TrainedModel* stored = project_->model(QStringLiteral("tackles"));
        QVERIFY(stored);
        QCOMPARE(stored->description.value(QStringLiteral("interaction"))
                     .toObject()
                     .value(QStringLiteral("neighbours"))
                     .toInt(),
                 3);
        QCOMPARE(stored->description.value(QStringLiteral("interaction_streams")).toArray().size(), 56);
    }

    void balancingAndFeatureSelection() {
        TestWorkspace workspace(project_.get());
        TrainClassifierWizard wizard(workspace);
        wizard.show();
        QCOMPARE(wizard.balanceCombo()->currentData().toString(), QStringLiteral("oversample"));
        QCOMPARE(wizard.selectFeaturesSpin()->value(), 0);
        wizard.classifierCombo()->setCurrentText(QStringLiteral("decision-tree"));
        wizard.balanceCombo()->setCurrentIndex(wizard.balanceCombo()->findData(QStringLiteral("smote")));
        wizard.selectFeaturesSpin()->setValue(12);
        QSignalSpy finished(&wizard, &TrainClassifierWizard::evaluationFinished);
        wizard.next();
        wizard.next();
        QVERIFY(finished.count() == 1 || finished.wait(60000));
        QCOMPARE(finished.first().first().toBool(), true);
        QVERIFY2(wizard.balancedAccuracy() > 0.9, qPrintable(wizard.metricsText()));
        QVERIFY2(wizard.metricsText().contains(QStringLiteral("the 12 features of highest mutual information")),
                 qPrintable(wizard.metricsText()));
        wizard.next();
        wizard.nameEdit()->setText(QStringLiteral("selected"));
        wizard.button(QWizard::FinishButton)->click();
        const TrainedModel* stored = project_->model(QStringLiteral("selected"));
        QVERIFY(stored);
        const QJsonObject d = stored->description;
        QCOMPARE(
            d.value(QStringLiteral("feature_selection")).toObject().value(QStringLiteral("features")).toArray().size(),
            12);
        const QJsonObject parameters = d.value(QStringLiteral("parameters")).toObject();
        QCOMPARE(parameters.value(QStringLiteral("balancing")).toString(), QStringLiteral("smote"));
        QCOMPARE(parameters.value(QStringLiteral("select_features")).toInt(), 12);
    }

    void cancelStopsTheTraining() {
        TestWorkspace workspace(project_.get());
        TrainClassifierWizard wizard(workspace);
        wizard.classifierCombo()->setCurrentText(QStringLiteral("svm"));  // grid search: slow enough to cancel
        QSignalSpy finished(&wizard, &TrainClassifierWizard::evaluationFinished);
        wizard.startTraining();
        QVERIFY(wizard.isRunning());
        wizard.cancelTraining();
        QVERIFY(finished.wait(60000));
        QCOMPARE(finished.first().first().toBool(), false);
        QCOMPARE(wizard.metricsText(), QStringLiteral("Cancelled."));
        QVERIFY(!wizard.hasModel());
        QVERIFY(project_->models().empty());
    }

private:
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
};

QTEST_MAIN(WizardTrainClassifierTest)
#include "WizardTrainClassifierTest.moc"
