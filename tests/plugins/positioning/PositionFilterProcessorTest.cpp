// The simulate-track-run and position-filter processors through the runner (as the CLI runs them):
// outputs, units, attributes, outlier flags, parameter errors and cancellation.
#include "core/processing/ProcessorRunner.h"
#include "plugins/positioning/PositionFilterProcessor.h"
#include "plugins/positioning/SimulateTrackRunProcessor.h"
#include "plugins/positioning/TrackRunSimulator.h"

#include <QDir>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::positioning;

namespace {

std::unique_ptr<Project> simulatedProject(int seed) {
    auto project = Project::create(QDir::temp().filePath(QStringLiteral("athlos-position-filter-test.athlos")));
    const auto out = runProcessor(
        *project, SimulateTrackRunProcessor(),
        {QStringLiteral("simulate-track-run"),
         {},
         QStringLiteral("sim/run"),
         {{QStringLiteral("seed"), QString::number(seed)}, {QStringLiteral("distance"), QStringLiteral("400")}}});
    EXPECT_TRUE(out.ok()) << out.message().toStdString();
    return project;
}

}  // namespace

TEST(SimulateTrackRunProcessor, WritesMeasurementsAndTruth) {
    auto project = simulatedProject(3);
    const Stream* lps = project->stream(QStringLiteral("sim/run"));
    const Stream* truth = project->stream(QStringLiteral("sim/run-truth"));
    ASSERT_TRUE(lps && truth);
    EXPECT_EQ(lps->kind(), QStringLiteral("lps-position"));
    EXPECT_EQ(lps->info().columnNames(), (QStringList{QStringLiteral("x"), QStringLiteral("y")}));
    EXPECT_EQ(truth->kind(), QStringLiteral("trajectory"));
    EXPECT_EQ(truth->info().columns[2].unit, QStringLiteral("m/s"));
    EXPECT_GT(lps->info().rows, 1000);
    // Deterministic for a seed.
    auto again = simulatedProject(3);
    EXPECT_EQ(again->stream(QStringLiteral("sim/run"))->info().contentHash, lps->info().contentHash);
}

TEST(PositionFilterProcessor, FiltersOntoGridWithOutlierOutputs) {
    auto project = simulatedProject(5);
    RunRequest request{
        QStringLiteral("position-filter"),
        {QStringLiteral("sim/run")},
        QStringLiteral("sim/filtered"),
        {{QStringLiteral("output_rate"), QStringLiteral("10")}, {QStringLiteral("noise"), QStringLiteral("auto")}}};
    const auto out = runProcessor(*project, PositionFilterProcessor(), request);
    ASSERT_TRUE(out.ok()) << out.message().toStdString();
    const Stream* filtered = project->stream(QStringLiteral("sim/filtered"));
    const Stream* flags = project->stream(QStringLiteral("sim/filtered-outliers"));
    ASSERT_TRUE(filtered && flags);
    EXPECT_EQ(filtered->info().columnNames().join(QLatin1Char(',')),
              QStringLiteral("x,y,speed,heading,turn_rate,accel,outlier"));
    EXPECT_EQ(filtered->info().columns[5].unit, QStringLiteral("m/s^2"));
    EXPECT_TRUE(filtered->info().attributes.contains(QStringLiteral("estimated_noise")));
    const QJsonObject est = filtered->info().attributes.value(QStringLiteral("estimated_noise")).toObject();
    EXPECT_GT(est.value(QStringLiteral("r_x")).toDouble(), 5e-3 / 3);
    EXPECT_LT(est.value(QStringLiteral("r_x")).toDouble(), 5e-3 * 3);
    const auto data = filtered->data();
    ASSERT_TRUE(data.ok());
    const StreamData& d = **data;
    for (std::size_t k = 1; k < d.rows(); ++k) ASSERT_NEAR(d.t[k] - d.t[k - 1], 0.1, 1e-9);
    EXPECT_EQ(flags->info().rows, project->stream(QStringLiteral("sim/run"))->info().rows);
    // The grid's outlier column marks exactly the output samples next to a flagged input sample.
    const auto f = *flags->data();
    double flaggedInputs = 0, flaggedOutputs = 0;
    for (std::size_t i = 0; i < f->rows(); ++i) flaggedInputs += f->at(i, 0);
    for (std::size_t k = 0; k < d.rows(); ++k) flaggedOutputs += d.at(k, 6);
    EXPECT_GT(flaggedInputs, 0);
    EXPECT_GT(flaggedOutputs, 0);
    EXPECT_LE(flaggedOutputs, flaggedInputs);
}

TEST(PositionFilterProcessor, ParameterErrorsNameTheParameter) {
    auto project = simulatedProject(7);
    auto run = [&](QVariantMap params) {
        return runProcessor(
            *project, PositionFilterProcessor(),
            {QStringLiteral("position-filter"), {QStringLiteral("sim/run")}, QStringLiteral("sim/f"), params});
    };
    auto bad = run(
        {{QStringLiteral("track"), QStringLiteral("nowhere")}, {QStringLiteral("noise"), QStringLiteral("manual")}});
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains(QStringLiteral("track"))) << bad.message().toStdString();
    bad = run({{QStringLiteral("filter"), QStringLiteral("kalman")}});
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains(QStringLiteral("filter"))) << bad.message().toStdString();
    bad = run(
        {{QStringLiteral("output_rate"), QStringLiteral("0")}, {QStringLiteral("noise"), QStringLiteral("manual")}});
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains(QStringLiteral("output_rate"))) << bad.message().toStdString();
    // Manual noise, project geometry by name with a pose.
    TrackGeometry shifted = TrackGeometry::iaaf400m();
    project->geometry()[QStringLiteral("home")] = shifted.toJson();
    const auto ok = run({{QStringLiteral("track"), QStringLiteral("home")},
                         {QStringLiteral("noise"), QStringLiteral("manual")},
                         {QStringLiteral("smoother"), QStringLiteral("fixed-lag")},
                         {QStringLiteral("filter"), QStringLiteral("srukf")}});
    EXPECT_TRUE(ok.ok()) << ok.message().toStdString();
}

TEST(PositionFilterProcessor, HonoursCancellation) {
    auto project = simulatedProject(9);
    CancelToken token;
    token.cancel();
    const auto out =
        runProcessor(*project, PositionFilterProcessor(),
                     {QStringLiteral("position-filter"), {QStringLiteral("sim/run")}, QStringLiteral("sim/f"), {}},
                     Progress([](double, const QString&) {}, token));
    ASSERT_FALSE(out.ok());
    EXPECT_EQ(out.message(), QStringLiteral("cancelled"));
    EXPECT_EQ(project->stream(QStringLiteral("sim/f")), nullptr);
}
