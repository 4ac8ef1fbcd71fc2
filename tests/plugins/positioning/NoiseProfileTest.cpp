// Noise profiles (issue #16 item 6): the table round trip and its refusals, and the deployment flow
// of thesis §4.4 through the runner, on simulated runs with known noise: a profile estimated on two
// training runs recovers the simulator's measurement variances, position-filter applies it
// (noise=profile:PATH) to a third run at least as well as estimating on that run itself (more data:
// 0.136 vs 0.188 m), and a profile of a different system (10× the noise) is measurably worse.
#include "core/processing/ParameterSpec.h"
#include "core/processing/ProcessorRunner.h"
#include "plugins/positioning/NoiseProfile.h"
#include "plugins/positioning/NoiseProfileProcessor.h"
#include "plugins/positioning/PositionFilterProcessor.h"
#include "plugins/positioning/SimulateTrackRunProcessor.h"

#include <QDir>
#include <gtest/gtest.h>
#include <cmath>
#include <map>

using namespace athlos;
using namespace athlos::positioning;

namespace {

void simulate(Project& project, const QString& path, int seed, double varScale) {
    const auto out = runProcessor(project, SimulateTrackRunProcessor(),
                                  {QStringLiteral("simulate-track-run"),
                                   {},
                                   path,
                                   {{QStringLiteral("seed"), QString::number(seed)},
                                    {QStringLiteral("distance"), QStringLiteral("400")},
                                    {QStringLiteral("noise_var_x"), QString::number(5e-3 * varScale)},
                                    {QStringLiteral("noise_var_y"), QString::number(1.6e-2 * varScale)}}});
    ASSERT_TRUE(out.ok()) << out.message().toStdString();
}

// 2D RMSE of a filtered stream (x, y) against the simulator's truth (100 Hz on multiples of 0.01 s).
double rmseAgainstTruth(const Project& project, const QString& filtered, const QString& truth) {
    const auto f = *project.stream(filtered)->data();
    const auto t = *project.stream(truth)->data();
    std::map<long long, std::size_t> at;
    for (std::size_t k = 0; k < t->rows(); ++k) at[std::llround(t->t[k] * 100.0)] = k;
    double sum = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < f->rows(); ++k) {
        const auto it = at.find(std::llround(f->t[k] * 100.0));
        if (it == at.end()) continue;
        const double dx = f->at(k, 0) - t->at(it->second, 0), dy = f->at(k, 1) - t->at(it->second, 1);
        sum += dx * dx + dy * dy;
        ++n;
    }
    EXPECT_GT(n, 100);
    return std::sqrt(sum / n);
}

Expected<RunOutcome> filter(Project& project, const QString& input, const QString& output, const QString& noise) {
    return runProcessor(project, PositionFilterProcessor(),
                        {QStringLiteral("position-filter"),
                         {input},
                         output,
                         {{QStringLiteral("noise"), noise}, {QStringLiteral("output_rate"), QStringLiteral("10")}}});
}

double tableValue(const Table& t, const char* parameter) {
    const auto row = t.column(QStringLiteral("parameter"))->texts.indexOf(QLatin1String(parameter));
    return t.column(QStringLiteral("value"))->numbers.at(static_cast<std::size_t>(row));
}

}  // namespace

TEST(NoiseProfile, TableRoundTripAndRefusals) {
    NoiseProfile p;
    p.model = ModelKind::ConstantVelocity;
    p.noise.ctra.rX = 0.02;
    p.noise.qAccelCv = 3.5;
    p.noise.gate = std::numeric_limits<double>::infinity();
    const Table t = noiseProfileTable(p);
    auto back = noiseProfileFromTable(t, QStringLiteral("a/profile"));
    ASSERT_TRUE(back.ok()) << back.message().toStdString();
    EXPECT_EQ(back->model, ModelKind::ConstantVelocity);
    EXPECT_DOUBLE_EQ(back->noise.ctra.rX, 0.02);
    EXPECT_DOUBLE_EQ(back->noise.qAccelCv, 3.5);
    EXPECT_TRUE(std::isinf(back->noise.gate));  // stored as 0 = gating off

    Table negative = t;
    negative.columns[1].numbers[6] = -1.0;  // r_x
    auto bad = noiseProfileFromTable(negative, QStringLiteral("a/profile"));
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains(QStringLiteral("a/profile")) && bad.message().contains(QStringLiteral("r_x")))
        << bad.message().toStdString();
    Table beacons = t;
    beacons.kind = QStringLiteral("beacons");
    EXPECT_FALSE(noiseProfileFromTable(beacons, QStringLiteral("a/b")).ok());
}

TEST(NoiseProfile, ChoiceWithArgument) {
    const ParameterSpec spec = ParameterSpec::choice(
        QStringLiteral("noise"), {QStringLiteral("auto"), QStringLiteral("profile:")}, QStringLiteral("auto"), {});
    EXPECT_TRUE(spec.convert(QStringLiteral("profile:train/noise")).ok());
    EXPECT_TRUE(spec.convert(QStringLiteral("auto")).ok());
    EXPECT_FALSE(spec.convert(QStringLiteral("profile:")).ok());  // the argument is required
    EXPECT_FALSE(spec.convert(QStringLiteral("profiles")).ok());
}

