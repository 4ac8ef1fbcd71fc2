#include "ui/UiEntry.h"

#include "core/model/Project.h"
#include "core/util/Version.h"
#include "ui/AnnotationLayer.h"
#include "ui/MainWindow.h"
#include "ui/TimeController.h"
#include "ui/TimeSeriesPanel.h"
#include "ui/ToolRegistry.h"
#include "ui/TrajectoryPanel.h"

#include <QApplication>
#include <QCoreApplication>
#include <QImage>
#include <QLibraryInfo>
#include <QLocale>
#include <QPixmap>
#include <QStatusBar>
#include <QTranslator>
#include <qcustomplot.h>

namespace athlos::ui {

void installTranslations(QApplication& app) {
    const QString lang = qEnvironmentVariable("ATHLOS_LANG");
    const QLocale locale = lang.isEmpty() ? QLocale::system() : QLocale(lang);
    // An explicit language also formats numbers and dates that way, as LANG would.
    if (!lang.isEmpty()) QLocale::setDefault(locale);

    auto* translator = new QTranslator(&app);
    if (translator->load(locale, QStringLiteral("athlos"), QStringLiteral("_"), QStringLiteral(":/i18n")))
        app.installTranslator(translator);
    else
        delete translator;  // English is the source language: nothing to load

    // Qt's own strings (standard dialog buttons) when the system has them installed.
    auto* qtTranslator = new QTranslator(&app);
    if (qtTranslator->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                           QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        app.installTranslator(qtTranslator);
    else
        delete qtTranslator;
}

int runMainWindow(const QString& projectPath) {
    MainWindow window;
    window.show();
    if (!projectPath.isEmpty()) window.openProject(projectPath);
    return QApplication::exec();
}

QString libraryVersions() {
    QString versions = athlos::libraryVersions().trimmed();
    // core does not link QCustomPlot, so the UI adds its own plotting library.
    if (!versions.contains(QLatin1String("QCustomPlot")))
        versions += QStringLiteral("\nQCustomPlot %1").arg(QLatin1String(QCUSTOMPLOT_VERSION_STR));
    return versions;
}

QStringList screenshotViews() {
    QStringList views{QStringLiteral("main"), QStringLiteral("trajectory"), QStringLiteral("annotate")};
    // Tools add theirs (ATHLOS_REGISTER_VIEW); a built-in name wins over a registered one.
    for (const ViewEntry& entry : registeredViews())
        if (!views.contains(entry.name)) views << entry.name;
    return views;
}

namespace {

const ViewEntry* registeredView(const QString& name) {
    for (const ViewEntry& entry : registeredViews())
        if (entry.name == name) return &entry;
    return nullptr;
}

// The time series of the first recording with annotations (else the first stream), the
// annotation dock with classes and intervals, and the cursor in the middle.
Status prepareAnnotateView(MainWindow& window) {
    const Project* project = window.project();
    QString path;
    for (const auto& [name, recording] : project->recordings())
        if (!recording.annotations.empty() && !recording.streams.empty()) {
            path = name + QLatin1Char('/') + recording.streams.begin()->first;
            break;
        }
    if (path.isEmpty()) path = window.firstStream();
    if (path.isEmpty())
        return makeError(QCoreApplication::translate(
            "athlos::ui::UiEntry", "the project has no stream to annotate; import a recording first"));
    window.selectItem(path);
    window.showTimeSeriesView();
    window.showAnnotationPanel();
    window.annotationLayer()->setAnnotateMode(true);
    window.waitForPlots();
    TimeController* time = window.timeController();
    time->setCursor(0.5 * (time->visibleBegin() + time->visibleEnd()));
    window.waitForPlots();
    return {};
}

}  // namespace

Status renderScreenshot(const QString& projectPath, const QString& view, const QString& pngPath, QSize size) {
    if (!screenshotViews().contains(view))
        return makeError(QCoreApplication::translate("athlos::ui::UiEntry", "unknown view '%1'; valid views: %2")
                             .arg(view, screenshotViews().join(QStringLiteral(", "))));
    if (!size.isValid() || size.isEmpty())
        return makeError(QCoreApplication::translate("athlos::ui::UiEntry", "invalid screenshot size"));

    auto opened = Project::open(projectPath);
    if (!opened) return opened.error();

    MainWindow window;
    window.setInteractive(false);
    // Rendered without ever appearing, whatever the platform plugin (offscreen in CI).
    window.setAttribute(Qt::WA_DontShowOnScreen);
    window.setProject(std::shared_ptr<Project>(std::move(opened).value()));
    window.resize(size);
    window.show();
    if (window.size() != size) window.setFixedSize(size);
    QCoreApplication::processEvents();

    if (view == QLatin1String("annotate")) {
        if (Status prepared = prepareAnnotateView(window); !prepared) return prepared;
    } else if (view != QLatin1String("main") && view != QLatin1String("trajectory")) {
        if (Status prepared = registeredView(view)->prepare(window); !prepared) return prepared;
    } else if (window.firstStream().isEmpty()) {
        return makeError(
            QCoreApplication::translate("athlos::ui::UiEntry", "the project has no streams to show in view '%1'")
                .arg(view));
    } else if (view == QLatin1String("trajectory")) {
        // A team (a recording with the position streams of two or more athletes) plays back on its
        // venue, cursor mid-recording: the view `team` that the playback view registers.
        const ViewEntry* team = registeredView(QStringLiteral("team"));
        const bool showTeam = team && team->hasData && team->hasData(*window.project());
        const QString path = showTeam ? QString() : window.firstPositionStream();
        if (showTeam) {
            if (Status prepared = team->prepare(window); !prepared) return prepared;
        } else if (path.isEmpty()) {
            const QString note =
                QCoreApplication::translate("athlos::ui::UiEntry",
                                            "No position stream (lps-position, trajectory or gnss with x/y) in this "
                                            "project; showing the main view.");
            qInfo("note: %s", qUtf8Printable(note));
            const QString first = window.firstStream();
            if (!first.isEmpty()) window.selectItem(first);
            window.showTimeSeriesView();
            window.trajectoryPanel()->setNote(note);
            window.statusBar()->showMessage(note);
        } else {
            window.selectItem(path);
            window.showTrajectoryView();
        }
    } else {
        const QString first = window.firstStream();
        if (!first.isEmpty()) window.selectItem(first);
        window.showTimeSeriesView();
    }

    window.waitForPlots();
    if (!window.timeSeriesPanel()->errorString().isEmpty())
        qWarning("%s", qUtf8Printable(window.timeSeriesPanel()->errorString()));

    QImage image = window.grab().toImage();
    // grab() returns device pixels; the CI wants exactly `size` logical pixels.
    if (image.size() != size) image = image.scaled(size, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    if (!image.save(pngPath, "PNG"))
        return makeError(QCoreApplication::translate("athlos::ui::UiEntry", "cannot write %1").arg(pngPath));
    return {};
}

}  // namespace athlos::ui
