// Issue #11: nothing unexpected loads. Plugins come only from ATHLOS_PLUGIN_PATH and the install
// folder; a plugin whose processors differ from its metadata is refused, a processor id registered
// twice keeps the first.
#include "core/processing/ProcessorRegistry.h"

#include <gtest/gtest.h>

#include <QDir>

namespace athlos {
namespace {

class NamedProcessor final : public Processor {
public:
    explicit NamedProcessor(QString id) : id_(std::move(id)) {}
    QString id() const override { return id_; }
    QString name() const override { return id_; }
    QString description() const override { return {}; }
    QString version() const override { return QStringLiteral("1"); }
    ParameterSpecs parameters() const override { return {}; }
    QList<InputSpec> inputs() const override { return {}; }
    QList<OutputSpec> outputs() const override { return {}; }
    Expected<std::vector<ProcessorOutput>> run(const RunContext&) const override {
        return std::vector<ProcessorOutput>{};
    }

private:
    QString id_;
};

std::vector<std::shared_ptr<const Processor>> processors(const QStringList& ids) {
    std::vector<std::shared_ptr<const Processor>> list;
    for (const QString& id : ids) list.push_back(std::make_shared<NamedProcessor>(id));
    return list;
}

TEST(ProcessorRegistry, PluginWhoseProcessorsDifferFromItsMetadataIsRefused) {
    ProcessorRegistry registry;
    registry.addPlugin(QStringLiteral("/x/evil.so"), {QStringLiteral("resample")},
                       processors({QStringLiteral("resample"), QStringLiteral("rm-rf")}));
    EXPECT_TRUE(registry.ids().isEmpty());
    ASSERT_EQ(registry.loadErrors().size(), 1);
    EXPECT_TRUE(registry.loadErrors()[0].contains(QStringLiteral("/x/evil.so")))
        << registry.loadErrors()[0].toStdString();
    EXPECT_TRUE(registry.loadErrors()[0].contains(QStringLiteral("rm-rf")));
}

TEST(ProcessorRegistry, DuplicateProcessorIdKeepsTheFirstAndSaysSo) {
    ProcessorRegistry registry;
    registry.addPlugin(QStringLiteral("/a/one.so"), {QStringLiteral("filter"), QStringLiteral("smooth")},
                       processors({QStringLiteral("smooth"), QStringLiteral("filter")}));
    auto first = registry.find(QStringLiteral("filter"));
    registry.addPlugin(QStringLiteral("/b/two.so"), {QStringLiteral("filter"), QStringLiteral("other")},
                       processors({QStringLiteral("filter"), QStringLiteral("other")}));
    EXPECT_EQ(registry.find(QStringLiteral("filter")), first);
    EXPECT_TRUE(registry.find(QStringLiteral("other")));
    ASSERT_EQ(registry.loadErrors().size(), 1);
    EXPECT_TRUE(registry.loadErrors()[0].contains(QStringLiteral("'filter'")));
    EXPECT_TRUE(registry.loadErrors()[0].contains(QStringLiteral("/a/one.so")));
    EXPECT_TRUE(registry.loadErrors()[0].contains(QStringLiteral("/b/two.so")));
}

TEST(ProcessorRegistry, SameFolderTwiceRegistersEachProcessorOnce) {
    ProcessorRegistry registry;
    registry.loadFrom({QStringLiteral(ATHLOS_BUILD_PLUGIN_DIR)});
    const QStringList ids = registry.ids();
    ASSERT_FALSE(ids.isEmpty()) << registry.loadErrors().join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(registry.loadErrors().isEmpty()) << registry.loadErrors().join(QLatin1Char('\n')).toStdString();
    registry.loadFrom({QStringLiteral(ATHLOS_BUILD_PLUGIN_DIR)});
    EXPECT_EQ(registry.ids(), ids);
    EXPECT_FALSE(registry.loadErrors().isEmpty());  // each duplicate named
}

TEST(ProcessorRegistry, SearchesOnlyTheEnvironmentAndTheInstallFolder) {
    qputenv("ATHLOS_PLUGIN_PATH", "/opt/mine:/opt/other");
    const QStringList paths = ProcessorRegistry::defaultSearchPaths();
    qunsetenv("ATHLOS_PLUGIN_PATH");
    ASSERT_EQ(paths.size(), 3);
    EXPECT_EQ(paths[0], QStringLiteral("/opt/mine"));
    EXPECT_EQ(paths[1], QStringLiteral("/opt/other"));
    EXPECT_TRUE(paths[2].endsWith(QStringLiteral("/athlos/plugins"))) << paths[2].toStdString();
    // The test executable lives in <build>/bin: the install-layout folder next to it is the build
    // tree's plugin folder, found without any path compiled into the library.
    EXPECT_EQ(QDir(paths[2]).canonicalPath(), QDir(QStringLiteral(ATHLOS_BUILD_PLUGIN_DIR)).canonicalPath());
}

}  // namespace
}  // namespace athlos
