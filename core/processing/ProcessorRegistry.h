#pragma once
// Discovers processor plugins and indexes their processors by id.
#include "core/processing/Processor.h"

#include <QString>
#include <QStringList>
#include <map>
#include <memory>
#include <vector>

namespace athlos {

class ProcessorRegistry {
public:
    // Folders searched, in order: $ATHLOS_PLUGIN_PATH (colon-separated), then the install folder
    // <exe>/../<libdir>/athlos/plugins (the build tree has the same layout). Nothing else: no
    // current directory, no path compiled in.
    static QStringList defaultSearchPaths();
    // Loads every plugin found; returns the global registry (loaded once).
    static ProcessorRegistry& instance();

    void loadFrom(const QStringList& folders);
    void add(std::shared_ptr<const Processor> processor);  // for tests and built-ins
    // A loaded plugin's processors: refused whole when they differ from the ids its metadata
    // declares; an id another plugin registered already is refused (each with a loadErrors() entry).
    void addPlugin(const QString& file, const QStringList& declared,
                   std::vector<std::shared_ptr<const Processor>> processors);

    std::shared_ptr<const Processor> find(const QString& id) const;
    QStringList ids() const;
    QStringList loadErrors() const { return errors_; }  // plugins that failed to load

private:
    std::map<QString, std::shared_ptr<const Processor>> processors_;
    std::map<QString, QString> origins_;  // id → plugin file
    QStringList errors_;
};

}  // namespace athlos
