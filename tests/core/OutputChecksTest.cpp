// The run contract refuses outputs that hold nothing (issue #13 item 8, core/processing/OutputChecks.h):
// a stream with no rows, a stream of only NaN/∞, an empty table. The error names the processor and
// the output path, and nothing is stored, so the project is unchanged; a useful output still runs.
#include "core/processing/OutputStreams.h"
#include "core/processing/ProcessorRunner.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <cmath>
#include <limits>

using namespace athlos;

namespace {

// Produces what `result` asks for from its input: "copy", "empty", "nan" (every value NaN or ∞),
// "some-nan" (one finite value left), "empty-table" (a useful stream plus an empty table).
class ShapeProcessor : public Processor {
public:
    QString id() const override { return QStringLiteral("test-shape"); }
    QString name() const override { return id(); }
    QString description() const override { return id(); }
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override {
        return {ParameterSpec::choice(QStringLiteral("result"),
                                      {QStringLiteral("copy"), QStringLiteral("empty"), QStringLiteral("nan"),
                                       QStringLiteral("some-nan"), QStringLiteral("empty-table")},
                                      QStringLiteral("copy"), {})};
    }
    QList<InputSpec> inputs() const override { return {InputSpec{QStringLiteral("signal"), {}, false, false, {}}}; }
    QList<OutputSpec> outputs() const override {
        return {OutputSpec{{}, false, QString(), {}},
                OutputSpec{QStringLiteral("report"), true, QStringLiteral("report"), {}}};
    }
    Expected<std::vector<ProcessorOutput>> run(const RunContext& c) const override {
        auto input = c.samples(0);
        if (!input) return input.error();
        const QString result = c.text(QStringLiteral("result"));
        StreamData out = *input->data;
        if (result == QLatin1String("empty")) out = StreamData(0, out.columns);
        if (result == QLatin1String("nan") || result == QLatin1String("some-nan")) {
            for (std::size_t k = 0; k < out.values.size(); ++k)
                out.values[k] =
                    k % 2 ? std::numeric_limits<double>::quiet_NaN() : std::numeric_limits<double>::infinity();
            if (result == QLatin1String("some-nan")) out.values[3] = 1.0;
        }
        Table report;
        report.kind = QStringLiteral("report");
        report.columns = {TableColumn{QStringLiteral("n"), QStringLiteral("1"), false, {double(out.rows())}, {}}};
        if (result == QLatin1String("empty-table")) report.columns[0].numbers.clear();
        std::vector<ProcessorOutput> outputs;
        outputs.push_back({QString(), derivedStream(*input->stream, std::move(out))});
        outputs.push_back({QStringLiteral("report"), std::move(report)});
        return outputs;
    }
};

class OutputChecks : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        project_ = Project::create(dir_.filePath(QStringLiteral("p.athlos")));
        StreamInfo info;
        info.kind = QStringLiteral("imu");
        info.columns = {{QStringLiteral("acc_x"), QStringLiteral("m/s^2")},
                        {QStringLiteral("acc_y"), QStringLiteral("m/s^2")}};
        StreamData d(10, 2);
        for (std::size_t k = 0; k < 10; ++k) {
            d.t[k] = 0.01 * double(k);
            d.at(k, 0) = double(k);
            d.at(k, 1) = 1.0;
        }
        project_->putStream(QStringLiteral("rec/imu"), Stream(std::move(info), std::move(d)));
        project_->setModified(false);
    }
    Expected<RunOutcome> run(const char* result) {
        return runProcessor(*project_, processor_,
                            RunRequest{processor_.id(),
                                       {QStringLiteral("rec/imu")},
                                       QStringLiteral("rec/out"),
                                       {{QStringLiteral("result"), QString::fromLatin1(result)}}});
    }
    void expectUnchanged() {
        EXPECT_EQ(project_->stream(QStringLiteral("rec/out")), nullptr);
        EXPECT_EQ(project_->table(QStringLiteral("rec/out-report")), nullptr);
        EXPECT_FALSE(project_->isModified());
    }
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
    ShapeProcessor processor_;
};

}  // namespace

TEST_F(OutputChecks, EmptyStreamIsRefusedAndNothingStored) {
    auto outcome = run("empty");
    ASSERT_FALSE(outcome.ok());
    EXPECT_EQ(
        outcome.message(),
        QStringLiteral("test-shape: output 'rec/out' would be empty (0 rows): the run produced nothing to store"));
    expectUnchanged();
}

TEST_F(OutputChecks, AllNanStreamIsRefusedAndNothingStored) {
    auto outcome = run("nan");
    ASSERT_FALSE(outcome.ok());
    EXPECT_EQ(outcome.message(),
              QStringLiteral("test-shape: output 'rec/out': every value of its 10 rows × 2 columns is "
                             "NaN or infinite: the run produced nothing to store"));
    expectUnchanged();
}

TEST_F(OutputChecks, EmptyTableIsRefusedEvenAfterAUsefulStream) {
    auto outcome = run("empty-table");
    ASSERT_FALSE(outcome.ok());
    EXPECT_EQ(
        outcome.message(),
        QStringLiteral(
            "test-shape: output table 'rec/out-report' would be empty (0 rows): the run produced nothing to store"));
    expectUnchanged();  // the stream before it was not stored either
}

TEST_F(OutputChecks, OneFiniteValueOrAFullCopyIsStored) {
    for (const char* result : {"some-nan", "copy"}) {
        auto outcome = run(result);
        ASSERT_TRUE(outcome.ok()) << result << ": " << outcome.message().toStdString();
        EXPECT_NE(project_->stream(QStringLiteral("rec/out")), nullptr);
        EXPECT_NE(project_->table(QStringLiteral("rec/out-report")), nullptr);
    }
}
