// The gait-events processor through the real runner on the imported gaitmap walk: strides as
// predicted annotations (label per foot, source, confidence), the events table, re-runs replacing
// their own annotations, and clear errors.
#include "plugins/events/GaitEventsProcessor.h"

#include "core/io/Importer.h"
#include "core/processing/ProcessorRunner.h"
#include "tools/eval/GaitEvaluation.h"

#include <QDir>
#include <QTemporaryDir>
#include <gtest/gtest.h>

using namespace athlos;
using namespace athlos::events;

namespace {

const QString kImu = QStringLiteral(ATHLOS_SHARED_DATA_DIR "/gaitmap/imu_sample_ic_stride.csv");

class GaitEventsProcessorTest : public ::testing::Test {
protected:
    void SetUp() override {
        if (!QFileInfo::exists(kImu)) GTEST_SKIP() << "no gaitmap data";
        ASSERT_TRUE(dir_.isValid());
        project_ = Project::create(dir_.filePath(QStringLiteral("p.athlos")));
        ImportOptions options;
        options.format = QStringLiteral("gaitmap");
        options.target = QStringLiteral("walk");
        auto imported = importFile(kImu, options);
        ASSERT_TRUE(imported.ok()) << qPrintable(imported.message());
        ASSERT_TRUE(applyImport(*project_, std::move(imported).value(), false).ok());
    }
    Expected<RunOutcome> run(const QString& input, const QString& output, QVariantMap params = {}) {
        return runProcessor(*project_, processor_, RunRequest{processor_.id(), {input}, output, params});
    }
    QTemporaryDir dir_;
    std::unique_ptr<Project> project_;
    GaitEventsProcessor processor_;
};

}  // namespace

TEST_F(GaitEventsProcessorTest, StridesBecomePredictedAnnotations) {
    ASSERT_NE(project_->stream(QStringLiteral("walk/left-foot")), nullptr);
    auto left = run(QStringLiteral("walk/left-foot"), QStringLiteral("walk/left-foot-gait"));
    ASSERT_TRUE(left.ok()) << qPrintable(left.message());
    auto right = run(QStringLiteral("walk/right-foot"), QStringLiteral("walk/right-foot-gait"));
    ASSERT_TRUE(right.ok()) << qPrintable(right.message());
    EXPECT_EQ(left->written, QStringList{QStringLiteral("walk/left-foot-gait")});
    EXPECT_EQ(left->annotated, QStringList{QStringLiteral("walk/left-foot-gait")});

    // The same strides as the detector run directly on the file.
    auto direct = detectGaitmapFile(kImu);
    ASSERT_TRUE(direct.ok());
    std::map<QString, std::size_t> expected;
    for (const auto& f : *direct) expected[QStringLiteral("stride ") + f.foot] = f.strides.size();

    const Recording& rec = *project_->recording(QStringLiteral("walk"));
    std::map<QString, std::size_t> counts;
    for (const Annotation& a : rec.annotations) {
        ++counts[a.label];
        EXPECT_EQ(a.source, QStringLiteral("gait-events"));
        EXPECT_GT(a.tEnd - a.tStart, 0.5);
        EXPECT_LT(a.tEnd - a.tStart, 2.5);
        EXPECT_GE(a.confidence, 0.0);
        EXPECT_LE(a.confidence, 1.0);
    }
    EXPECT_EQ(counts, expected);
    EXPECT_GE(counts[QStringLiteral("stride left")], 20u);  // the file holds ~40 s of walking with turns

    const Table* table = project_->table(QStringLiteral("walk/left-foot-gait"));
    ASSERT_NE(table, nullptr);
    EXPECT_EQ(table->kind, QStringLiteral("gait-events"));
    EXPECT_EQ(table->provenance.processorId, QStringLiteral("gait-events"));
    EXPECT_EQ(table->attributes.value(QStringLiteral("swing_sign")).toInt(), -1);  // verified on the data
    const TableColumn* type = table->column(QStringLiteral("type"));
    ASSERT_NE(type, nullptr);
    // Every stride ends on an IC and starts on one (bouts add one more IC each).
    EXPECT_GE(type->texts.count(QStringLiteral("ic")), qsizetype(counts[QStringLiteral("stride left")] + 1));
    EXPECT_GT(type->texts.count(QStringLiteral("tc")), 0);
    EXPECT_GT(type->texts.count(QStringLiteral("min_vel")), 0);
    EXPECT_EQ(table->column(QStringLiteral("foot"))->texts.front(), QStringLiteral("left"));

    // A re-run with another label replaces exactly its own annotations.
    ASSERT_TRUE(run(QStringLiteral("walk/left-foot"), QStringLiteral("walk/left-foot-gait"),
                    {{QStringLiteral("label"), QStringLiteral("step cycle")}})
                    .ok());
    std::map<QString, std::size_t> after;
    for (const Annotation& a : project_->recording(QStringLiteral("walk"))->annotations) ++after[a.label];
    EXPECT_EQ(after[QStringLiteral("step cycle")], counts[QStringLiteral("stride left")]);
    EXPECT_EQ(after.count(QStringLiteral("stride left")), 0u);
    EXPECT_EQ(after[QStringLiteral("stride right")], counts[QStringLiteral("stride right")]);
}

