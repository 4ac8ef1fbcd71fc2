// The skiing processors through the real runner on simulate-skiing recordings: per-cycle/per-turn
// tables with units, predicted annotations with the processor as source, the truth reproduced, and
// refusals (wrong stream kind, missing gyroscope column, nothing found, bad parameters) that name
// the stream or parameter and store nothing.
#include "plugins/events/AlpineTurnsProcessor.h"
#include "plugins/events/SimulateSkiingProcessor.h"
#include "plugins/events/SkimoPhasesProcessor.h"
#include "plugins/events/XcSkiingCyclesProcessor.h"

#include "core/processing/ProcessorRunner.h"

#include <QTemporaryDir>
#include <cmath>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::events;

namespace {

class SkiingProcessorsTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        project_ = Project::create(dir_.filePath(QStringLiteral("p.athlos")));
    }
    Expected<RunOutcome> run(const Processor& p, const QString& input, const QString& output, QVariantMap params = {}) {
        const QStringList inputs = input.isEmpty() ? QStringList() : input.split(QLatin1Char(','));
        return runProcessor(*project_, p, RunRequest{p.id(), inputs, output, params});
    }
    void simulate(const QString& scenario, const QString& output) {
        auto r = run(sim_, QString(), output, {{QStringLiteral("scenario"), scenario}, {QStringLiteral("count"), 20}});
        ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    }
    std::vector<double> numbers(const QString& table, const QString& column) {
        const Table* t = project_->table(table);
        if (!t || !t->column(column)) return {};
        return t->column(column)->numbers;
    }
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
    SimulateSkiingProcessor sim_;
};

}  // namespace

