// The `athlos` executable: a headless command line over core, and the GUI (ui library).
#include "Commands.h"
#include "VideoCommand.h"

#include "core/util/Version.h"
#include "ui/UiEntry.h"

#include <QApplication>
#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <unistd.h>
#include <cstdio>
#include <functional>
#include <map>

namespace {

const char* kUsage =
    "Usage: athlos [<project.athlos>]            open the GUI\n"
    "       athlos <command> [options]           headless\n"
    "\n"
    "Commands:\n"
    "  new <project> [--sport S]                 create an empty project\n"
    "  import <project> <file> --as <rec>[/<stream>] [--format auto|csv|broad|gaitmap] [--kind K]\n"
    "                                            import a recording file\n"
    "  info <project> [--json]                   list recordings, streams, tables, provenance\n"
    "  processors [--json]                       list processors and their parameters\n"
    "  run <project> <processor> --input <rec/stream>[,…] --output <rec/stream> [--param k=v …]\n"
    "  export <project> <rec/stream> --to <file.csv|file.h5>\n"
    "  pipeline <project> <pipeline.json>        run a list of processor steps\n"
    "  train <project> --model NAME --input STREAM [--window S --step S --classifier C --cv SCHEME]\n"
    "                                            train an activity classifier from annotated recordings\n"
    "  screenshot <project> --view <name> --to <file.png>   render a view offscreen\n"
    "  report <project> --to <file.pdf> [--recording R] [--csv F]   coach's session report (PDF)\n"
    "  history <project>… --to <file.csv> [--athlete A]   sessions against a rolling 4-week baseline, flags\n"
    "  video <project> <recording> <file> [--offset S] | --detach | --info\n"
    "                                            attach a video to a recording\n"
    "  venue <project> --corners \"LAT,LON;…\" | --corners-xy \"X,Y;…\" [--kind football|rugby|rectangle]\n"
    "                                            place a pitch from its 4 corners (no corners: list venues)\n"
    "  batch <pipeline.json> <project>… [--jobs N] [--engine local|slurm] [--slurm-args '…'] [--summary out.csv]\n"
    "                                            run a pipeline over many projects (worker processes or Slurm)\n"
    "\n"
    "Every command has --help. Exit code 0 on success, non-zero with a one-line reason otherwise.\n";

// Qt warns on stderr when XDG_RUNTIME_DIR is unset (root shells, CI); a private folder keeps the
// one-line-error contract of the CLI.
void ensureRuntimeDir() {
    if (qEnvironmentVariableIsSet("XDG_RUNTIME_DIR")) return;
    const QByteArray dir = QDir::tempPath().toLocal8Bit() + "/athlos-runtime-" + QByteArray::number(getuid());
    QDir().mkpath(QString::fromLocal8Bit(dir));
    QFile::setPermissions(QString::fromLocal8Bit(dir),
                          QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
    qputenv("XDG_RUNTIME_DIR", dir);
}

// The offscreen platform warns "This plugin does not support propagateSizeHints()" for every
// window it renders; that is not something a user can act on, so screenshot drops it.
QtMessageHandler previousHandler = nullptr;
void dropOffscreenNoise(QtMsgType type, const QMessageLogContext& context, const QString& message) {
    if (message.contains(QLatin1String("propagateSizeHints"))) return;
    if (previousHandler) previousHandler(type, context, message);
}

}  // namespace

int main(int argc, char** argv) {
    using namespace athlos::cli;
    const std::map<QString, std::function<int(const QStringList&)>> headless = {
        {QStringLiteral("new"), cmdNew},           {QStringLiteral("import"), cmdImport},
        {QStringLiteral("info"), cmdInfo},         {QStringLiteral("processors"), cmdProcessors},
        {QStringLiteral("run"), cmdRun},           {QStringLiteral("export"), cmdExport},
        {QStringLiteral("pipeline"), cmdPipeline}, {QStringLiteral("video"), cmdVideo},
        {QStringLiteral("venue"), cmdVenue},       {QStringLiteral("batch"), cmdBatch},
        {QStringLiteral("history"), cmdHistory},   {QStringLiteral("batch-task"), cmdBatchTask},
        {QStringLiteral("train"), cmdTrain},
    };
    const QString command = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QString();

    if (command == u"--help" || command == u"-h" || command == u"help") {
        std::fputs(kUsage, stdout);
        return Ok;
    }
    if (command == u"--version" || command == u"-v") {
        QCoreApplication app(argc, argv);
        std::printf("%s\n", qUtf8Printable(athlos::ui::libraryVersions()));
        return Ok;
    }
    if (auto it = headless.find(command); it != headless.end()) {
        QCoreApplication app(argc, argv);
        QCoreApplication::setApplicationName(QStringLiteral("Athlos"));
        QStringList args = app.arguments().mid(1);
        return it->second(args);
    }
    if (command == u"report") {
        // The report's plots are widgets: rendered offscreen, with or without a display.
        qputenv("QT_QPA_PLATFORM", "offscreen");
        ensureRuntimeDir();
        previousHandler = qInstallMessageHandler(dropOffscreenNoise);
        QApplication app(argc, argv);
        QCoreApplication::setApplicationName(QStringLiteral("Athlos"));
        athlos::ui::installTranslations(app);
        return cmdReport(app.arguments().mid(1));
    }
    if (command == u"screenshot") {
        // Rendering is always offscreen: deterministic, and it works without a display (CI).
        qputenv("QT_QPA_PLATFORM", "offscreen");
        ensureRuntimeDir();
        previousHandler = qInstallMessageHandler(dropOffscreenNoise);
        QApplication app(argc, argv);
        QCoreApplication::setApplicationName(QStringLiteral("Athlos"));
        athlos::ui::installTranslations(app);
        return cmdScreenshot(app.arguments().mid(1));
    }
    if (!command.isEmpty() &&
        (command.startsWith(QLatin1Char('-')) || !QFileInfo(command).suffix().startsWith(u"athlos"))) {
        std::fprintf(stderr, "athlos: unknown command '%s' (see athlos --help)\n", qUtf8Printable(command));
        return Usage;
    }

    QApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("Athlos"));
    QCoreApplication::setOrganizationName(QStringLiteral("Athlos"));
    QCoreApplication::setApplicationVersion(athlos::appVersion());
    athlos::ui::installTranslations(app);
    return athlos::ui::runMainWindow(command);
}
