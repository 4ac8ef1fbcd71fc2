// simulate-gates → orientation → anchor-smoother through the runner (as the CLI runs them): outputs,
// units, the crossings table, and the refusals (no magnetometer, malformed gates table, no gate
// found) that name the input, the recording and the threshold and store nothing.
#include "core/processing/ProcessorRunner.h"
#include "plugins/inertial/OrientationProcessor.h"
#include "plugins/positioning/AnchorSmootherProcessor.h"
#include "plugins/positioning/GateTable.h"
#include "plugins/positioning/SimulateGatesProcessor.h"

#include <QDir>
#include <gtest/gtest.h>
#include <cmath>

using namespace athlos;
using namespace athlos::positioning;

namespace {

std::unique_ptr<Project> simulatedRun(int seed) {
    auto project = Project::create(QDir::temp().filePath(QStringLiteral("athlos-anchor-smoother-test.athlos")));
    auto out = runProcessor(
        *project, SimulateGatesProcessor(),
        {QStringLiteral("simulate-gates"),
         {},
         QStringLiteral("gs/imu"),
         {{QStringLiteral("seed"), QString::number(seed)}, {QStringLiteral("gates"), QStringLiteral("10")}}});
    EXPECT_TRUE(out.ok()) << out.message().toStdString();
    out = runProcessor(*project, inertial::OrientationProcessor(),
                       {QStringLiteral("orientation"), {QStringLiteral("gs/imu")}, QStringLiteral("gs/q"), {}});
    EXPECT_TRUE(out.ok()) << out.message().toStdString();
    return project;
}

RunRequest smootherRequest(const QString& imu = QStringLiteral("gs/imu"),
                           const QString& gates = QStringLiteral("gs/imu-gates"), QVariantMap parameters = {}) {
    return {QStringLiteral("anchor-smoother"),
            {imu, QStringLiteral("gs/q"), gates},
            QStringLiteral("gs/anchored"),
            std::move(parameters)};
}

}  // namespace

TEST(AnchorSmootherProcessor, WritesTrajectoryAndCrossings) {
    auto project = simulatedRun(2);
    const auto out = runProcessor(*project, AnchorSmootherProcessor(), smootherRequest());
    ASSERT_TRUE(out.ok()) << out.message().toStdString();
    const Stream* trajectory = project->stream(QStringLiteral("gs/anchored"));
    const Table* crossings = project->table(QStringLiteral("gs/anchored-crossings"));
    ASSERT_TRUE(trajectory && crossings);
    EXPECT_EQ(trajectory->info().columnNames().join(QLatin1Char(',')), QStringLiteral("x,y,z,vx,vy,vz,speed"));
    EXPECT_EQ(trajectory->info().columns[6].unit, QStringLiteral("m/s"));
    EXPECT_EQ(crossings->rows(), 10);
    EXPECT_EQ(trajectory->info().attributes.value(QStringLiteral("gates_matched")).toInt(), 10);
    // Every crossing was matched to the gate of its order.
    const auto* gate = crossings->column(QStringLiteral("gate"));
    ASSERT_TRUE(gate);
    for (int m = 0; m < 10; ++m)
        EXPECT_EQ(gate->texts.value(m), QStringLiteral("G%1").arg(m + 1, 2, 10, QLatin1Char('0')));
    // Gate-to-gate times against the truth: the passage is the instant of closest horizontal approach of
    // the true track to the gate.
    const auto* split = crossings->column(QStringLiteral("gate_to_gate"));
    const auto* t = crossings->column(QStringLiteral("t"));
    ASSERT_TRUE(split && t);
    EXPECT_TRUE(std::isnan(split->numbers[0]));
    const Table* gates = project->table(QStringLiteral("gs/imu-gates"));
    ASSERT_TRUE(gates);
    const auto trueTrack = *project->stream(QStringLiteral("gs/imu-truth"))->data();
    auto passage = [&](int g) {
        const double ge = gates->column(QStringLiteral("east"))->numbers[std::size_t(g)],
                     gn = gates->column(QStringLiteral("north"))->numbers[std::size_t(g)];
        double best = 1e9, when = 0.0;
        for (std::size_t k = 0; k < trueTrack->rows(); ++k) {
            const double d = std::hypot(trueTrack->at(k, 0) - ge, trueTrack->at(k, 1) - gn);
            if (d < best) {
                best = d;
                when = trueTrack->t[k];
            }
        }
        return when;
    };
    for (int m = 1; m < 10; ++m) {
        EXPECT_NEAR(split->numbers[std::size_t(m)], t->numbers[std::size_t(m)] - t->numbers[std::size_t(m - 1)], 1e-12);
        EXPECT_NEAR(split->numbers[std::size_t(m)], passage(m) - passage(m - 1), 0.05) << "gate " << m;
    }
    // The passages as instants in the recording's annotations.
    int gateAnnotations = 0;
    for (const Annotation& a : project->recording(QStringLiteral("gs"))->annotations)
        if (a.label == QLatin1String("gate") && a.source == QLatin1String("anchor-smoother")) ++gateAnnotations;
    EXPECT_EQ(gateAnnotations, 10);
    // The smoothed track ends where the truth ends (within the judged accuracy).
    const auto est = *trajectory->data();
    const auto truth = *project->stream(QStringLiteral("gs/imu-truth"))->data();
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(est->at(est->rows() - 1, i), truth->at(truth->rows() - 1, i), 0.5) << i;
}

