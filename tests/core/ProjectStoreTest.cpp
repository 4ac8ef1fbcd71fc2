// The HDF5 project store: round trips, lazy loading, undecoded copies and atomic saves.
#include "core/store/ProjectFile.h"
#include "tests/core/StoreTestData.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <atomic>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace athlos {
namespace {

using test::fileBytes;
using test::makeFullProject;

class ProjectStoreTest : public ::testing::Test {
protected:
    void SetUp() override {
        ASSERT_TRUE(dir_.isValid());
        path_ = dir_.filePath(QStringLiteral("Saison 2024 ä.athlos"));
    }
    std::unique_ptr<Project> saveFull() {
        auto project = makeFullProject(path_);
        const Status saved = project->save();
        EXPECT_TRUE(saved.ok()) << saved.message().toStdString();
        return project;
    }
    std::unique_ptr<Project> reopen(const QString& path) {
        auto opened = Project::open(path);
        EXPECT_TRUE(opened.ok()) << (opened ? std::string() : opened.message().toStdString());
        return opened ? std::move(opened).value() : nullptr;
    }
    QTemporaryDir dir_;
    QString path_;
};

std::shared_ptr<const StreamData> samples(const Stream& stream) {
    auto data = stream.data();
    EXPECT_TRUE(data.ok()) << (data ? std::string() : data.message().toStdString());
    return data ? *data : std::make_shared<const StreamData>();
}

// Everything but the samples, which the callers compare when they need them loaded.
void expectSameContent(const Project& expected, const Project& actual) {
    EXPECT_EQ(actual.meta().formatVersion, Project::kFormatVersion);
    EXPECT_EQ(actual.meta().appVersion, expected.meta().appVersion);
    EXPECT_EQ(actual.meta().created, expected.meta().created);
    EXPECT_EQ(actual.meta().modified, expected.meta().modified);
    EXPECT_EQ(actual.meta().sport, expected.meta().sport);
    EXPECT_EQ(actual.meta().extra, expected.meta().extra);
    EXPECT_EQ(actual.geometry(), expected.geometry());
    EXPECT_EQ(actual.annotationClasses(), expected.annotationClasses());
    EXPECT_EQ(actual.pipelineHistory(), expected.pipelineHistory());
    ASSERT_EQ(actual.recordingNames(), expected.recordingNames());
    ASSERT_EQ(actual.streamPaths(), expected.streamPaths());
    ASSERT_EQ(actual.tablePaths(), expected.tablePaths());
    for (const QString& name : expected.recordingNames()) {
        EXPECT_EQ(actual.recording(name)->name, name);
        EXPECT_EQ(actual.recording(name)->metadata, expected.recording(name)->metadata) << name.toStdString();
        EXPECT_EQ(actual.recording(name)->annotations, expected.recording(name)->annotations) << name.toStdString();
    }
    for (const QString& path : expected.streamPaths()) {
        SCOPED_TRACE(path.toStdString());
        const StreamInfo& a = actual.stream(path)->info();
        const StreamInfo& e = expected.stream(path)->info();
        EXPECT_EQ(a.name, e.name);
        EXPECT_EQ(a.kind, e.kind);
        EXPECT_EQ(a.frame, e.frame);
        EXPECT_EQ(a.columns, e.columns);
        EXPECT_EQ(a.attributes, e.attributes);
        EXPECT_EQ(a.provenance.toJson(), e.provenance.toJson());
        EXPECT_EQ(a.rows, e.rows);
        EXPECT_EQ(a.tBegin, e.tBegin);
        EXPECT_EQ(a.tEnd, e.tEnd);
        EXPECT_EQ(a.contentHash, e.contentHash);
    }
    for (const QString& path : expected.tablePaths()) {
        SCOPED_TRACE(path.toStdString());
        const Table& a = *actual.table(path);
        const Table& e = *expected.table(path);
        EXPECT_EQ(a.name, e.name);
        EXPECT_EQ(a.kind, e.kind);
        EXPECT_EQ(a.attributes, e.attributes);
        EXPECT_EQ(a.provenance.toJson(), e.provenance.toJson());
        ASSERT_EQ(a.columns.size(), e.columns.size());
        for (std::size_t i = 0; i < e.columns.size(); ++i) {
            EXPECT_EQ(a.columns[i].name, e.columns[i].name);
            EXPECT_EQ(a.columns[i].unit, e.columns[i].unit);
            EXPECT_EQ(a.columns[i].isText, e.columns[i].isText);
            EXPECT_EQ(a.columns[i].numbers, e.columns[i].numbers);
            EXPECT_EQ(a.columns[i].texts, e.columns[i].texts);
        }
    }
}

void expectSameSamples(const Project& expected, const Project& actual) {
    for (const QString& path : expected.streamPaths()) {
        SCOPED_TRACE(path.toStdString());
        auto e = samples(*expected.stream(path));
        auto a = samples(*actual.stream(path));
        EXPECT_EQ(a->columns, e->columns);
        EXPECT_EQ(a->t, e->t);  // bit-exact
        EXPECT_EQ(a->values, e->values);
        EXPECT_EQ(a->contentHash(), actual.stream(path)->info().contentHash);
    }
}

TEST_F(ProjectStoreTest, RoundTripsEveryKindOfContent) {
    auto original = saveFull();
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    EXPECT_EQ(opened->path(), QFileInfo(path_).absoluteFilePath());
    EXPECT_FALSE(opened->isModified());
    expectSameContent(*original, *opened);
    expectSameSamples(*original, *opened);
    // Spot checks that do not rely on the generator.
    EXPECT_EQ(opened->stream(QStringLiteral("run1/empty"))->info().rows, 0);
    EXPECT_EQ(samples(*opened->stream(QStringLiteral("run1/empty")))->columns, 3);
    EXPECT_EQ(samples(*opened->stream(QStringLiteral("run1/events")))->rows(), 7u);
    EXPECT_EQ(opened->stream(QStringLiteral("run2/lps"))->info().rows, 300000);
    EXPECT_EQ(opened->table(QStringLiteral("run1/beacons"))->columns[0].texts.at(1), QStringLiteral("Bäke 2"));
    EXPECT_EQ(opened->stream(QStringLiteral("run2/filtered"))
                  ->info()
                  .provenance.parameters.value(QStringLiteral("order"))
                  .toInt(),
              4);
}

TEST_F(ProjectStoreTest, EmptyProjectRoundTrips) {
    auto project = Project::create(path_, QStringLiteral("football"));
    ASSERT_TRUE(project->save().ok());
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    expectSameContent(*project, *opened);
    EXPECT_TRUE(opened->recordingNames().isEmpty());
}

TEST_F(ProjectStoreTest, OpenReadsMetadataButNoSamples) {
    auto original = saveFull();
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    for (const QString& path : opened->streamPaths()) {
        SCOPED_TRACE(path.toStdString());
        const Stream& stream = *opened->stream(path);
        EXPECT_FALSE(stream.isLoaded());
        ASSERT_TRUE(stream.fileSource().has_value());
        EXPECT_EQ(stream.fileSource()->file, QFileInfo(path_).absoluteFilePath());
        EXPECT_EQ(stream.fileSource()->group, QStringLiteral("/recordings/") + path);
        EXPECT_EQ(stream.info().rows, original->stream(path)->info().rows);
        EXPECT_EQ(stream.info().tEnd, original->stream(path)->info().tEnd);
        EXPECT_FALSE(stream.info().contentHash.isEmpty());
    }
    const Stream& lps = *opened->stream(QStringLiteral("run2/lps"));
    EXPECT_TRUE(lps.data().ok());
    EXPECT_TRUE(lps.isLoaded());
    EXPECT_FALSE(opened->stream(QStringLiteral("run1/imu"))->isLoaded());
}

TEST_F(ProjectStoreTest, SavingUnloadedStreamsCopiesTheirSamples) {
    auto original = saveFull();
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    // Metadata edits on an unloaded stream must be saved even though its samples are copied.
    opened->stream(QStringLiteral("run1/imu"))->info().attributes[QStringLiteral("note")] = QStringLiteral("checked");
    original->stream(QStringLiteral("run1/imu"))->info().attributes[QStringLiteral("note")] = QStringLiteral("checked");

    const QString other = dir_.filePath(QStringLiteral("copy.athlos"));
    ASSERT_TRUE(opened->saveAs(other).ok());
    for (const QString& path : opened->streamPaths()) {
        EXPECT_FALSE(opened->stream(path)->isLoaded()) << "saving decoded " << path.toStdString();
        EXPECT_EQ(opened->stream(path)->fileSource()->file, QFileInfo(other).absoluteFilePath());
    }
    // Saving in place copies from the very file that is then replaced.
    ASSERT_TRUE(opened->save().ok());
    auto again = reopen(other);
    ASSERT_TRUE(again);
    original->meta() = again->meta();  // saving stamps modified/app version
    expectSameContent(*original, *again);
    expectSameSamples(*original, *again);
    // The rebound loaders of the saved project read the new file.
    expectSameSamples(*original, *opened);
}

TEST_F(ProjectStoreTest, LargeJsonAttributesRoundTrip) {
    auto project = makeFullProject(path_);
    QJsonArray steps;
    for (int i = 0; i < 5000; ++i) steps.append(QStringLiteral("step %1 with a fairly long description").arg(i));
    project->pipelineHistory().append(QJsonObject{{QStringLiteral("steps"), steps}});  // ~250 kB > 64 kB header limit
    ASSERT_TRUE(project->save().ok());
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    EXPECT_EQ(opened->pipelineHistory(), project->pipelineHistory());
}

TEST_F(ProjectStoreTest, ConcurrentLazyLoadsAreSafe) {
    auto original = saveFull();
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    const QStringList paths = opened->streamPaths();
    std::vector<std::thread> threads;
    std::atomic<int> failures = 0;
    for (int k = 0; k < 4; ++k)
        threads.emplace_back([&, k] {
            for (int i = 0; i < paths.size(); ++i) {
                const QString& path = paths[(i + k) % paths.size()];
                auto direct = ProjectFile::loadStream(path_, QStringLiteral("/recordings/") + path,
                                                      int(opened->stream(path)->info().columns.size()));
                auto lazy = opened->stream(path)->data();
                if (!direct || !lazy || direct->t != (*lazy)->t || direct->values != (*lazy)->values) ++failures;
            }
        });
    for (auto& t : threads) t.join();
    EXPECT_EQ(failures.load(), 0);
    expectSameSamples(*original, *opened);
}

TEST_F(ProjectStoreTest, CancelledSaveLeavesTheFileUntouched) {
    saveFull();
    const QByteArray before = fileBytes(path_);
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    opened->putStream(QStringLiteral("run3/big"),
                      test::makeStream(QStringLiteral("imu"), test::imuColumns(), test::makeSamples(400000, 6, 9)));
    CancelToken token;
    int reports = 0;
    double cancelledAt = -1;
    Progress progress(
        [&](double fraction, const QString&) {
            ++reports;
            if (fraction > 0.3 && cancelledAt < 0) {
                cancelledAt = fraction;
                token.cancel();
            }
        },
        token);
    const Status saved = opened->save(progress);
    ASSERT_FALSE(saved.ok());
    EXPECT_EQ(saved.message(), QStringLiteral("cancelled"));
    EXPECT_GT(cancelledAt, 0.3);
    EXPECT_LT(cancelledAt, 1.0) << "cancellation must be polled while writing, not only at the end";
    EXPECT_EQ(fileBytes(path_), before);
    EXPECT_EQ(test::strayFiles(dir_.path(), {QFileInfo(path_).fileName()}), QStringList());
    EXPECT_TRUE(opened->isModified());
    // The project is still intact and can be saved.
    ASSERT_TRUE(opened->save().ok());
    auto again = reopen(path_);
    ASSERT_TRUE(again);
    EXPECT_EQ(again->stream(QStringLiteral("run3/big"))->info().rows, 400000);
}

TEST_F(ProjectStoreTest, FailedWriteLeavesNoTemporaryFile) {
    saveFull();
    const QByteArray before = fileBytes(path_);
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    // Samples with two columns under three column names: the store refuses while writing.
    Stream bad =
        test::makeStream(QStringLiteral("imu"), {{"a", "1"}, {"b", "1"}, {"c", "1"}}, test::makeSamples(10, 2, 5));
    opened->putStream(QStringLiteral("run1/zz-bad"), std::move(bad));
    const Status saved = opened->save();
    ASSERT_FALSE(saved.ok());
    EXPECT_TRUE(saved.message().contains(QStringLiteral("run1/zz-bad"))) << saved.message().toStdString();
    EXPECT_EQ(fileBytes(path_), before);
    EXPECT_EQ(test::strayFiles(dir_.path(), {QFileInfo(path_).fileName()}), QStringList());
}

TEST_F(ProjectStoreTest, RefusesNamesThatAreNotHdf5Links) {
    auto project = Project::create(path_);
    project->putStream(QStringLiteral("run1/a/b"),
                       test::makeStream(QStringLiteral("imu"), {{"x", "m"}}, test::makeSamples(3, 1, 1)));
    const QString target = dir_.filePath(QStringLiteral("direct.athlos"));
    const Status written = ProjectFile::write(*project, target);
    ASSERT_FALSE(written.ok());
    EXPECT_TRUE(written.message().contains(QStringLiteral("a/b"))) << written.message().toStdString();
    EXPECT_TRUE(written.message().contains(QStringLiteral("direct.athlos"))) << written.message().toStdString();
    EXPECT_FALSE(QFile::exists(target));
}

// A process that dies in the middle of a save (here: _exit from the progress callback of a forked
// child) must leave the previous file exactly as it was.
TEST_F(ProjectStoreTest, CrashDuringSaveLeavesThePreviousFile) {
    saveFull();
    const QByteArray before = fileBytes(path_);
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        auto opened = Project::open(path_);
        if (!opened) _exit(2);
        (*opened)->putStream(QStringLiteral("run3/big"), test::makeStream(QStringLiteral("imu"), test::imuColumns(),
                                                                          test::makeSamples(400000, 6, 9)));
        (void)(*opened)->save(Progress([](double fraction, const QString&) {
            if (fraction > 0.5) _exit(3);
        }));
        _exit(4);  // the save finished: the crash was not simulated
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_EQ(WEXITSTATUS(status), 3);
    EXPECT_EQ(fileBytes(path_), before);
    // The dead process's temporary file and lock remain (nobody could delete them), but they are
    // not the project.
    QStringList stray = test::strayFiles(dir_.path(), {QFileInfo(path_).fileName()});
    stray.sort();
    ASSERT_EQ(stray.size(), 2);
    EXPECT_EQ(stray[0], QLatin1Char('.') + QFileInfo(path_).fileName() + QStringLiteral(".lock"));
    EXPECT_TRUE(stray[1].startsWith(QLatin1Char('.') + QFileInfo(path_).fileName() + QStringLiteral(".tmp-")));
    auto opened = reopen(path_);
    ASSERT_TRUE(opened);
    EXPECT_EQ(opened->stream(QStringLiteral("run3/big")), nullptr);
    // The next writer takes over the dead process's lock and removes its unfinished save, saying so.
    {
        auto writer = Project::openForChange(path_);
        ASSERT_TRUE(writer.ok()) << writer.message().toStdString();
        ASSERT_EQ((*writer)->notes().size(), 1);
        EXPECT_TRUE((*writer)->notes()[0].contains(QStringLiteral("removed"))) << (*writer)->notes()[0].toStdString();
    }
    EXPECT_TRUE(test::strayFiles(dir_.path(), {QFileInfo(path_).fileName()}).isEmpty());
    EXPECT_EQ(fileBytes(path_), before);
}

}  // namespace
}  // namespace athlos
