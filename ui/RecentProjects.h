#pragma once
// The most recently opened projects, newest first, kept in QSettings.
#include <QString>
#include <QStringList>

namespace athlos::ui {

class RecentProjects {
public:
    static constexpr int kMaxEntries = 10;

    static QStringList list();
    // Moves path to the front (absolute, deduplicated) and trims the list to kMaxEntries.
    static void add(const QString& path);
    static void remove(const QString& path);
    static void clear();

private:
    static void store(const QStringList& paths);
};

}  // namespace athlos::ui
