// Orientation angles view: Euler angles equal core's decomposition, and the error against a
// reference (values and RMS in the legend) equals core's OrientationError metric.
#include "GuiTestSupport.h"

#include "core/math/Angles.h"
#include "core/math/EulerAngles.h"
#include "core/math/OrientationError.h"
#include "ui/MainWindow.h"
#include "ui/ToolRegistry.h"
#include "ui/views/OrientationAnglesView.h"

#include <QComboBox>
#include <QTemporaryDir>
#include <QtTest>
#include <qcustomplot.h>
#include <numbers>

using namespace athlos;
using namespace athlos::ui;

namespace {

using math::kDeg;

Stream quaternionStream(const QString& kind, const std::vector<math::Quat>& q, double rate = 100.0) {
    StreamInfo info;
    info.kind = kind;
    info.frame = QStringLiteral("ENU");
    info.columns = {{"qw", "1"}, {"qx", "1"}, {"qy", "1"}, {"qz", "1"}};
    StreamData d(q.size(), 4);
    for (std::size_t k = 0; k < q.size(); ++k) {
        d.t[k] = double(k) / rate;
        d.at(k, 0) = q[k].w();
        d.at(k, 1) = q[k].x();
        d.at(k, 2) = q[k].y();
        d.at(k, 3) = q[k].z();
    }
    return Stream(info, d);
}

// A reference turning about z with a slow tilt, and an estimate off by a varying error rotation.
void addTrial(Project& project, std::vector<math::Quat>& est, std::vector<math::Quat>& ref) {
    const auto zyx = *math::EulerSequence::parse("ZYX");
    for (int k = 0; k < 300; ++k) {
        const double s = k / 100.0;
        ref.push_back(math::quaternionFromEuler(math::Vec3(0.8 * s, 0.2 * std::sin(s), 0.1), zyx));
        const math::Quat error = math::quatFromRotationVector(math::Vec3(0.02 * std::cos(3 * s), -0.01, 0.05 * s));
        est.push_back((error * ref.back()).normalized());  // earth-frame error, as the metric defines it
    }
    project.putStream("trial/orientation", quaternionStream("orientation", est));
    project.putStream("trial/reference", quaternionStream("reference", ref));
}

QVector<double> values(const QCPGraph* graph) {
    QVector<double> v;
    for (auto it = graph->data()->constBegin(); it != graph->data()->constEnd(); ++it) v << it->value;
    return v;
}

}  // namespace

class ViewsOrientationAnglesTest : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        QVERIFY(dir_.isValid());
        testing::isolateSettings(dir_.path());
    }

    void eulerAnglesEqualCoreDecomposition() {
        auto project = testing::makeProject(dir_.filePath("a.athlos"));
        const math::Quat q =
            math::quaternionFromEuler(math::Vec3(30, -20, 10) * kDeg, *math::EulerSequence::parse("ZYX"));
        project->putStream("still/orientation", quaternionStream("orientation", std::vector<math::Quat>(20, q)));
        OrientationAnglesView view(project.get());
        QCOMPARE(OrientationAnglesView::orientationStreams(*project), QStringList{"still/orientation"});
        QVERIFY(view.setStream("still/orientation").ok());
        QVERIFY(!view.setStream("run1/imu").ok());
        QCOMPARE(view.anglePlot()->graphCount(), 3);
        const double expected[3] = {30, -20, 10};
        for (int i = 0; i < 3; ++i) {
            const QVector<double> v = values(view.anglePlot()->graph(i));
            QCOMPARE(v.size(), 20);
            for (double a : v) QVERIFY2(std::abs(a - expected[i]) < 1e-9, qPrintable(QString::number(a)));
        }
        QVERIFY(view.anglePlot()->graph(0)->name().contains("yaw"));

        for (const char* name : {"XYZ", "ZXZ", "zyx"}) {
            view.setSequence(name);
            const math::Vec3 core = math::eulerFromQuaternion(q, *math::EulerSequence::parse(name)) / kDeg;
            for (int i = 0; i < 3; ++i)
                QVERIFY2(std::abs(values(view.anglePlot()->graph(i)).front() - core[i]) < 1e-12, name);
        }
        QCOMPARE(view.errorPlot()->graphCount(), 0);  // no reference in that recording
        QCOMPARE(view.errorRms().count, 0);
    }

    void errorAgainstReferenceEqualsCoreMetric() {
        auto project = testing::makeProject(dir_.filePath("b.athlos"));
        std::vector<math::Quat> est, ref;
        addTrial(*project, est, ref);
        QCOMPARE(OrientationAnglesView::referenceFor(*project, "trial/orientation"), QStringLiteral("trial/reference"));
        OrientationAnglesView view(project.get());
        QVERIFY(view.setStream("trial/orientation").ok());
        const math::ErrorRms core = math::orientationErrorRms(est, ref);
        QCOMPARE(view.errorRms().count, 300);
        QVERIFY(std::abs(view.errorRms().total - core.total) < 1e-12);
        QVERIFY(std::abs(view.errorRms().heading - core.heading) < 1e-12);
        QVERIFY(std::abs(view.errorRms().inclination - core.inclination) < 1e-12);
        QVERIFY(core.total > 0.5);  // the constructed error is not trivially zero
        QCOMPARE(view.errorPlot()->graphCount(), 3);
        QVERIFY(view.errorPlot()->graph(0)->name().contains(QString::number(core.total, 'f', 2)));
        QVERIFY(view.errorPlot()->graph(2)->name().contains(QString::number(core.inclination, 'f', 2)));
        const QVector<double> heading = values(view.errorPlot()->graph(1));
        for (int k : {0, 150, 299})
            QVERIFY(std::abs(heading[k] - math::orientationError(est[k], ref[k]).heading / kDeg) < 1e-12);
    }

    void registeredAsToolAndScreenshotView() {
        const auto& tools = registeredTools();
        QVERIFY(std::any_of(tools.begin(), tools.end(), [](const ToolEntry& t) {
            return t.id == "orientation-angles" && QByteArray(t.menu) == "Inertial";
        }));
        const auto& views = registeredViews();
        auto it = std::find_if(views.begin(), views.end(), [](const ViewEntry& v) { return v.name == "orientation"; });
        QVERIFY(it != views.end());

        MainWindow window;
        window.setInteractive(false);
        auto shared = std::shared_ptr<Project>(testing::makeProject(dir_.filePath("c.athlos")));
        window.setProject(shared);
        QVERIFY(!it->prepare(window).ok());
        std::vector<math::Quat> est, ref;
        addTrial(*shared, est, ref);
        const Status status = it->prepare(window);
        QVERIFY2(status.ok(), status.ok() ? "" : qPrintable(status.message()));
        auto* view = window.findChild<OrientationAnglesView*>();
        QVERIFY(view);
        QCOMPARE(view->stream(), QStringLiteral("trial/orientation"));
        QCOMPARE(view->errorPlot()->graphCount(), 3);
    }

private:
    QTemporaryDir dir_;
};

QTEST_MAIN(ViewsOrientationAnglesTest)
#include "ViewsOrientationAnglesTest.moc"