TEST_F(GaitEventsProcessorTest, ClearErrors) {
    auto bad = run(QStringLiteral("walk/left-foot"), QStringLiteral("walk/g"),
                   {{QStringLiteral("min_stride"), 2.0}, {QStringLiteral("max_stride"), 1.0}});
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(bad.message().contains(QStringLiteral("max_stride"))) << qPrintable(bad.message());

    StreamInfo info;
    info.kind = QStringLiteral("imu");
    info.columns = {{"acc_x", "m/s^2"}, {"gyr_x", "deg/s"}, {"gyr_y", "deg/s"}, {"gyr_z", "deg/s"}};
    StreamData d(100, 4);
    for (std::size_t k = 0; k < 100; ++k) d.t[k] = 0.01 * double(k);
    project_->putStream(QStringLiteral("walk/degrees"), Stream(info, d));
    auto units = run(QStringLiteral("walk/degrees"), QStringLiteral("walk/g"));
    ASSERT_FALSE(units.ok());
    EXPECT_TRUE(units.message().contains(QStringLiteral("deg/s"))) << qPrintable(units.message());
    EXPECT_TRUE(units.message().contains(QStringLiteral("walk/degrees")));

    info.columns = {{"acc_x", "m/s^2"}};
    project_->putStream(QStringLiteral("walk/nogyr"), Stream(info, StreamData(10, 1)));
    auto missing = run(QStringLiteral("walk/nogyr"), QStringLiteral("walk/g"));
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(missing.message().contains(QStringLiteral("gyr_x"))) << qPrintable(missing.message());
    EXPECT_TRUE(project_->recording(QStringLiteral("walk"))->annotations.empty());  // nothing written on failure

    // Standing still: no event is an error with the reason, not an empty events table.
    info.columns = {{"gyr_x", "rad/s"}, {"gyr_y", "rad/s"}, {"gyr_z", "rad/s"}};
    StreamData still(500, 3);
    for (std::size_t k = 0; k < 500; ++k) still.t[k] = 0.01 * double(k);
    project_->putStream(QStringLiteral("walk/still"), Stream(info, still));
    auto none = run(QStringLiteral("walk/still"), QStringLiteral("walk/g"));
    ASSERT_FALSE(none.ok());
    EXPECT_TRUE(
        none.message().startsWith(QStringLiteral("gait-events: input 'walk/still' (imu): no gait event found in "
                                                 "4.99 s of data (ml_axis = auto [0.000, 1.000, 0.000], "
                                                 "swing_threshold = ")))
        << qPrintable(none.message());
    EXPECT_EQ(project_->table(QStringLiteral("walk/g")), nullptr);
}
