#include "ui/WindowActions.h"

#include "core/model/Project.h"
#include "core/util/Version.h"
#include "ui/AnnotationEditor.h"
#include "ui/AnnotationLayer.h"
#include "ui/AnnotationPanel.h"
#include "ui/MainWindow.h"
#include "ui/PanelLayout.h"
#include "ui/PlotExporter.h"
#include "ui/ProjectSession.h"
#include "ui/RecentProjects.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/UiEntry.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QUndoStack>
#include <qcustomplot.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace athlos::ui {

WindowActions::WindowActions(MainWindow& window) : window_(window) {
    createActions();
    createMenus();
}

void WindowActions::createActions() {
    MainWindow* w = &window_;
    new_ =
        new QAction(QIcon::fromTheme(QStringLiteral("document-new"), QIcon(QStringLiteral(":/athlos/icons/new.svg"))),
                    tr("&New Project…"), w);
    new_->setShortcut(QKeySequence::New);
    new_->setStatusTip(tr("Create an empty project file"));
    QObject::connect(new_, &QAction::triggered, w, [w] { w->session_->newProjectDialog(); });

    open_ =
        new QAction(QIcon::fromTheme(QStringLiteral("document-open"), QIcon(QStringLiteral(":/athlos/icons/open.svg"))),
                    tr("&Open Project…"), w);
    open_->setShortcut(QKeySequence::Open);
    open_->setStatusTip(tr("Open an existing project file"));
    QObject::connect(open_, &QAction::triggered, w, [w] { w->session_->openProjectDialog(); });

    save_ =
        new QAction(QIcon::fromTheme(QStringLiteral("document-save"), QIcon(QStringLiteral(":/athlos/icons/save.svg"))),
                    tr("&Save"), w);
    save_->setShortcut(QKeySequence::Save);
    save_->setStatusTip(tr("Save the project (the file is replaced atomically)"));
    QObject::connect(save_, &QAction::triggered, w, [w] { w->saveProject(); });

    saveAs_ = new QAction(tr("Save &As…"), w);
    saveAs_->setShortcut(QKeySequence::SaveAs);
    saveAs_->setStatusTip(tr("Save the project under a new name"));
    QObject::connect(saveAs_, &QAction::triggered, w, [w] { w->session_->saveAsDialog(); });

    import_ = new QAction(QIcon(QStringLiteral(":/athlos/icons/import.svg")), tr("&Import…"), w);
    import_->setShortcut(Qt::CTRL | Qt::Key_I);
    import_->setStatusTip(tr("Import recordings (CSV, BROAD, gaitmap, …) into the project"));
    QObject::connect(import_, &QAction::triggered, w, [w] { w->session_->importDialog(); });

    quit_ = new QAction(tr("&Quit"), w);
    quit_->setShortcut(QKeySequence::Quit);
    quit_->setMenuRole(QAction::QuitRole);
    QObject::connect(quit_, &QAction::triggered, w, &QWidget::close);

    about_ = new QAction(tr("&About Athlos"), w);
    about_->setMenuRole(QAction::AboutRole);
    QObject::connect(about_, &QAction::triggered, w, [this] { about(); });

    runProcessor_ = new QAction(tr("&Run Processor…"), w);
    runProcessor_->setShortcut(Qt::CTRL | Qt::Key_R);
    runProcessor_->setStatusTip(tr("Run any processor on streams of the project"));
    QObject::connect(runProcessor_, &QAction::triggered, w, [w] { w->openProcessorDialog(); });

    addPanel_ = new QAction(tr("Add &Time-Series Panel"), w);
    addPanel_->setStatusTip(tr("Plot the selected stream in another panel that shares the time cursor"));
    QObject::connect(addPanel_, &QAction::triggered, w, [w] {
        const QString path = w->currentItem();
        if (w->project() && w->project()->stream(path))
            w->addTimeSeriesPanel(path);
        else
            w->statusBar()->showMessage(tr("Select a stream first."), 5000);
    });
    QUndoStack* undoStack = w->annotationEditor()->undoStack();
    undo_ = undoStack->createUndoAction(w, tr("&Undo"));
    undo_->setShortcut(QKeySequence::Undo);
    redo_ = undoStack->createRedoAction(w, tr("&Redo"));
    redo_->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence::Redo});
    annotateMode_ = new QAction(tr("&Annotate Mode"), w);
    annotateMode_->setCheckable(true);
    annotateMode_->setShortcut(Qt::CTRL | Qt::Key_M);
    annotateMode_->setStatusTip(
        tr("Drag on the plot to create intervals of the current class (Shift+drag works always)"));
    QObject::connect(annotateMode_, &QAction::toggled, w, [w](bool on) {
        w->annotationLayer()->setAnnotateMode(on);
        if (on) w->showAnnotationPanel();
    });
    addClass_ = new QAction(tr("Add Annotation &Class…"), w);
    QObject::connect(addClass_, &QAction::triggered, w, [w] { w->annotationPanel()->addClassDialog(); });
    preferences_ = new QAction(tr("&Preferences…"), w);
    preferences_->setMenuRole(QAction::PreferencesRole);
    QObject::connect(preferences_, &QAction::triggered, w, [w] {
        bool ok = false;
        const QString name = QInputDialog::getText(w, tr("Preferences"), tr("Annotator name:"), QLineEdit::Normal,
                                                   AnnotationEditor::annotator(), &ok);
        if (ok && !name.trimmed().isEmpty()) AnnotationEditor::setAnnotator(name);
    });

    exportView_ = new QAction(tr("&Export View…"), w);
    exportView_->setShortcut(Qt::CTRL | Qt::Key_E);
    exportView_->setStatusTip(tr("Save the shown plot as PNG, SVG or PDF"));
    QObject::connect(exportView_, &QAction::triggered, w, [this, w] { exportPlot(w->panels_->currentPlot()); });

    showAll_ = new QAction(tr("Show &All"), w);
    showAll_->setShortcut(Qt::CTRL | Qt::Key_0);
    QObject::connect(showAll_, &QAction::triggered, w->timeController(), &TimeController::showAll);
}

