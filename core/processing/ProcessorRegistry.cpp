#include "core/processing/ProcessorRegistry.h"

#include "core/processing/ProcessorPlugin.h"
#include "core/util/BuildInfo.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QPluginLoader>
#include <QSet>

namespace athlos {
namespace {

// The executable's folder: from Qt when an application object exists, else from the kernel (tests
// and tools that use the registry without one).
QString executableDir() {
    if (QCoreApplication::instance()) return QCoreApplication::applicationDirPath();
    const QFileInfo self(QStringLiteral("/proc/self/exe"));
    return self.exists() ? QFileInfo(self.symLinkTarget()).absolutePath() : QString();
}

QStringList declaredProcessors(const QJsonObject& metaData) {
    QStringList ids;
    for (const auto& value :
         metaData.value(QStringLiteral("MetaData")).toObject().value(QStringLiteral("processors")).toArray())
        ids << value.toString();
    return ids;
}

}  // namespace

QStringList ProcessorRegistry::defaultSearchPaths() {
    QStringList paths;
    const QString env = qEnvironmentVariable("ATHLOS_PLUGIN_PATH");
    if (!env.isEmpty()) paths << env.split(QLatin1Char(':'), Qt::SkipEmptyParts);
    // The install folder relative to the executable; the build tree has the same layout.
    if (const QString exe = executableDir(); !exe.isEmpty())
        paths << QDir(exe).absoluteFilePath(QStringLiteral("../") + QStringLiteral(ATHLOS_INSTALL_PLUGIN_DIR));
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
        for (const QString& file : dir.entryList({QStringLiteral("*.so")}, QDir::Files)) {
            // The same family found in two folders (ATHLOS_PLUGIN_PATH and install): the first wins.
            if (seen.contains(file)) continue;
            const QString path = dir.absoluteFilePath(file);
            QPluginLoader loader(path);
            // The metadata is read without running any of the library's code: refuse anything that
            // is not an Athlos processor plugin before loading it.
            const QJsonObject metaData = loader.metaData();
            if (metaData.value(QStringLiteral("IID")).toString() != QLatin1String(AthlosProcessorPlugin_iid)) {
                errors_ << QStringLiteral(
                               "%1: not an Athlos processor plugin (interface '%2', expected '%3'); not loaded")
                               .arg(path, metaData.value(QStringLiteral("IID")).toString(),
                                    QStringLiteral(AthlosProcessorPlugin_iid));
                continue;
            }
            QObject* instance = loader.instance();
            auto* plugin = qobject_cast<ProcessorPlugin*>(instance);
            if (!plugin) {
                errors_ << QStringLiteral("%1: %2").arg(
                    path, instance ? QStringLiteral("not an Athlos processor plugin") : loader.errorString());
                continue;
            }
            seen.insert(file);
            addPlugin(path, declaredProcessors(metaData), plugin->processors());
        }
    }
}

void ProcessorRegistry::addPlugin(const QString& file, const QStringList& declared,
                                  std::vector<std::shared_ptr<const Processor>> processors) {
    QStringList registered;
    for (const auto& processor : processors) registered << processor->id();
    QStringList sortedDeclared = declared, sortedRegistered = registered;
    sortedDeclared.sort();
    sortedRegistered.sort();
    if (sortedDeclared != sortedRegistered) {
        errors_ << QStringLiteral("%1: its metadata declares the processors [%2] but it registers [%3]; not loaded")
                       .arg(file, declared.join(QStringLiteral(", ")), registered.join(QStringLiteral(", ")));
        return;
    }
    for (auto& processor : processors) {
        const QString id = processor->id();
        if (auto it = origins_.find(id); it != origins_.end()) {
            errors_ << QStringLiteral("%1: processor id '%2' is already registered by %3; the second one is refused")
                           .arg(file, id, it->second);
            continue;
        }
        origins_[id] = file;
        processors_[id] = std::move(processor);
    }
}

void ProcessorRegistry::add(std::shared_ptr<const Processor> processor) {
    const QString id = processor->id();
    origins_[id] = QStringLiteral("(built in)");
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
