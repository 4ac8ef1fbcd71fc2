#pragma once
// The project as a tree: recordings → streams and tables, with kind, rows and columns/units.
//
// Everything shown is copied out of the project in refresh(), so painting never touches the
// project; that lets a save run on a worker thread while the window repaints.
#include <QAbstractItemModel>
#include <QIcon>
#include <QString>
#include <vector>

namespace athlos {
class Project;
}

namespace athlos::ui {

class ProjectTreeModel : public QAbstractItemModel {
    Q_OBJECT

public:
    enum Column { NameColumn, KindColumn, RowsColumn, ColumnsColumn, ColumnCount };
    enum Role {
        PathRole = Qt::UserRole + 1,  // "rec" for a recording, "rec/item" for a stream or table
        NodeTypeRole,                 // NodeType as int
        KindRole,
    };
    enum class NodeType { Recording, Stream, Table };

    explicit ProjectTreeModel(QObject* parent = nullptr);

    // The model does not own the project. Call refresh() after the project changed.
    void setProject(const Project* project);
    void refresh();

    QString pathOf(const QModelIndex& index) const;
    NodeType nodeType(const QModelIndex& index) const;
    QModelIndex indexOf(const QString& path) const;

    QModelIndex index(int row, int column, const QModelIndex& parent = {}) const override;
    QModelIndex parent(const QModelIndex& child) const override;
    int rowCount(const QModelIndex& parent = {}) const override;
    int columnCount(const QModelIndex& parent = {}) const override;
    QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role = Qt::DisplayRole) const override;

private:
    struct Node {
        NodeType type = NodeType::Stream;
        QString name, path, kind, rows, columns, toolTip;
        bool result = false;
    };
    struct RecordingNode {
        Node node;
        std::vector<Node> items;
    };
    const Node* node(const QModelIndex& index) const;

    const Project* project_ = nullptr;
    std::vector<RecordingNode> recordings_;
    QIcon recordingIcon_, streamIcon_, tableIcon_, resultIcon_;
};

}  // namespace athlos::ui