void WindowActions::createMenus() {
    QMenuBar* bar = window_.menuBar();
    QMenu* file = bar->addMenu(tr("&File"));
    file->addAction(new_);
    file->addAction(open_);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    QObject::connect(recentMenu_, &QMenu::aboutToShow, &window_, [this] { rebuildRecentMenu(); });
    rebuildRecentMenu();
    file->addSeparator();
    file->addAction(save_);
    file->addAction(saveAs_);
    file->addSeparator();
    file->addAction(import_);
    file->addAction(exportView_);
    QAction* beforeQuit = file->addSeparator();
    file->addAction(quit_);

    QMenu* edit = bar->addMenu(tr("&Edit"));
    edit->addAction(undo_);
    edit->addAction(redo_);
    edit->addSeparator();
    edit->addAction(annotateMode_);
    edit->addAction(addClass_);
    edit->addSeparator();
    edit->addAction(preferences_);

    QMenu* view = bar->addMenu(tr("&View"));
    viewMenu_ = view;
    view->addAction(addPanel_);
    view->addAction(showAll_);

    QMenu* processing = bar->addMenu(tr("&Processing"));
    processing->addAction(runProcessor_);
    createToolMenus(file, processing, view);
    // Tools of the File menu (import wizard…) sit with Import, before the quit separator.
    for (QAction* action : std::as_const(toolActions_)) {
        if (!file->actions().contains(action)) continue;
        file->removeAction(action);
        file->insertAction(beforeQuit, action);
    }

    QMenu* help = bar->addMenu(tr("&Help"));
    help->addAction(about_);
}