TEST(AnchorSmootherProcessor, RefusesWithoutMagnetometer) {
    auto project = simulatedRun(3);
    const Stream* imu = project->stream(QStringLiteral("gs/imu"));
    const auto d = *imu->data();
    StreamData six(d->rows(), 6);
    six.t = d->t;
    for (std::size_t k = 0; k < d->rows(); ++k)
        for (int c = 0; c < 6; ++c) six.at(k, c) = d->at(k, c);
    StreamInfo info = imu->info();
    info.columns.resize(6);
    project->putStream(QStringLiteral("gs/imu6"), Stream(info, std::move(six)));
    const auto out = runProcessor(*project, AnchorSmootherProcessor(), smootherRequest(QStringLiteral("gs/imu6")));
    ASSERT_FALSE(out.ok());
    EXPECT_TRUE(out.message().contains(QStringLiteral("gs/imu6"))) << out.message().toStdString();
    EXPECT_TRUE(out.message().contains(QStringLiteral("mag_x"))) << out.message().toStdString();
    EXPECT_EQ(project->stream(QStringLiteral("gs/anchored")), nullptr);
}

TEST(AnchorSmootherProcessor, RefusesMalformedGatesTables) {
    auto project = simulatedRun(4);
    Table noUp = *project->table(QStringLiteral("gs/imu-gates"));
    noUp.columns.pop_back();
    project->putTable(QStringLiteral("gs/no-up"), noUp);
    auto out = runProcessor(*project, AnchorSmootherProcessor(),
                            smootherRequest(QStringLiteral("gs/imu"), QStringLiteral("gs/no-up")));
    ASSERT_FALSE(out.ok());
    EXPECT_TRUE(out.message().contains(QStringLiteral("gs/no-up"))) << out.message().toStdString();
    EXPECT_TRUE(out.message().contains(QStringLiteral("'up'"))) << out.message().toStdString();

    Table duplicate = *project->table(QStringLiteral("gs/imu-gates"));
    duplicate.columns[0].texts[3] = duplicate.columns[0].texts[2];
    project->putTable(QStringLiteral("gs/dup"), duplicate);
    out = runProcessor(*project, AnchorSmootherProcessor(),
                       smootherRequest(QStringLiteral("gs/imu"), QStringLiteral("gs/dup")));
    ASSERT_FALSE(out.ok());
    EXPECT_TRUE(out.message().contains(QStringLiteral("twice"))) << out.message().toStdString();

    Table nan = *project->table(QStringLiteral("gs/imu-gates"));
    nan.columns[1].numbers[5] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(gatesFromTable(nan, QStringLiteral("x/g")).ok());
    EXPECT_EQ(project->stream(QStringLiteral("gs/anchored")), nullptr);
}

TEST(AnchorSmootherProcessor, NoGatesFoundNamesRecordingAndThreshold) {
    auto project = simulatedRun(5);
    const auto out = runProcessor(*project, AnchorSmootherProcessor(),
                                  smootherRequest(QStringLiteral("gs/imu"), QStringLiteral("gs/imu-gates"),
                                                  {{QStringLiteral("mag_threshold"), QStringLiteral("50")}}));
    ASSERT_FALSE(out.ok());
    EXPECT_TRUE(out.message().contains(QStringLiteral("'gs'"))) << out.message().toStdString();
    EXPECT_TRUE(out.message().contains(QStringLiteral("no gate crossing found"))) << out.message().toStdString();
    EXPECT_TRUE(out.message().contains(QStringLiteral("50"))) << out.message().toStdString();
    EXPECT_EQ(project->stream(QStringLiteral("gs/anchored")), nullptr);
}
