#include "ui/ProjectBrowser.h"

#include "core/model/Project.h"
#include "ui/ItemDescription.h"
#include "ui/ProjectTreeModel.h"

#include <QCoreApplication>
#include <QDockWidget>
#include <QHeaderView>
#include <QMainWindow>
#include <QTextBrowser>
#include <QTreeView>

namespace athlos::ui {

ProjectBrowser::ProjectBrowser(QMainWindow& window) : QObject(&window) {
    model_ = new ProjectTreeModel(this);
    tree_ = new QTreeView(&window);
    tree_->setModel(model_);
    tree_->setUniformRowHeights(true);
    tree_->setAlternatingRowColors(true);
    tree_->setSelectionMode(QAbstractItemView::SingleSelection);
    tree_->header()->setStretchLastSection(true);
    // A model reset replaces the selection model's contents, not the object: connect once.
    connect(tree_->selectionModel(), &QItemSelectionModel::currentChanged, this,
            [this](const QModelIndex& current) { onCurrentChanged(current); });
    connect(tree_, &QTreeView::activated, this, [this](const QModelIndex& index) {
        if (model_->nodeType(index) == ProjectTreeModel::NodeType::Stream) emit streamActivated(model_->pathOf(index));
    });
    tree_->setContextMenuPolicy(Qt::CustomContextMenu);
    connect(tree_, &QTreeView::customContextMenuRequested, this, [this](const QPoint& pos) {
        emit contextMenuRequested(model_->pathOf(tree_->indexAt(pos)), tree_->viewport()->mapToGlobal(pos));
    });

    // The dock titles were the main window's strings; that context keeps their translations.
    auto* treeDock = new QDockWidget(QCoreApplication::translate("athlos::ui::MainWindow", "Project"), &window);
    treeDock->setObjectName(QStringLiteral("projectDock"));
    treeDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    treeDock->setWidget(tree_);
    window.addDockWidget(Qt::LeftDockWidgetArea, treeDock);

    details_ = new QTextBrowser(&window);
    details_->setOpenLinks(false);
    auto* detailsDock = new QDockWidget(QCoreApplication::translate("athlos::ui::MainWindow", "Details"), &window);
    detailsDock->setObjectName(QStringLiteral("detailsDock"));
    detailsDock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    detailsDock->setWidget(details_);
    window.addDockWidget(Qt::LeftDockWidgetArea, detailsDock);
    window.splitDockWidget(treeDock, detailsDock, Qt::Vertical);
    window.resizeDocks({treeDock}, {380}, Qt::Horizontal);
    window.resizeDocks({treeDock, detailsDock}, {420, 300}, Qt::Vertical);
}

ProjectBrowser::~ProjectBrowser() = default;

void ProjectBrowser::setProject(Project* project) {
    project_ = project;
    model_->setProject(project);
    expandAll();
    showProjectDetails();
}

void ProjectBrowser::refresh() {
    model_->refresh();
    expandAll();
}

void ProjectBrowser::expandAll() {
    tree_->expandAll();
    for (int c = 0; c < ProjectTreeModel::ColumnsColumn; ++c) tree_->resizeColumnToContents(c);
}

bool ProjectBrowser::selectItem(const QString& path) {
    const QModelIndex index = model_->indexOf(path);
    if (!index.isValid()) return false;
    if (tree_->currentIndex() == index)
        onCurrentChanged(index);
    else
        tree_->setCurrentIndex(index);
    tree_->scrollTo(index);
    return true;
}

QString ProjectBrowser::currentItem() const { return model_->pathOf(tree_->currentIndex()); }

void ProjectBrowser::showProjectDetails() {
    details_->setHtml(project_ ? ItemDescription::projectHtml(*project_) : QString());
}

void ProjectBrowser::onCurrentChanged(const QModelIndex& current) {
    const QString path = model_->pathOf(current);
    showDetails(path);
    if (model_->nodeType(current) == ProjectTreeModel::NodeType::Stream) emit streamSelected(path);
}

void ProjectBrowser::showDetails(const QString& path) {
    if (!project_) {
        details_->clear();
        return;
    }
    if (path.isEmpty()) {
        details_->setHtml(ItemDescription::projectHtml(*project_));
    } else if (const Stream* stream = project_->stream(path)) {
        details_->setHtml(ItemDescription::streamHtml(path, stream->info()));
    } else if (const Table* table = project_->table(path)) {
        details_->setHtml(ItemDescription::tableHtml(path, *table));
    } else if (const Recording* recording = project_->recording(path)) {
        details_->setHtml(ItemDescription::recordingHtml(*recording));
    }
}

}  // namespace athlos::ui
