// wrist-speed: the k-means + local linear model trained on simulated walkers and scored on other
// walkers (split by subject: other seeds and heights), against baselines it must beat; the model's
// JSON round trip; and train → apply through the runner with clear errors.
#include "plugins/events/SimulateWristWalkProcessor.h"
#include "plugins/events/WristCadenceProcessor.h"
#include "plugins/events/WristSpeedProcessor.h"
#include "tools/eval/WristEvaluation.h"

#include "core/processing/ProcessorRunner.h"

#include <QTemporaryDir>
#include <cmath>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::events;

namespace {

std::vector<WristTrial> trials(unsigned firstSeed, int count, double h0, double h1) {
    WristWalkParams base;
    base.duration = 400.0;
    std::vector<WristTrial> out;
    for (int i = 0; i < count; ++i)
        out.push_back(simulateWristTrial({firstSeed + unsigned(i), h0 + (h1 - h0) * i / std::max(1, count - 1)}, base));
    return out;
}

ErrorSummary errors(const WristSpeedModel& m, const std::vector<WristFeatures>& x, const std::vector<double>& v) {
    std::vector<double> e;
    for (std::size_t k = 0; k < x.size(); ++k) e.push_back(100.0 * (m.predict(x[k]) - v[k]) / v[k]);
    return summarize(e);
}

}  // namespace

TEST(WristSpeed, ClusteredModelGeneralisesToOtherWalkers) {
    std::vector<WristFeatures> xTrain, xTest;
    std::vector<double> vTrain, vTest;
    speedRows(trials(501, 6, 1.55, 1.95), xTrain, vTrain);
    speedRows(trials(601, 3, 1.6, 1.9), xTest, vTest);
    ASSERT_GT(xTrain.size(), 1000u);
    ASSERT_GT(xTest.size(), 400u);
    QString error;
    const WristSpeedModel model = WristSpeedModel::train(xTrain, vTrain, {}, &error);
    ASSERT_TRUE(model.valid()) << qPrintable(error);
    const ErrorSummary s = errors(model, xTest, vTest);
    EXPECT_LE(std::abs(s.median), 2.0) << s.median;  // thesis −0.67 %
    EXPECT_LE(s.medianAbs, 5.0) << s.medianAbs;
    // Baselines it must beat: the training mean, and the model without the barometer (slopes).
    double mean = 0.0;
    for (double v : vTrain) mean += v;
    mean /= double(vTrain.size());
    std::vector<double> constant;
    for (double v : vTest) constant.push_back(100.0 * (mean - v) / v);
    EXPECT_LT(2.0 * s.medianAbs, summarize(constant).medianAbs);
    auto zeroed = [](std::vector<WristFeatures> x) {
        for (auto& r : x) r[2] = 0.0;
        return x;
    };
    const ErrorSummary noBaro = errors(WristSpeedModel::train(zeroed(xTrain), vTrain, {}), zeroed(xTest), vTest);
    EXPECT_LT(s.q75 - s.q25, noBaro.q75 - noBaro.q25);

    // JSON round trip predicts the same.
    QString jsonError;
    const WristSpeedModel back = WristSpeedModel::fromJson(model.toJson(), &jsonError);
    ASSERT_TRUE(back.valid()) << qPrintable(jsonError);
    for (std::size_t k = 0; k < 50; ++k) EXPECT_DOUBLE_EQ(back.predict(xTest[k]), model.predict(xTest[k]));
    EXPECT_FALSE(WristSpeedModel::fromJson(QJsonObject{}, &jsonError).valid());
    EXPECT_FALSE(jsonError.isEmpty());
}

