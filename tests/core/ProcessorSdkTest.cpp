// The SDK a processor is written against (core/processing): RunContext reads inputs with one form
// of error (processor, input role, stream path), prepare() drives validate() by default, derived
// and new output streams leave provenance to the runner, time ranges map to row ranges, list
// parameters split, and Translator translates in a family's context.
#include "core/processing/OutputStreams.h"
#include "core/processing/ProcessorRunner.h"
#include "core/processing/RowRange.h"
#include "core/processing/Translator.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cmath>
#include <vector>

using namespace athlos;

namespace {

// Doubles its input; refuses streams shorter than `min_rows` in prepare().
class DoubleProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("test-double"); }
    QString name() const override { return id(); }
    QString description() const override { return id(); }
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override {
        return {ParameterSpec::integer(QStringLiteral("min_rows"), 2, 0, 1000, {})};
    }
    QList<InputSpec> inputs() const override {
        return {InputSpec{QStringLiteral("signal"), {}, false, false, {}},
                InputSpec{QStringLiteral("extra"), {}, false, true, {}}};
    }
    QList<OutputSpec> outputs() const override { return {OutputSpec{{}, false, QString(), {}}}; }
    Status prepare(const RunContext& c) const override {
        ++prepared;
        auto input = c.samples(0);
        if (!input) return input.error();
        if (int(input->data->rows()) < c.integer(QStringLiteral("min_rows")))
            return input->error(QStringLiteral("too short"));
        return {};
    }
    Expected<std::vector<ProcessorOutput>> run(const RunContext& c) const override {
        auto input = c.samples(0);
        if (!input) return input.error();
        StreamData out = *input->data;
        for (double& v : out.values) v *= 2.0;
        std::vector<ProcessorOutput> outputs;
        outputs.push_back({QString(), derivedStream(*input->stream, std::move(out))});
        return outputs;
    }
    mutable int prepared = 0;
};

StreamData ramp(std::size_t rows) {
    StreamData d(rows, 1);
    for (std::size_t k = 0; k < rows; ++k) {
        d.t[k] = 0.1 * double(k);
        d.at(k, 0) = double(k);
    }
    return d;
}

Stream signalStream(std::size_t rows) {
    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.frame = QStringLiteral("sensor");
    info.columns = {{QStringLiteral("acc_x"), QStringLiteral("m/s^2")}};
    info.attributes = QJsonObject{{QStringLiteral("device"), QStringLiteral("left foot")}};
    return Stream(std::move(info), ramp(rows));
}

class ProcessorSdk : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        project_ = Project::create(dir_.filePath(QStringLiteral("p.athlos")));
        project_->putStream(QStringLiteral("rec/imu"), signalStream(20));
        // A stream whose samples cannot be read (as if its file had gone).
        StreamInfo info = signalStream(1).info();
        info.rows = 5;
        project_->putStream(
            QStringLiteral("rec/lost"),
            Stream(info, FileSource{QStringLiteral("gone.athlos"), QStringLiteral("/recordings/rec/lost")},
                   [] { return Expected<StreamData>(makeError(QStringLiteral("gone.athlos: no such file"))); }));
    }
    Expected<RunOutcome> run(const QString& input, QVariantMap params = {}) {
        return runProcessor(*project_, processor_,
                            RunRequest{processor_.id(), {input}, QStringLiteral("rec/out"), params});
    }
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
    DoubleProcessor processor_;
};

}  // namespace

TEST_F(ProcessorSdk, DefaultValidateRunsPrepare) {
    auto outcome = run(QStringLiteral("rec/imu"), {{QStringLiteral("min_rows"), 50}});
    ASSERT_FALSE(outcome.ok());
    EXPECT_EQ(outcome.message(), QStringLiteral("test-double: input 'rec/imu' (signal): too short"));
    EXPECT_EQ(processor_.prepared, 1);
    EXPECT_EQ(project_->stream(QStringLiteral("rec/out")), nullptr);  // nothing stored
}

TEST_F(ProcessorSdk, UnreadableSamplesNameProcessorInputAndStream) {
    auto outcome = run(QStringLiteral("rec/lost"));
    ASSERT_FALSE(outcome.ok());
    EXPECT_EQ(
        outcome.message(),
        QStringLiteral("test-double: input 'rec/lost' (signal): cannot read its samples: gone.athlos: no such file"));
}

