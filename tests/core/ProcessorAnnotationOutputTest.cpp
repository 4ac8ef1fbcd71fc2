// Processors that output predicted annotations (ProcessorOutput holding Annotations): the runner
// tags them with source and output path, a re-run replaces exactly its own annotations, a failed
// pipeline restores them, provenance is recorded, and they survive a save.
#include "core/processing/ProcessorRegistry.h"
#include "core/processing/ProcessorRunner.h"

#include <gtest/gtest.h>

#include <QJsonArray>
#include <QTemporaryDir>

using namespace athlos;

namespace {

// One annotation per whole second of the input, label from a parameter; fails on demand.
class PredictProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("test-predict"); }
    QString name() const override { return id(); }
    QString description() const override { return id(); }
    QString version() const override { return QStringLiteral("3"); }
    ParameterSpecs parameters() const override {
        return {ParameterSpec::text(QStringLiteral("label"), QStringLiteral("step"), {}),
                ParameterSpec::boolean(QStringLiteral("fail"), false, {})};
    }
    QList<InputSpec> inputs() const override { return {InputSpec{QStringLiteral("signal"), {}, false, false, {}}}; }
    QList<OutputSpec> outputs() const override {
        return {OutputSpec{QStringLiteral("events"), true, QString(), {}}, OutputSpec{{}, false, QString(), {}, true}};
    }
    Expected<std::vector<ProcessorOutput>> run(const RunContext& c) const override {
        if (c.flag(QStringLiteral("fail"))) return makeError(QStringLiteral("asked to fail"));
        const StreamInfo& info = c.stream(0)->info();
        Annotations out;
        Table table;
        table.kind = QStringLiteral("events");
        TableColumn t{QStringLiteral("t"), QStringLiteral("s"), false, {}, {}};
        for (double s = std::ceil(info.tBegin); s + 1.0 <= info.tEnd; s += 1.0) {
            // Out-of-range confidence and a reversed interval: the runner must tidy both up.
            out.push_back({c.text(QStringLiteral("label")), s + 1.0, s, QStringLiteral("ignored"), s < 1.0 ? 1.7 : 0.4,
                           QStringLiteral("ignored")});
            t.numbers.push_back(s);
        }
        table.columns.push_back(t);
        std::vector<ProcessorOutput> outputs;
        outputs.push_back({QString(), std::move(table)});
        outputs.push_back({QString(), std::move(out)});
        return outputs;
    }
};

Stream makeStream(double seconds) {
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.columns = {{"acc_x", "m/s^2"}};
    StreamData d(std::size_t(seconds * 10) + 1, 1);
    for (std::size_t k = 0; k < d.rows(); ++k) d.t[k] = 0.1 * double(k);
    return Stream(std::move(info), std::move(d));
}

int countSource(const Recording& r, const QString& annotator) {
    return int(std::count_if(r.annotations.begin(), r.annotations.end(), [&](const Annotation& a) {
        return a.source == QLatin1String("test-predict") && a.annotator == annotator;
    }));
}

class AnnotationOutput : public ::testing::Test {
protected:
    void SetUp() override {
        static bool registered = false;
        if (!registered) ProcessorRegistry::instance().add(std::make_shared<PredictProcessor>());
        registered = true;
        ASSERT_TRUE(dir_.isValid());
        project_ = Project::create(dir_.filePath(QStringLiteral("p.athlos")));
        project_->putStream(QStringLiteral("walk/imu"), makeStream(5.0));
        project_->recording(QStringLiteral("walk"))
            ->annotations.push_back(
                {QStringLiteral("step"), 0.5, 0.7, QStringLiteral("me"), 1.0, QStringLiteral("manual")});
    }
    Expected<RunOutcome> run(const QString& output, QVariantMap params = {}) {
        return runProcessor(*project_,
                            RunRequest{QStringLiteral("test-predict"), {QStringLiteral("walk/imu")}, output, params});
    }
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
};

}  // namespace

TEST_F(AnnotationOutput, RunnerTagsClampsAndRecordsProvenance) {
    auto outcome = run(QStringLiteral("walk/pred"));
    ASSERT_TRUE(outcome.ok()) << qPrintable(outcome.message());
    EXPECT_EQ(outcome->written, QStringList{QStringLiteral("walk/pred")});  // the table
    EXPECT_EQ(outcome->annotated, QStringList{QStringLiteral("walk/pred")});
    const Recording& rec = *project_->recording(QStringLiteral("walk"));
    ASSERT_EQ(rec.annotations.size(), 6u);  // manual + 5
    EXPECT_EQ(rec.annotations[0].source, QStringLiteral("manual"));
    for (std::size_t k = 1; k < rec.annotations.size(); ++k) {
        const Annotation& a = rec.annotations[k];
        EXPECT_EQ(a.source, QStringLiteral("test-predict"));
        EXPECT_EQ(a.annotator, QStringLiteral("walk/pred"));
        EXPECT_LT(a.tStart, a.tEnd);
        EXPECT_GE(a.confidence, 0.0);
        EXPECT_LE(a.confidence, 1.0);
    }
    EXPECT_EQ(rec.annotations[1].confidence, 1.0);
    EXPECT_EQ(rec.annotations[2].confidence, 0.4);
    const QJsonObject prov = rec.metadata.value(QStringLiteral("annotation_provenance"))
                                 .toObject()
                                 .value(QStringLiteral("walk/pred"))
                                 .toObject();
    const Provenance p = Provenance::fromJson(prov);
    EXPECT_EQ(p.processorId, QStringLiteral("test-predict"));
    EXPECT_EQ(p.processorVersion, QStringLiteral("3"));
    ASSERT_EQ(p.inputs.size(), 1u);
    EXPECT_EQ(p.inputs[0].name, QStringLiteral("walk/imu"));
    EXPECT_EQ(project_->table(QStringLiteral("walk/pred"))->provenance.processorId, QStringLiteral("test-predict"));
}