TEST(NoiseProfile, TrainedOnTwoRunsAppliedToAThird) {
    auto project = Project::create(QDir::temp().filePath(QStringLiteral("athlos-noise-profile-test.athlos")));
    simulate(*project, QStringLiteral("train1/run"), 8101, 1.0);
    simulate(*project, QStringLiteral("train2/run"), 8102, 1.0);
    simulate(*project, QStringLiteral("noisy/run"), 8103, 10.0);
    simulate(*project, QStringLiteral("new/run"), 8104, 1.0);

    auto trained = runProcessor(*project, NoiseProfileProcessor(),
                                {QStringLiteral("noise-profile"),
                                 {QStringLiteral("train1/run"), QStringLiteral("train2/run")},
                                 QStringLiteral("train1/noise"),
                                 {}});
    ASSERT_TRUE(trained.ok()) << trained.message().toStdString();
    const Table* profile = project->table(QStringLiteral("train1/noise"));
    ASSERT_TRUE(profile);
    EXPECT_EQ(profile->kind, kNoiseProfileKind);
    EXPECT_EQ(profile->attributes.value(QStringLiteral("training")).toArray().size(), 2);
    // The simulator's variances (5e-3, 1.6e-2 m²) are recovered from the two runs.
    EXPECT_NEAR(tableValue(*profile, "r_x"), 5e-3, 2.5e-3);
    EXPECT_NEAR(tableValue(*profile, "r_y"), 1.6e-2, 8e-3);
    ASSERT_TRUE(runProcessor(
                    *project, NoiseProfileProcessor(),
                    {QStringLiteral("noise-profile"), {QStringLiteral("noisy/run")}, QStringLiteral("noisy/noise"), {}})
                    .ok());
    EXPECT_GT(tableValue(*project->table(QStringLiteral("noisy/noise")), "r_x"), 4.0 * tableValue(*profile, "r_x"));

    ASSERT_TRUE(filter(*project, QStringLiteral("new/run"), QStringLiteral("new/profiled"),
                       QStringLiteral("profile:train1/noise"))
                    .ok());
    ASSERT_TRUE(filter(*project, QStringLiteral("new/run"), QStringLiteral("new/auto"), QStringLiteral("auto")).ok());
    ASSERT_TRUE(
        filter(*project, QStringLiteral("new/run"), QStringLiteral("new/wrong"), QStringLiteral("profile:noisy/noise"))
            .ok());
    const auto applied = project->stream(QStringLiteral("new/profiled"))->info().attributes;
    EXPECT_EQ(applied.value(QStringLiteral("noise_profile")).toString(), QStringLiteral("train1/noise"));
    EXPECT_DOUBLE_EQ(applied.value(QStringLiteral("noise")).toObject().value(QStringLiteral("r_x")).toDouble(),
                     tableValue(*profile, "r_x"));
    const double profiled = rmseAgainstTruth(*project, QStringLiteral("new/profiled"), QStringLiteral("new/run-truth"));
    const double own = rmseAgainstTruth(*project, QStringLiteral("new/auto"), QStringLiteral("new/run-truth"));
    const double wrong = rmseAgainstTruth(*project, QStringLiteral("new/wrong"), QStringLiteral("new/run-truth"));
    std::printf(
        "RMSE on a new run: profile %.4f m, estimated on the run %.4f m, profile of a 10x noisier system "
        "%.4f m\n",
        profiled, own, wrong);
    EXPECT_LE(profiled, 1.15 * own);
    EXPECT_GT(wrong, 1.05 * profiled);  // measured 0.148 vs 0.136 m
}

TEST(NoiseProfile, RefusedProfilesNameTheProblem) {
    auto project = Project::create(QDir::temp().filePath(QStringLiteral("athlos-noise-profile-test2.athlos")));
    simulate(*project, QStringLiteral("a/run"), 8201, 1.0);
    auto missing = filter(*project, QStringLiteral("a/run"), QStringLiteral("a/f"), QStringLiteral("profile:a/none"));
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(missing.message().contains(QStringLiteral("a/none"))) << missing.message().toStdString();
    // A constant-velocity profile cannot drive the augmented model (its Q has other states).
    NoiseProfile cv;
    cv.model = ModelKind::ConstantVelocity;
    project->putTable(QStringLiteral("a/cv"), noiseProfileTable(cv));
    auto mismatch = filter(*project, QStringLiteral("a/run"), QStringLiteral("a/f"), QStringLiteral("profile:a/cv"));
    ASSERT_FALSE(mismatch.ok());
    EXPECT_TRUE(mismatch.message().contains(QStringLiteral("constant-velocity"))) << mismatch.message().toStdString();
    EXPECT_EQ(project->stream(QStringLiteral("a/f")), nullptr);
}
