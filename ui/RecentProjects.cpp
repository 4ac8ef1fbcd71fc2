#include "ui/RecentProjects.h"

#include <QFileInfo>
#include <QSettings>

namespace athlos::ui {

namespace {
const QString kKey = QStringLiteral("recentProjects");

QSettings settings() {
    // Explicit names, so the list does not depend on how the embedding application set its
    // organisation (tests, the CLI's screenshot command).
    return QSettings(QSettings::UserScope, QStringLiteral("Athlos"), QStringLiteral("Athlos"));
}
}  // namespace

QStringList RecentProjects::list() { return settings().value(kKey).toStringList(); }

void RecentProjects::add(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    QStringList paths = list();
    paths.removeAll(absolute);
    paths.prepend(absolute);
    while (paths.size() > kMaxEntries) paths.removeLast();
    store(paths);
}

void RecentProjects::remove(const QString& path) {
    QStringList paths = list();
    paths.removeAll(QFileInfo(path).absoluteFilePath());
    paths.removeAll(path);
    store(paths);
}

void RecentProjects::clear() { store({}); }

void RecentProjects::store(const QStringList& paths) {
    QSettings s = settings();
    s.setValue(kKey, paths);
}

}  // namespace athlos::ui
