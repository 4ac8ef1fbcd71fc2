// The "Filter positions" wizard and the track view, driven offscreen against an in-memory project
// and a Workspace double that records the RunRequest and stores a made-up result.
#include "GuiTestSupport.h"
#include "WizardTestSupport.h"

#include "core/processing/ProcessorRegistry.h"
#include "ui/MainWindow.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/venue/TrackOverlay.h"
#include "ui/views/TrackTrajectoryView.h"
#include "ui/wizards/PositionFilterWizard.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>
#include <numbers>

using namespace athlos;
using namespace athlos::ui;
using athlos::testing::child;

namespace {

// Records requests; "runs" position-filter by copying the input as trajectory and flagging every
// 50th fix as an outlier, with the provenance the real runner would attach.
class RecordingWorkspace : public testing::WorkspaceDouble {
public:
    using WorkspaceDouble::WorkspaceDouble;
    Expected<RunOutcome> runProcessor(const RunRequest& request) override {
        requests.append(request);
        if (!failWith.isEmpty()) return makeError(failWith);
        storeFakeResult(*project_, request);
        return testing::wrote({request.output, request.output + QStringLiteral("-outliers")});
    }

    static void storeFakeResult(Project& project, const RunRequest& request) {
        const Stream* input = project.stream(request.inputs.front());
        const StreamData& in = **input->data();
        StreamData out(in.rows(), 7), flags(in.rows(), 2);
        for (std::size_t k = 0; k < in.rows(); ++k) {
            out.t[k] = flags.t[k] = in.t[k];
            out.at(k, 0) = in.at(k, 0);
            out.at(k, 1) = in.at(k, 1);
            out.at(k, 2) = 5.0 + 3.0 * double(k) / double(in.rows());
            flags.at(k, 0) = out.at(k, 6) = k % 50 == 7 ? 1.0 : 0.0;
        }
        Provenance p;
        p.processorId = QStringLiteral("position-filter");
        p.parameters = QJsonObject::fromVariantMap(request.parameters);
        p.inputs = {{request.inputs.front(), input->info().contentHash}};
        StreamInfo info;
        info.kind = QStringLiteral("trajectory");
        info.columns = {
            {"x", "m"},         {"y", "m"},      {"speed", "m/s"}, {"heading", "rad"}, {"turn_rate", "rad/s"},
            {"accel", "m/s^2"}, {"outlier", "1"}};
        info.provenance = p;
        project.putStream(request.output, Stream(info, std::move(out)));
        StreamInfo flagInfo;
        flagInfo.kind = QStringLiteral("outliers");
        flagInfo.columns = {{"outlier", "1"}, {"mahalanobis", "1"}};
        flagInfo.provenance = p;
        project.putStream(request.output + QStringLiteral("-outliers"), Stream(flagInfo, std::move(flags)));
    }

    QString failWith;
};

// Distance of every point of a curve with track-frame x beyond the bend start from the bend centre.
QList<double> bendRadii(const QCPCurve* curve, const TrackGeometry& track) {
    const Eigen::Vector2d centre = track.toLps({track.ovalParams().straightLength / 2, 0.0});
    QList<double> radii;
    for (auto it = curve->data()->constBegin(); it != curve->data()->constEnd(); ++it) {
        const Eigen::Vector2d p(it->key, it->value);
        if (track.toTrack(p).x() > track.ovalParams().straightLength / 2 + 1e-9) radii << (p - centre).norm();
    }
    return radii;
}

// Runs requests through core's real runner and the real processor, as MainWindow does (minus the
// worker thread and progress dialog).
class RunnerWorkspace : public RecordingWorkspace {
public:
    using RecordingWorkspace::RecordingWorkspace;
    Expected<RunOutcome> runProcessor(const RunRequest& request) override {
        requests.append(request);
        return athlos::runProcessor(*project_, request);
    }
};

}  // namespace

class WizardPositionFilterTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
        // The real schema when the plugin is built (manual noise fields are generated from it).
        specs_ = ProcessorRegistry::instance().find(QStringLiteral("position-filter"))
                     ? ProcessorRegistry::instance().find(QStringLiteral("position-filter"))->parameters()
                     : ParameterSpecs{};
        QVERIFY2(!specs_.isEmpty(), "position-filter plugin not found; build athlos_plugin_positioning");
    }

    void init() { project_ = testing::makeProject(dir_.filePath(QStringLiteral("p.athlos"))); }

    void listsOnlyPositionStreams() {
        RecordingWorkspace ws(project_.get());
        PositionFilterWizard wizard(ws, nullptr, specs_);
        auto* streams = child<QComboBox>(&wizard, "streamCombo");
        QCOMPARE(streams->count(), 1);
        QCOMPARE(streams->currentText(), QStringLiteral("run1/lps"));
        QCOMPARE(child<QLineEdit>(&wizard, "outputEdit")->text(), QStringLiteral("run1/lps-filtered"));
    }

    void requestFollowsEveryControl() {
        RecordingWorkspace ws(project_.get());
        PositionFilterWizard wizard(ws, nullptr, specs_);
        child<QComboBox>(&wizard, "filterCombo")->setCurrentText(QStringLiteral("ukf"));
        child<QComboBox>(&wizard, "modelCombo")->setCurrentText(QStringLiteral("pseudo"));
        child<QComboBox>(&wizard, "trackCombo")->setCurrentText(QStringLiteral("indoor-200m"));
        child<QDoubleSpinBox>(&wizard, "trackX")->setValue(3.5);
        child<QDoubleSpinBox>(&wizard, "trackY")->setValue(-2.0);
        child<QDoubleSpinBox>(&wizard, "trackRotation")->setValue(90.0);

        RunRequest r = wizard.request();
        QCOMPARE(r.processorId, QStringLiteral("position-filter"));
        QCOMPARE(r.inputs, QStringList{QStringLiteral("run1/lps")});
        QCOMPARE(r.parameters.value("filter").toString(), QStringLiteral("ukf"));
        QCOMPARE(r.parameters.value("model").toString(), QStringLiteral("pseudo"));
        QCOMPARE(r.parameters.value("track").toString(), QStringLiteral("indoor-200m"));
        QCOMPARE(r.parameters.value("track_x").toDouble(), 3.5);
        QCOMPARE(r.parameters.value("track_y").toDouble(), -2.0);
        QVERIFY(std::abs(r.parameters.value("track_rotation").toDouble() - std::numbers::pi / 2) < 1e-12);
        QCOMPARE(r.parameters.value("noise").toString(), QStringLiteral("auto"));
        QVERIFY(!r.parameters.contains("q_position"));
        QVERIFY(!r.parameters.contains("lag"));
        QVERIFY(!r.parameters.contains("output_rate"));

        // Manual noise: every q_*/r_*/gate of the schema appears, with the edited value.
        child<QComboBox>(&wizard, "noiseCombo")->setCurrentText(QStringLiteral("manual"));
        child<QLineEdit>(&wizard, "param_q_position")->setText(QStringLiteral("1e-7"));
        child<QLineEdit>(&wizard, "param_gate")->setText(QStringLiteral("16"));
        child<QComboBox>(&wizard, "smootherCombo")->setCurrentText(QStringLiteral("fixed-lag"));
        child<QDoubleSpinBox>(&wizard, "lagSpin")->setValue(1.5);
        child<QCheckBox>(&wizard, "rateCheck")->setChecked(true);
        child<QDoubleSpinBox>(&wizard, "rateSpin")->setValue(25.0);
        child<QLineEdit>(&wizard, "outputEdit")->setText(QStringLiteral("run1/smooth"));
        r = wizard.request();
        for (const ParameterSpec& spec : specs_)
            if (spec.name.startsWith("q_") || spec.name.startsWith("r_") || spec.name == "gate")
                QVERIFY2(r.parameters.contains(spec.name), qPrintable(spec.name));
        QCOMPARE(r.parameters.value("q_position").toDouble(), 1e-7);
        QCOMPARE(r.parameters.value("gate").toDouble(), 16.0);
        QCOMPARE(r.parameters.value("smoother").toString(), QStringLiteral("fixed-lag"));
        QCOMPARE(r.parameters.value("lag").toDouble(), 1.5);
        QCOMPARE(r.parameters.value("output_rate").toDouble(), 25.0);
        QCOMPARE(r.output, QStringLiteral("run1/smooth"));
        // Every parameter the wizard sends is one the processor accepts, with a valid value.
        const auto validated = validateParameters(specs_, r.parameters);
        QVERIFY2(validated.ok(), validated.ok() ? "" : qPrintable(validated.message()));
    }

    void runsThroughWorkspaceAndShowsResult() {
        RecordingWorkspace ws(project_.get());
        PositionFilterWizard wizard(ws, nullptr, specs_);
        wizard.show();
        child<QComboBox>(&wizard, "modelCombo")->setCurrentText(QStringLiteral("augmented"));
        wizard.next();
        QCOMPARE(wizard.currentId(), int(PositionFilterWizard::TrackPage));
        child<QDoubleSpinBox>(&wizard, "trackX")->setValue(1.25);
        wizard.next();
        wizard.next();
        QCOMPARE(wizard.currentId(), int(PositionFilterWizard::OutputPage));
        QVERIFY(ws.requests.isEmpty());
        wizard.next();  // runs
        QCOMPARE(ws.requests.size(), 1);
        QCOMPARE(wizard.currentId(), int(PositionFilterWizard::ResultPage));
        const RunRequest& r = ws.requests.front();
        QCOMPARE(r.processorId, QStringLiteral("position-filter"));
        QCOMPARE(r.parameters.value("model").toString(), QStringLiteral("augmented"));
        QCOMPARE(r.parameters.value("track_x").toDouble(), 1.25);
        QCOMPARE(r.output, QStringLiteral("run1/lps-filtered"));
        TrackTrajectoryView* view = wizard.resultView();
        QCOMPARE(view->trajectoryCurve()->dataCount(), 800);
        QCOMPARE(view->rawCurve()->dataCount(), 800);
        QCOMPARE(view->outlierCurve()->dataCount(), 16);  // k % 50 == 7 for k < 800
    }

    void realProcessorRunsWizardRequest() {
        RunnerWorkspace ws(project_.get());
        PositionFilterWizard wizard(ws, nullptr, specs_);
        wizard.show();
        child<QComboBox>(&wizard, "modelCombo")->setCurrentText(QStringLiteral("augmented"));
        child<QComboBox>(&wizard, "noiseCombo")->setCurrentText(QStringLiteral("manual"));  // fast: no noise search
        child<QCheckBox>(&wizard, "rateCheck")->setChecked(true);
        child<QDoubleSpinBox>(&wizard, "rateSpin")->setValue(5.0);
        wizard.next();
        wizard.next();
        wizard.next();
        wizard.next();
        QVERIFY2(wizard.lastError().isEmpty(), qPrintable(wizard.lastError()));
        QCOMPARE(wizard.currentId(), int(PositionFilterWizard::ResultPage));
        const Stream* out = project_->stream(QStringLiteral("run1/lps-filtered"));
        QVERIFY(out);
        QCOMPARE(out->info().provenance.parameters.value("model").toString(), QStringLiteral("augmented"));
        QVERIFY(project_->stream(QStringLiteral("run1/lps-filtered-outliers")));
        QCOMPARE(wizard.resultView()->trajectoryCurve()->dataCount(), int(out->info().rows));
        QCOMPARE(wizard.resultView()->rawCurve()->dataCount(), 800);
        // The filtered lap stays on the drawn lane-1 line of the track it was run with (the test lap
        // is 36.8 m from the bend centres, i.e. on lane 1's running line).
        const TrackGeometry track = TrackTrajectoryView::trackOf(*project_, QStringLiteral("run1/lps-filtered"));
        const QCPCurve* curve = wizard.resultView()->trajectoryCurve();
        double worst = 0;
        for (auto it = curve->data()->constBegin(); it != curve->data()->constEnd(); ++it)
            worst = std::max(worst, std::abs(track.query({it->key, it->value}).d - track.laneOffset(1)));
        QVERIFY2(worst < 0.5, qPrintable(QString::number(worst)));
    }

    void runErrorStaysOnPage() {
        RecordingWorkspace ws(project_.get());
        ws.failWith = QStringLiteral("parameter 'lag': broken");
        PositionFilterWizard wizard(ws, nullptr, specs_);
        wizard.show();
        wizard.next();
        wizard.next();
        wizard.next();
        wizard.next();
        QCOMPARE(wizard.currentId(), int(PositionFilterWizard::OutputPage));
        QCOMPARE(wizard.lastError(), ws.failWith);
        // An existing output name is refused before running.
        ws.failWith.clear();
        child<QLineEdit>(&wizard, "outputEdit")->setText(QStringLiteral("run1/imu"));
        wizard.next();
        QCOMPARE(ws.requests.size(), 1);
        QVERIFY(wizard.lastError().contains("run1/imu"));
    }

    void overlayMatchesTrackGeometry() {
        RecordingWorkspace ws(project_.get());
        PositionFilterWizard wizard(ws, nullptr, specs_);
        wizard.show();
        wizard.next();
        child<QDoubleSpinBox>(&wizard, "trackX")->setValue(10.0);
        child<QDoubleSpinBox>(&wizard, "trackY")->setValue(5.0);
        child<QDoubleSpinBox>(&wizard, "trackRotation")->setValue(30.0);
        const TrackGeometry track = wizard.currentTrack();
        QCOMPARE(track.pose().x, 10.0);
        TrackOverlay* overlay = wizard.poseOverlay();
        const QList<double> lane1 = bendRadii(overlay->laneOneRunningLine(), track);
        const QList<double> kerb = bendRadii(overlay->kerbCurve(), track);
        QVERIFY(lane1.size() > 50);
        for (double r : lane1) QVERIFY2(std::abs(r - 36.80) < 1e-9, qPrintable(QString::number(r, 'g', 12)));
        for (double r : kerb) QVERIFY(std::abs(r - 36.50) < 1e-9);
        // Lane lines: 8 outer edges, the last at 36.50 + 8 × 1.22 m.
        QCOMPARE(overlay->curves().size(), 10);
        for (double r : bendRadii(overlay->curves()[8], track)) QVERIFY(std::abs(r - (36.5 + 8 * 1.22)) < 1e-9);

        // Live: moving the origin moves the drawn kerb by the same amount.
        const double before = overlay->kerbCurve()->data()->constBegin()->key;
        child<QDoubleSpinBox>(&wizard, "trackX")->setValue(12.0);
        QVERIFY(std::abs(overlay->kerbCurve()->data()->constBegin()->key - (before + 2.0)) < 1e-9);
    }

    void fitPoseFindsShiftedTrack() {
        // The test lap moved by (100, 50) and turned by 20°.
        Stream lap = testing::makeTrackStream();
        StreamData data = **lap.data();
        const double a = 20.0 * std::numbers::pi / 180.0;
        for (std::size_t k = 0; k < data.rows(); ++k) {
            const double x = data.at(k, 0), y = data.at(k, 1);
            data.at(k, 0) = 100.0 + std::cos(a) * x - std::sin(a) * y;
            data.at(k, 1) = 50.0 + std::sin(a) * x + std::cos(a) * y;
        }
        lap.setData(std::move(data));
        project_->putStream(QStringLiteral("run1/lps"), std::move(lap));
        RecordingWorkspace ws(project_.get());
        PositionFilterWizard wizard(ws, nullptr, specs_);
        wizard.show();
        wizard.next();
        wizard.fitPose();
        // The extent's centre is the track centre only for an unrotated oval; within a metre here.
        QVERIFY(std::abs(child<QDoubleSpinBox>(&wizard, "trackX")->value() - 100.0) < 1.0);
        QVERIFY(std::abs(child<QDoubleSpinBox>(&wizard, "trackY")->value() - 50.0) < 1.0);
        QVERIFY(std::abs(child<QDoubleSpinBox>(&wizard, "trackRotation")->value() - 20.0) < 0.5);
    }

    void trackViewScreenshotNeedsResult() {
        const auto& views = registeredViews();
        auto it = std::find_if(views.begin(), views.end(), [](const ViewEntry& v) { return v.name == "track"; });
        QVERIFY(it != views.end());
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) {
            return t.id == "position-filter-wizard" && QByteArray(t.menu) == "Positioning";
        }));

        MainWindow window;
        window.setInteractive(false);
        auto shared = std::shared_ptr<Project>(testing::makeProject(dir_.filePath(QStringLiteral("q.athlos"))));
        window.setProject(shared);
        QVERIFY(!it->prepare(window).ok());

        RecordingWorkspace::storeFakeResult(*shared, RunRequest{QStringLiteral("position-filter"),
                                                                {QStringLiteral("run1/lps")},
                                                                QStringLiteral("run1/track"),
                                                                {{"track_x", 2.0}}});
        QCOMPARE(TrackTrajectoryView::findResult(*shared), QStringLiteral("run1/track"));
        QCOMPARE(TrackTrajectoryView::trackOf(*shared, QStringLiteral("run1/track")).pose().x, 2.0);
        const Status status = it->prepare(window);
        QVERIFY2(status.ok(), status.ok() ? "" : qPrintable(status.message()));
        auto* view = window.findChild<TrackTrajectoryView*>();
        QVERIFY(view);
        QCOMPARE(view->outlierCurve()->dataCount(), 16);
        QVERIFY(view->isVisibleTo(&window));
    }

    void launchesFromMainWindowMenu() {
        MainWindow window;
        window.setInteractive(false);
        window.setProject(std::shared_ptr<Project>(testing::makeProject(dir_.filePath(QStringLiteral("m.athlos")))));
        auto* action = window.findChild<QAction*>(QStringLiteral("position-filter-wizard"));
        QVERIFY(action);
        action->trigger();
        auto* wizard = window.findChild<PositionFilterWizard*>();
        QVERIFY(wizard);
        QCOMPARE(child<QComboBox>(wizard, "streamCombo")->currentText(), QStringLiteral("run1/lps"));
        wizard->reject();
    }

private:
    QTemporaryDir dir_;
    ParameterSpecs specs_;
    std::unique_ptr<Project> project_;
};

QTEST_MAIN(WizardPositionFilterTest)
#include "WizardPositionFilterTest.moc"
