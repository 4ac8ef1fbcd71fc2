// checkPipelineDone (athlos batch's skip rule): a pipeline counts as done only when every step's
// outputs carry provenance with the step's processor version, validated parameters and the current
// content hashes of its inputs — also after a save and a reload.
#include "core/processing/PipelineProvenance.h"
#include "core/processing/OutputStreams.h"
#include "core/processing/ProcessorRegistry.h"
#include "core/processing/ProcessorRunner.h"

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QTemporaryDir>

using namespace athlos;

namespace {

// Multiplies every sample by a factor (a double parameter with a default, and an integer one).
class ScaleProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("test-batch-scale"); }
    QString name() const override { return id(); }
    QString description() const override { return id(); }
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override {
        return {ParameterSpec::number(QStringLiteral("factor"), 2.0, -10, 10, {}, {}),
                ParameterSpec::integer(QStringLiteral("repeat"), 1, 1, 5, {})};
    }
    QList<InputSpec> inputs() const override { return {InputSpec{QStringLiteral("signal"), {}, false, false, {}}}; }
    QList<OutputSpec> outputs() const override { return {OutputSpec{}}; }
    Expected<std::vector<ProcessorOutput>> run(const RunContext& c) const override {
        const Stream& in = *c.stream(0);
        auto loaded = in.data();
        if (!loaded) return makeError(loaded.message());
        StreamData d = **loaded;
        double f = 1.0;
        for (int k = 0; k < c.integer(QStringLiteral("repeat")); ++k) f *= c.number(QStringLiteral("factor"));
        for (std::size_t r = 0; r < d.rows(); ++r) d.at(r, 0) *= f;
        std::vector<ProcessorOutput> out;
        out.push_back({QString(), derivedStream(in, std::move(d))});
        return out;
    }
};

Stream makeStream(double offset) {
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.columns = {{"acc_x", "m/s^2"}};
    StreamData d(50, 1);
    for (std::size_t k = 0; k < d.rows(); ++k) {
        d.t[k] = 0.1 * double(k);
        d.at(k, 0) = offset + double(k);
    }
    return Stream(std::move(info), std::move(d));
}

QJsonObject step(const QString& input, const QString& output, const QJsonObject& params) {
    return {{QStringLiteral("processor"), QStringLiteral("test-batch-scale")},
            {QStringLiteral("input"), input},
            {QStringLiteral("output"), output},
            {QStringLiteral("params"), params}};
}

class PipelineDone : public ::testing::Test {
protected:
    void SetUp() override {
        static bool registered = false;
        if (!registered) ProcessorRegistry::instance().add(std::make_shared<ScaleProcessor>());
        registered = true;
        ASSERT_TRUE(dir_.isValid());
        path_ = dir_.filePath(QStringLiteral("p.athlos"));
        project_ = Project::create(path_);
        project_->putStream(QStringLiteral("walk/imu"), makeStream(0.0));
        // Two chained steps; the second reads the first's output. Parameters as a user writes them:
        // an integer-valued factor (JSON integer) and the integer parameter left at its default.
        pipeline_ = {{QStringLiteral("steps"),
                      QJsonArray{step(QStringLiteral("walk/imu"), QStringLiteral("walk/a"), {{"factor", 3}}),
                                 step(QStringLiteral("walk/a"), QStringLiteral("walk/b"), {{"repeat", 2}})}}};
    }
    PipelineCheck check(const Project& p, const QJsonObject& pipeline) {
        auto c = checkPipelineDone(p, pipeline);
        EXPECT_TRUE(c.ok()) << qPrintable(c.message());
        return c.ok() ? *c : PipelineCheck{};
    }
    QTemporaryDir dir_;
    QString path_;
    std::unique_ptr<Project> project_;
    QJsonObject pipeline_;
};

}  // namespace

TEST_F(PipelineDone, NotDoneBeforeRunDoneAfterAndAfterReload) {
    PipelineCheck before = check(*project_, pipeline_);
    EXPECT_FALSE(before.done);
    EXPECT_TRUE(before.reason.contains(QStringLiteral("step 1"))) << qPrintable(before.reason);

    ASSERT_TRUE(runPipeline(*project_, pipeline_).ok());
    EXPECT_TRUE(check(*project_, pipeline_).done);

    ASSERT_TRUE(project_->save().ok());
    project_.reset();
    auto reopened = Project::open(path_);
    ASSERT_TRUE(reopened.ok()) << qPrintable(reopened.message());
    const PipelineCheck after = check(**reopened, pipeline_);
    EXPECT_TRUE(after.done) << qPrintable(after.reason);
}

TEST_F(PipelineDone, OtherParametersOrChangedInputsAreNotDone) {
    ASSERT_TRUE(runPipeline(*project_, pipeline_).ok());

    // The same step with the default written out explicitly is the same run.
    QJsonObject explicitDefault = pipeline_;
    QJsonArray steps = explicitDefault[QStringLiteral("steps")].toArray();
    steps[0] = step(QStringLiteral("walk/imu"), QStringLiteral("walk/a"), {{"factor", 3.0}, {"repeat", 1}});
    explicitDefault[QStringLiteral("steps")] = steps;
    EXPECT_TRUE(check(*project_, explicitDefault).done);

    // Another parameter in the second step.
    QJsonObject other = pipeline_;
    steps = other[QStringLiteral("steps")].toArray();
    steps[1] = step(QStringLiteral("walk/a"), QStringLiteral("walk/b"), {{"repeat", 3}});
    other[QStringLiteral("steps")] = steps;
    PipelineCheck c = check(*project_, other);
    EXPECT_FALSE(c.done);
    EXPECT_TRUE(c.reason.startsWith(QStringLiteral("step 2"))) << qPrintable(c.reason);
    EXPECT_TRUE(c.reason.contains(QStringLiteral("parameters"))) << qPrintable(c.reason);

    // New raw data under the same name: the first step's output is stale.
    project_->putStream(QStringLiteral("walk/imu"), makeStream(1.0));
    c = check(*project_, pipeline_);
    EXPECT_FALSE(c.done);
    EXPECT_TRUE(c.reason.contains(QStringLiteral("input 'walk/imu' changed"))) << qPrintable(c.reason);

    // A missing input is not done either (the run will then fail with the runner's reason).
    project_->removeItem(QStringLiteral("walk/imu"));
    c = check(*project_, pipeline_);
    EXPECT_FALSE(c.done);
    EXPECT_TRUE(c.reason.contains(QStringLiteral("missing"))) << qPrintable(c.reason);
}

TEST_F(PipelineDone, MalformedPipelinesAreErrors) {
    EXPECT_FALSE(checkPipelineDone(*project_, QJsonObject{}).ok());
    const QJsonObject unknown{
        {QStringLiteral("steps"), QJsonArray{QJsonObject{{QStringLiteral("processor"), QStringLiteral("no-such")}}}}};
    auto c = checkPipelineDone(*project_, unknown);
    ASSERT_FALSE(c.ok());
    EXPECT_TRUE(c.message().contains(QStringLiteral("no-such")));
    QJsonObject bad = pipeline_;
    QJsonArray steps = bad[QStringLiteral("steps")].toArray();
    steps[0] = step(QStringLiteral("walk/imu"), QStringLiteral("walk/a"), {{"factor", 99}});
    bad[QStringLiteral("steps")] = steps;
    c = checkPipelineDone(*project_, bad);
    ASSERT_FALSE(c.ok());
    EXPECT_TRUE(c.message().contains(QStringLiteral("factor"))) << qPrintable(c.message());
}
