#pragma once
// What the `athlos` executable needs from the UI library. A QApplication must exist.
#include "core/util/Expected.h"

#include <QSize>
#include <QString>
#include <QStringList>

class QApplication;

namespace athlos::ui {

// Loads the translation for the system locale (or $ATHLOS_LANG, e.g. "de") into app.
void installTranslations(QApplication& app);
// Shows the main window (opening projectPath if not empty) and runs the event loop.
int runMainWindow(const QString& projectPath);
// Renders a view of the project offscreen at size and writes a PNG. Views: screenshotViews().
Status renderScreenshot(const QString& projectPath, const QString& view, const QString& pngPath,
                        QSize size = QSize(1280, 800));
QStringList screenshotViews();
// athlos::libraryVersions() plus the libraries only the UI links (QCustomPlot), one per line:
// for "About" and `athlos --version`.
QString libraryVersions();

}  // namespace athlos::ui