TEST_F(SkiingProcessorsTest, CrossCountryCyclesMatchTheTruth) {
    simulate(QStringLiteral("xc"), QStringLiteral("xc/ski"));
    XcSkiingCyclesProcessor xc;
    auto r = run(xc, QStringLiteral("xc/ski,xc/ski-pole"), QStringLiteral("xc/cycles"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Table* table = project_->table(QStringLiteral("xc/cycles"));
    ASSERT_NE(table, nullptr);
    EXPECT_EQ(table->kind, QStringLiteral("ski-cycles"));
    EXPECT_EQ(table->column(QStringLiteral("speed"))->unit, QStringLiteral("m/s"));
    const auto start = numbers(QStringLiteral("xc/cycles"), QStringLiteral("thrust_start"));
    const auto speed = numbers(QStringLiteral("xc/cycles"), QStringLiteral("speed"));
    const auto plant = numbers(QStringLiteral("xc/cycles"), QStringLiteral("pole_plant"));
    const auto trueStart = numbers(QStringLiteral("xc/ski-truth"), QStringLiteral("thrust_start"));
    const auto trueSpeed = numbers(QStringLiteral("xc/ski-truth"), QStringLiteral("speed"));
    const auto truePlant = numbers(QStringLiteral("xc/ski-truth"), QStringLiteral("pole_plant"));
    ASSERT_EQ(trueStart.size(), 20u);
    int matched = 0;
    for (std::size_t k = 1; k < trueStart.size(); ++k)
        for (std::size_t j = 0; j < start.size(); ++j)
            if (std::abs(start[j] - trueStart[k]) < 0.1) {
                ++matched;
                EXPECT_NEAR(speed[j], trueSpeed[k], 0.01 * trueSpeed[k]) << k;
                EXPECT_NEAR(plant[j], truePlant[k], 0.011) << k;
            }
    EXPECT_EQ(matched, 19);
    const Recording& rec = *project_->recording(QStringLiteral("xc"));
    int cycles = 0, pushes = 0;
    for (const Annotation& a : rec.annotations) {
        EXPECT_EQ(a.source, QStringLiteral("xc-skiing-cycles"));
        cycles += a.label == QLatin1String("xc cycle");
        pushes += a.label == QLatin1String("pole push");
    }
    EXPECT_EQ(cycles, int(start.size()));
    EXPECT_EQ(pushes, 20);
}

TEST_F(SkiingProcessorsTest, MountaineeringAndAlpine) {
    simulate(QStringLiteral("skimo"), QStringLiteral("up/ski"));
    SkimoPhasesProcessor skimo;
    auto r = run(skimo, QStringLiteral("up/ski"), QStringLiteral("up/cycles"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const Table* table = project_->table(QStringLiteral("up/cycles"));
    ASSERT_NE(table, nullptr);
    double trueGain = 0.0;
    for (double e : numbers(QStringLiteral("up/ski-truth"), QStringLiteral("elevation"))) trueGain += e;
    // The first true cycle merges with the initial stand: its elevation is missing from the estimate.
    trueGain -= numbers(QStringLiteral("up/ski-truth"), QStringLiteral("elevation")).front();
    EXPECT_NEAR(table->attributes.value(QStringLiteral("elevation_gain")).toDouble(), trueGain, 0.02 * trueGain);

    simulate(QStringLiteral("alpine"), QStringLiteral("gs/imu"));
    AlpineTurnsProcessor alpine;
    r = run(alpine, QStringLiteral("gs/imu"), QStringLiteral("gs/turns"));
    ASSERT_TRUE(r.ok()) << qPrintable(r.message());
    const auto start = numbers(QStringLiteral("gs/turns"), QStringLiteral("start"));
    const auto trueStart = numbers(QStringLiteral("gs/imu-truth"), QStringLiteral("start"));
    ASSERT_EQ(start.size(), trueStart.size() - 2);
    const Table* turns = project_->table(QStringLiteral("gs/turns"));
    const Table* truth = project_->table(QStringLiteral("gs/imu-truth"));
    for (std::size_t k = 0; k < start.size(); ++k) {
        EXPECT_NEAR(start[k], trueStart[k + 1], 0.15);
        EXPECT_EQ(turns->column(QStringLiteral("side"))->texts[qsizetype(k)],
                  truth->column(QStringLiteral("side"))->texts[qsizetype(k + 1)]);
    }
    int labelled = 0;
    for (const Annotation& a : project_->recording(QStringLiteral("gs"))->annotations)
        labelled += a.label == QLatin1String("turn left") || a.label == QLatin1String("turn right");
    EXPECT_EQ(labelled, int(start.size()));
}

TEST_F(SkiingProcessorsTest, RefusalsNameTheCauseAndStoreNothing) {
    simulate(QStringLiteral("xc"), QStringLiteral("xc/ski"));
    XcSkiingCyclesProcessor xc;
    SkimoPhasesProcessor skimo;
    AlpineTurnsProcessor alpine;
    const std::size_t annotations = project_->recording(QStringLiteral("xc"))->annotations.size();

    auto kind = run(xc, QStringLiteral("xc/ski-truth"), QStringLiteral("xc/c"));
    ASSERT_FALSE(kind.ok());
    EXPECT_TRUE(kind.message().contains(QStringLiteral("xc/ski-truth"))) << qPrintable(kind.message());

    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.columns = {{"acc_x", "m/s^2"}, {"acc_y", "m/s^2"}, {"acc_z", "m/s^2"}, {"gyr_x", "rad/s"}, {"gyr_z", "rad/s"}};
    StreamData d(400, 5);
    for (std::size_t k = 0; k < 400; ++k) {
        d.t[k] = 0.005 * double(k);
        d.at(k, 2) = 9.81;
    }
    project_->putStream(QStringLiteral("xc/nogyr"), Stream(info, d));
    auto missing = run(xc, QStringLiteral("xc/nogyr"), QStringLiteral("xc/c"));
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(missing.message().contains(QStringLiteral("gyr_y"))) << qPrintable(missing.message());
    EXPECT_TRUE(missing.message().contains(QStringLiteral("xc/nogyr")));

    info.columns = {{"acc_x", "m/s^2"}, {"acc_y", "m/s^2"}, {"acc_z", "m/s^2"},
                    {"gyr_x", "rad/s"}, {"gyr_y", "rad/s"}, {"gyr_z", "rad/s"}};
    StreamData still(400, 6);
    for (std::size_t k = 0; k < 400; ++k) {
        still.t[k] = 0.005 * double(k);
        still.at(k, 2) = 9.81;
    }
    project_->putStream(QStringLiteral("xc/still"), Stream(info, still));
    auto none = run(xc, QStringLiteral("xc/still"), QStringLiteral("xc/c"));
    ASSERT_FALSE(none.ok());
    EXPECT_TRUE(none.message().contains(QStringLiteral("no cross-country cycle found"))) << qPrintable(none.message());
    auto noPhase = run(skimo, QStringLiteral("xc/still"), QStringLiteral("xc/c"));
    ASSERT_FALSE(noPhase.ok());
    EXPECT_TRUE(noPhase.message().contains(QStringLiteral("no motionless phase found")))
        << qPrintable(noPhase.message());
    auto noTurn = run(alpine, QStringLiteral("xc/still"), QStringLiteral("xc/c"));
    ASSERT_FALSE(noTurn.ok());
    EXPECT_TRUE(noTurn.message().contains(QStringLiteral("no turn switch found"))) << qPrintable(noTurn.message());

    auto axes = run(xc, QStringLiteral("xc/ski"), QStringLiteral("xc/c"),
                    {{QStringLiteral("forward_axis"), QStringLiteral("y")}});
    ASSERT_FALSE(axes.ok());
    EXPECT_TRUE(axes.message().contains(QStringLiteral("ml_axis"))) << qPrintable(axes.message());
    auto bounds = run(xc, QStringLiteral("xc/ski"), QStringLiteral("xc/c"),
                      {{QStringLiteral("min_cycle"), 2.0}, {QStringLiteral("max_cycle"), 1.0}});
    ASSERT_FALSE(bounds.ok());
    EXPECT_TRUE(bounds.message().contains(QStringLiteral("max_cycle"))) << qPrintable(bounds.message());

    EXPECT_EQ(project_->table(QStringLiteral("xc/c")), nullptr);
    EXPECT_EQ(project_->recording(QStringLiteral("xc"))->annotations.size(), annotations);
}
