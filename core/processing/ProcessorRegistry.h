#pragma once
// Discovers processor plugins and indexes their processors by id.
#include "core/processing/Processor.h"

#include <QString>
#include <QStringList>
#include <map>
#include <memory>

namespace athlos {

class ProcessorRegistry {
public:
    // Folders searched, in order: $ATHLOS_PLUGIN_PATH (colon-separated), <exe>/../plugins,
    // <exe>/../lib/athlos/plugins, the build tree's plugin folder.
    static QStringList defaultSearchPaths();
    // Loads every plugin found; returns the global registry (loaded once).
    static ProcessorRegistry& instance();

    void loadFrom(const QStringList& folders);
    void add(std::shared_ptr<const Processor> processor);  // for tests and built-ins

    std::shared_ptr<const Processor> find(const QString& id) const;
    QStringList ids() const;
    QStringList loadErrors() const { return errors_; }  // plugins that failed to load

private:
    std::map<QString, std::shared_ptr<const Processor>> processors_;
    QStringList errors_;
};

}  // namespace athlos
