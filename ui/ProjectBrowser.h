#pragma once
// The left side of the main window: the project tree and the details of the current item, each
// in a dock. Selecting a stream asks for it to be plotted; the rest of the window listens.
#include <QObject>
#include <QString>

class QMainWindow;
class QModelIndex;
class QPoint;
class QTextBrowser;
class QTreeView;

namespace athlos {
class Project;
}

namespace athlos::ui {

class ProjectTreeModel;

class ProjectBrowser : public QObject {
    Q_OBJECT

public:
    // Adds the tree and details docks to window.
    explicit ProjectBrowser(QMainWindow& window);
    ~ProjectBrowser() override;

    // Shows project (may be null), expanded, with its description in the details.
    void setProject(Project* project);
    // After the project changed: rebuilds the tree (the selection is not restored).
    void refresh();
    // Selects "rec" or "rec/item"; selecting the current item again re-announces it.
    bool selectItem(const QString& path);
    QString currentItem() const;
    // The project's description in the details (e.g. after Save As changed its path).
    void showProjectDetails();

    ProjectTreeModel* model() const { return model_; }
    QTreeView* view() const { return tree_; }
    QTextBrowser* details() const { return details_; }

signals:
    void streamSelected(const QString& path);
    // Double-click or Enter on a stream.
    void streamActivated(const QString& path);
    void contextMenuRequested(const QString& path, const QPoint& globalPos);

private:
    void onCurrentChanged(const QModelIndex& current);
    void showDetails(const QString& path);
    void expandAll();

    Project* project_ = nullptr;
    ProjectTreeModel* model_ = nullptr;
    QTreeView* tree_ = nullptr;
    QTextBrowser* details_ = nullptr;
};

}  // namespace athlos::ui