void WindowActions::createToolMenus(QMenu* file, QMenu* processing, QMenu* view) {
    // Menus appear in the order tools first name them, between Processing and Help.
    std::vector<std::pair<QString, QMenu*>> menus{
        {QStringLiteral("File"), file}, {QStringLiteral("Processing"), processing}, {QStringLiteral("View"), view}};
    QList<QMenu*> separated;
    for (const ToolEntry& entry : registeredTools()) {
        const QString menuName = QString::fromUtf8(entry.menu ? entry.menu : "Processing");
        auto it = std::find_if(menus.begin(), menus.end(), [&](const auto& m) { return m.first == menuName; });
        QMenu* menu = nullptr;
        if (it == menus.end()) {
            menu = window_.menuBar()->addMenu(QCoreApplication::translate("Tools", entry.menu));
            menus.emplace_back(menuName, menu);
        } else {
            menu = it->second;
        }
        if ((menu == processing || menu == view) && !separated.contains(menu)) {
            menu->addSeparator();
            separated << menu;
        }
        QAction* action = menu->addAction(QCoreApplication::translate("Tools", entry.text));
        action->setData(entry.id);
        action->setObjectName(entry.id);
        const auto launch = entry.launch;
        MainWindow* w = &window_;
        QObject::connect(action, &QAction::triggered, w, [w, launch] {
            if (launch && !w->busy_) launch(*w);
        });
        toolActions_ << action;
    }
}

void WindowActions::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList paths = RecentProjects::list();
    int number = 1;
    MainWindow* w = &window_;
    for (const QString& path : paths) {
        QAction* action =
            recentMenu_->addAction(QStringLiteral("&%1 %2").arg(number++ % 10).arg(QFileInfo(path).fileName()));
        action->setToolTip(QDir::toNativeSeparators(path));
        action->setStatusTip(QDir::toNativeSeparators(path));
        QObject::connect(action, &QAction::triggered, w, [w, path] { w->openProject(path); });
    }
    if (paths.isEmpty()) {
        recentMenu_->addAction(tr("No recent projects"))->setEnabled(false);
        return;
    }
    recentMenu_->addSeparator();
    QObject::connect(recentMenu_->addAction(tr("Clear List")), &QAction::triggered, w, [] { RecentProjects::clear(); });
}

void WindowActions::updateEnabled(bool projectOpen) {
    save_->setEnabled(projectOpen);
    saveAs_->setEnabled(projectOpen);
    import_->setEnabled(projectOpen);
    runProcessor_->setEnabled(projectOpen);
    // Tools work on a project; they are offered once one is open.
    for (QAction* action : std::as_const(toolActions_)) action->setEnabled(projectOpen);
}

void WindowActions::setBusy(bool busy, bool projectOpen) {
    for (QAction* action : {new_, open_, save_, saveAs_, import_, quit_, runProcessor_}) action->setEnabled(!busy);
    for (QAction* action : std::as_const(toolActions_)) action->setEnabled(!busy);
    if (!busy) updateEnabled(projectOpen);
}

void WindowActions::addExportMenu(QCustomPlot* plot) {
    plot->setContextMenuPolicy(Qt::CustomContextMenu);
    QObject::connect(plot, &QWidget::customContextMenuRequested, &window_, [this, plot](const QPoint& pos) {
        QMenu menu(&window_);
        menu.addAction(tr("Export View…"), &window_, [this, plot] { exportPlot(plot); });
        menu.addAction(showAll_);
        menu.exec(plot->mapToGlobal(pos));
    });
}

void WindowActions::exportPlot(QCustomPlot* plot) {
    const QString written = PlotExporter::exportDialog(plot, &window_);
    if (!written.isEmpty())
        window_.statusBar()->showMessage(tr("Exported %1").arg(QDir::toNativeSeparators(written)), 5000);
}

void WindowActions::addToViewMenu(QAction* action) {
    if (viewMenu_ && !viewMenu_->actions().contains(action)) viewMenu_->addAction(action);
}

QAction* WindowActions::toolAction(const QString& id) const {
    for (QAction* action : toolActions_)
        if (action->data().toString() == id) return action;
    return nullptr;
}

void WindowActions::about() {
    const QString versions = ui::libraryVersions();
    QMessageBox::about(
        &window_, tr("About Athlos"),
        QStringLiteral("<h3>Athlos %1</h3><p>%2</p><p>%3</p><pre>%4</pre>")
            .arg(appVersion().toHtmlEscaped(),
                 tr("Analysis of sports recordings from local positioning systems, IMUs and GNSS.").toHtmlEscaped(),
                 tr("Built with:").toHtmlEscaped(), versions.toHtmlEscaped()));
}

}  // namespace athlos::ui