TEST(WristSpeed, TrainThenApplyThroughTheRunner) {
    QTemporaryDir dir;
    auto project = Project::create(dir.filePath(QStringLiteral("p.athlos")));
    SimulateWristWalkProcessor sim;
    WristCadenceProcessor cadence;
    WristSpeedTrainProcessor train;
    WristSpeedProcessor speed;
    auto ok = [&](const Processor& p, QStringList in, const QString& out, QVariantMap params) {
        auto r = runProcessor(*project, p, RunRequest{p.id(), in, out, params});
        EXPECT_TRUE(r.ok()) << qPrintable(p.id() + ": " + r.message());
        return r.ok();
    };
    const struct {
        const char* rec;
        int seed;
        double height;
    } walkers[] = {{"a", 11, 1.60}, {"b", 12, 1.90}, {"d", 14, 1.70}, {"e", 15, 1.80}, {"c", 13, 1.75}};
    for (const auto& w : walkers) {
        const QString r = QString::fromLatin1(w.rec);
        ASSERT_TRUE(ok(sim, {}, r + "/wrist", {{"seed", w.seed}, {"height", w.height}, {"duration", 400.0}}));
        ASSERT_TRUE(ok(cadence, {r + "/wrist"}, r + "/cadence", {}));
    }
    // Training chained over four walkers (c is held out).
    ASSERT_TRUE(ok(train, {"a/cadence", "a/wrist-barometer", "a/wrist-truth"}, "a/model", {{"height", 1.60}}));
    ASSERT_TRUE(
        ok(train, {"d/cadence", "d/wrist-barometer", "d/wrist-truth", "a/model"}, "d/model", {{"height", 1.70}}));
    ASSERT_TRUE(
        ok(train, {"e/cadence", "e/wrist-barometer", "e/wrist-truth", "d/model"}, "e/model", {{"height", 1.80}}));
    ASSERT_TRUE(
        ok(train, {"b/cadence", "b/wrist-barometer", "b/wrist-truth", "e/model"}, "b/model", {{"height", 1.90}}));
    const Table* model = project->table(QStringLiteral("b/model"));
    ASSERT_NE(model, nullptr);
    EXPECT_EQ(model->kind, QStringLiteral("wrist-speed-model"));
    EXPECT_EQ(model->attributes.value("rows_from_previous").toInt(), int(project->table("e/model")->rows()));
    EXPECT_EQ(model->rows(), project->table("e/model")->rows() + model->attributes.value("rows_added").toInt());

    ASSERT_TRUE(ok(speed, {"c/cadence", "c/wrist-barometer", "b/model"}, "c/speed", {{"height", 1.72}}));
    const StreamData& v = **project->stream(QStringLiteral("c/speed"))->data();
    const StreamData& truth = **project->stream(QStringLiteral("c/wrist-truth"))->data();
    std::vector<double> e;
    for (std::size_t k = 0; k < v.rows(); ++k) {
        if (!std::isfinite(v.at(k, 0))) continue;
        const auto i = std::size_t(std::lround(v.t[k] * 10.0));
        if (i < truth.rows() && truth.at(i, 4) > 0.5 && truth.at(i, 1) > 0.5)
            e.push_back(100.0 * (v.at(k, 0) - truth.at(i, 1)) / truth.at(i, 1));
    }
    ASSERT_GT(e.size(), 150u);
    // Four short training walkers only: the plumbing, not the accuracy (WristSpeed.ClusteredModel…).
    EXPECT_LE(summarize(e).medianAbs, 20.0) << summarize(e).median;

    // Errors: no height, no model, a reference without speed.
    auto noHeight = runProcessor(*project, speed,
                                 RunRequest{speed.id(), {"c/cadence", "c/wrist-barometer", "b/model"}, "c/speed2", {}});
    ASSERT_FALSE(noHeight.ok());
    EXPECT_TRUE(noHeight.message().contains("height")) << qPrintable(noHeight.message());
    auto noModel = runProcessor(
        *project, speed, RunRequest{speed.id(), {"c/cadence", "c/wrist-barometer"}, "c/speed2", {{"height", 1.7}}});
    ASSERT_FALSE(noModel.ok());
    auto noSpeed =
        runProcessor(*project, train,
                     RunRequest{train.id(), {"c/cadence", "c/wrist-barometer", "c/wrist"}, "c/m", {{"height", 1.7}}});
    ASSERT_FALSE(noSpeed.ok());
    EXPECT_TRUE(noSpeed.message().contains("speed")) << qPrintable(noSpeed.message());
    EXPECT_EQ(project->stream(QStringLiteral("c/speed2")), nullptr);
    EXPECT_EQ(project->table(QStringLiteral("c/m")), nullptr);
}