TEST_F(AnnotationOutput, RerunReplacesOnlyItsOwnAnnotations) {
    ASSERT_TRUE(run(QStringLiteral("walk/pred")).ok());
    ASSERT_TRUE(run(QStringLiteral("walk/other"), {{QStringLiteral("label"), QStringLiteral("other")}}).ok());
    ASSERT_TRUE(run(QStringLiteral("walk/pred"), {{QStringLiteral("label"), QStringLiteral("stride")}}).ok());
    const Recording& rec = *project_->recording(QStringLiteral("walk"));
    EXPECT_EQ(rec.annotations.size(), 11u);
    EXPECT_EQ(countSource(rec, QStringLiteral("walk/pred")), 5);
    EXPECT_EQ(countSource(rec, QStringLiteral("walk/other")), 5);
    for (const auto& a : rec.annotations)
        if (a.annotator == QLatin1String("walk/pred")) {
            EXPECT_EQ(a.label, QStringLiteral("stride"));
        }
    EXPECT_EQ(rec.annotations[0].source, QStringLiteral("manual"));
}

TEST_F(AnnotationOutput, FailedPipelineRestoresAnnotationsAndMetadata) {
    ASSERT_TRUE(run(QStringLiteral("walk/pred")).ok());
    const Recording before = *project_->recording(QStringLiteral("walk"));
    project_->setModified(false);
    const QJsonObject pipeline{
        {QStringLiteral("steps"),
         QJsonArray{
             QJsonObject{{QStringLiteral("processor"), QStringLiteral("test-predict")},
                         {QStringLiteral("input"), QStringLiteral("walk/imu")},
                         {QStringLiteral("output"), QStringLiteral("walk/pred")},
                         {QStringLiteral("params"), QJsonObject{{QStringLiteral("label"), QStringLiteral("new")}}}},
             QJsonObject{{QStringLiteral("processor"), QStringLiteral("test-predict")},
                         {QStringLiteral("input"), QStringLiteral("walk/imu")},
                         {QStringLiteral("output"), QStringLiteral("walk/more")}},
             QJsonObject{{QStringLiteral("processor"), QStringLiteral("test-predict")},
                         {QStringLiteral("input"), QStringLiteral("walk/imu")},
                         {QStringLiteral("output"), QStringLiteral("walk/x")},
                         {QStringLiteral("params"), QJsonObject{{QStringLiteral("fail"), true}}}}}}};
    auto result = runPipeline(*project_, pipeline);
    ASSERT_FALSE(result.ok());
    const Recording& after = *project_->recording(QStringLiteral("walk"));
    EXPECT_EQ(after.annotations, before.annotations);
    EXPECT_EQ(after.metadata, before.metadata);
    EXPECT_FALSE(project_->isModified());
    // The same pipeline without the failing step succeeds and records the annotation outputs.
    QJsonObject ok = pipeline;
    QJsonArray steps = ok.value(QStringLiteral("steps")).toArray();
    steps.removeLast();
    ok[QStringLiteral("steps")] = steps;
    ASSERT_TRUE(runPipeline(*project_, ok).ok());
    const QJsonObject last = project_->pipelineHistory().last().toObject();
    EXPECT_EQ(
        last.value(QStringLiteral("steps")).toArray()[1].toObject().value(QStringLiteral("annotations")).toArray(),
        QJsonArray{QStringLiteral("walk/more")});
    EXPECT_EQ(countSource(*project_->recording(QStringLiteral("walk")), QStringLiteral("walk/pred")), 5);
}

TEST_F(AnnotationOutput, AnnotationsAndProvenanceSurviveSave) {
    ASSERT_TRUE(run(QStringLiteral("walk/pred")).ok());
    ASSERT_TRUE(project_->save().ok());
    auto reopened = Project::open(project_->path());
    ASSERT_TRUE(reopened.ok()) << qPrintable(reopened.message());
    const Recording& rec = *(*reopened)->recording(QStringLiteral("walk"));
    EXPECT_EQ(rec.annotations, project_->recording(QStringLiteral("walk"))->annotations);
    EXPECT_TRUE(
        rec.metadata.value(QStringLiteral("annotation_provenance")).toObject().contains(QStringLiteral("walk/pred")));
}
