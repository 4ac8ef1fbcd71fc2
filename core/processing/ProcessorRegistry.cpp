#include "core/processing/ProcessorRegistry.h"

#include "core/processing/ProcessorPlugin.h"
#include "core/util/BuildInfo.h"

#include <QCoreApplication>
#include <QDir>
#include <QPluginLoader>
#include <QSet>

namespace athlos {

QStringList ProcessorRegistry::defaultSearchPaths() {
    QStringList paths;
    const QString env = qEnvironmentVariable("ATHLOS_PLUGIN_PATH");
    if (!env.isEmpty()) paths << env.split(QLatin1Char(':'), Qt::SkipEmptyParts);
    if (QCoreApplication::instance()) {
        const QDir exe(QCoreApplication::applicationDirPath());
        paths << exe.absoluteFilePath(QStringLiteral("../plugins"));
        paths << exe.absoluteFilePath(QStringLiteral("../") + QStringLiteral(ATHLOS_INSTALL_PLUGIN_DIR));
    }
    // The build tree, so tests and uninstalled builds find their plugins from anywhere.
    paths << QStringLiteral(ATHLOS_BUILD_PLUGIN_DIR);
    return paths;
}

ProcessorRegistry& ProcessorRegistry::instance() {
    static ProcessorRegistry registry = [] {
        ProcessorRegistry r;
        r.loadFrom(defaultSearchPaths());
        return r;
    }();
    return registry;
}

void ProcessorRegistry::loadFrom(const QStringList& folders) {
    QSet<QString> seen;
    for (const QString& folder : folders) {
        const QDir dir(folder);
        if (!dir.exists()) continue;
        for (const QString& file : dir.entryList({QStringLiteral("*.so"), QStringLiteral("*.dylib"), QStringLiteral("*.dll")},
                                                 QDir::Files)) {
            // The same family found in two folders (build tree and install): the first wins.
            if (seen.contains(file)) continue;
            QPluginLoader loader(dir.absoluteFilePath(file));
            QObject* instance = loader.instance();
            auto* plugin = qobject_cast<ProcessorPlugin*>(instance);
            if (!plugin) {
                errors_ << QStringLiteral("%1: %2").arg(dir.absoluteFilePath(file),
                                                        instance ? QStringLiteral("not an Athlos processor plugin")
                                                                 : loader.errorString());
                continue;
            }
            seen.insert(file);
            for (auto& processor : plugin->processors()) add(std::move(processor));
        }
    }
}

void ProcessorRegistry::add(std::shared_ptr<const Processor> processor) {
    const QString id = processor->id();
    processors_[id] = std::move(processor);
}

std::shared_ptr<const Processor> ProcessorRegistry::find(const QString& id) const {
    auto it = processors_.find(id);
    return it == processors_.end() ? nullptr : it->second;
}

QStringList ProcessorRegistry::ids() const {
    QStringList ids;
    for (const auto& [id, p] : processors_) ids << id;
    return ids;
}

}  // namespace athlos