TEST_F(ProcessorSdk, DerivedStreamKeepsDescriptionAndGetsFreshProvenance) {
    auto outcome = run(QStringLiteral("rec/imu"));
    ASSERT_TRUE(outcome.ok()) << outcome.message().toStdString();
    const Stream* out = project_->stream(QStringLiteral("rec/out"));
    ASSERT_NE(out, nullptr);
    EXPECT_EQ(out->info().kind, QStringLiteral("imu"));
    EXPECT_EQ(out->info().frame, QStringLiteral("sensor"));
    EXPECT_EQ(out->info().columns, (Columns{{QStringLiteral("acc_x"), QStringLiteral("m/s^2")}}));
    EXPECT_EQ(out->info().attributes.value(QStringLiteral("device")).toString(), QStringLiteral("left foot"));
    EXPECT_EQ(out->info().provenance.processorId, QStringLiteral("test-double"));
    ASSERT_EQ(out->info().provenance.inputs.size(), 1u);
    EXPECT_EQ(out->info().provenance.inputs[0].name, QStringLiteral("rec/imu"));
    auto data = out->data();
    ASSERT_TRUE(data.ok());
    EXPECT_EQ((*data)->at(7, 0), 14.0);
    EXPECT_EQ(out->info().contentHash, (*data)->contentHash());
}

TEST(ProcessorSdkStreams, OutputStreamOnTheInputTimeAxis) {
    const StreamData in = ramp(4);
    StreamData d = samplesOnTimeAxis(in, 2);
    EXPECT_EQ(d.t, in.t);
    EXPECT_EQ(d.columns, 2);
    EXPECT_EQ(d.values, std::vector<double>(8, 0.0));
    d.at(3, 1) = 1.5;
    const Stream s = outputStream(QStringLiteral("orientation"), QStringLiteral("ENU"), columnsOf({"a", "b"}, {"rad"}),
                                  std::move(d), QJsonObject{{"mode", "6d"}});
    EXPECT_EQ(s.info().kind, QStringLiteral("orientation"));
    EXPECT_EQ(s.info().frame, QStringLiteral("ENU"));
    EXPECT_EQ(s.info().columns,
              (Columns{{QStringLiteral("a"), QStringLiteral("rad")}, {QStringLiteral("b"), QStringLiteral("1")}}));
    EXPECT_EQ(s.info().rows, 4);
    EXPECT_DOUBLE_EQ(s.info().tEnd, 0.3);
    EXPECT_TRUE(s.info().provenance.processorId.isEmpty());
    EXPECT_EQ(s.info().attributes.value(QStringLiteral("mode")).toString(), QStringLiteral("6d"));
}

TEST(ProcessorSdkIntervals, TimeRangeToRows) {
    const std::vector<double> t{0.0, 0.1, 0.2, 0.3, 0.4, 0.5};
    auto rows = [&](double a, double b) {
        const RowRange r = rowsInTimeRange(t, a, b);
        return std::pair{r.begin, r.end};
    };
    EXPECT_EQ(rows(0.1, 0.3), (std::pair<std::size_t, std::size_t>{1, 4}));  // both ends included
    EXPECT_EQ(rows(0.15, 0.35), (std::pair<std::size_t, std::size_t>{2, 4}));
    EXPECT_EQ(rows(-1.0, 10.0), (std::pair<std::size_t, std::size_t>{0, 6}));
    EXPECT_TRUE(rowsInTimeRange(t, 0.6, 1.0).empty());
    EXPECT_TRUE(rowsInTimeRange(t, 0.31, 0.39).empty());
    EXPECT_TRUE(rowsInTimeRange(t, 0.4, 0.2).empty());  // reversed
    EXPECT_EQ(rowsInTimeRange(t, 0.2, 0.2).size(), 1u);
    EXPECT_TRUE(rowsInTimeRange(std::vector<double>{}, 0.0, 1.0).empty());
}

TEST(ProcessorSdkParameters, SplitList) {
    EXPECT_EQ(splitList(QStringLiteral(" acc_x, acc_y ,,acc_z ")),
              (QStringList{QStringLiteral("acc_x"), QStringLiteral("acc_y"), QStringLiteral("acc_z")}));
    EXPECT_TRUE(splitList(QStringLiteral(" , ")).isEmpty());
}

TEST(ProcessorSdkTranslation, UntranslatedTextComesBack) {
    constexpr Translator tr{"athlos::test"};
    EXPECT_EQ(tr("Resample"), QStringLiteral("Resample"));
}
