#include "ui/ProjectTreeModel.h"

#include "core/model/Project.h"
#include "ui/ItemDescription.h"

#include <QLocale>

namespace athlos::ui {

// Internal ids: 0 marks a recording row; recording r's children carry r + 1.
ProjectTreeModel::ProjectTreeModel(QObject* parent)
    : QAbstractItemModel(parent),
      recordingIcon_(QStringLiteral(":/athlos/icons/recording.svg")),
      streamIcon_(QStringLiteral(":/athlos/icons/stream.svg")),
      tableIcon_(QStringLiteral(":/athlos/icons/table.svg")),
      resultIcon_(QStringLiteral(":/athlos/icons/result.svg")) {}

void ProjectTreeModel::setProject(const Project* project) {
    project_ = project;
    refresh();
}

void ProjectTreeModel::refresh() {
    beginResetModel();
    recordings_.clear();
    if (project_) {
        for (const auto& [name, recording] : project_->recordings()) {
            RecordingNode rec;
            rec.node.type = NodeType::Recording;
            rec.node.name = name;
            rec.node.path = name;
            rec.node.kind = tr("recording");
            const int count = int(recording.streams.size() + recording.tables.size());
            // Two plain strings rather than %n: English has no .qm file to supply plural forms.
            rec.node.rows = count == 1 ? tr("1 item") : tr("%1 items").arg(count);
            rec.node.toolTip = tr("Recording %1").arg(name);
            for (const auto& [streamName, stream] : recording.streams) {
                Node n;
                n.type = NodeType::Stream;
                n.name = streamName;
                n.path = name + QLatin1Char('/') + streamName;
                const StreamInfo& info = stream.info();
                n.kind = info.kind;
                n.rows = QLocale().toString(info.rows);
                n.columns = ItemDescription::columnsText(info.columns);
                n.toolTip = ItemDescription::streamToolTip(n.path, info);
                n.result = ItemDescription::isResult(info.provenance);
                rec.items.push_back(std::move(n));
            }
            for (const auto& [tableName, table] : recording.tables) {
                Node n;
                n.type = NodeType::Table;
                n.name = tableName;
                n.path = name + QLatin1Char('/') + tableName;
                n.kind = table.kind;
                n.rows = QLocale().toString(table.rows());
                n.columns = ItemDescription::columnsText(table);
                n.toolTip = ItemDescription::tableToolTip(n.path, table);
                n.result = ItemDescription::isResult(table.provenance);
                rec.items.push_back(std::move(n));
            }
            recordings_.push_back(std::move(rec));
        }
    }
    endResetModel();
}

const ProjectTreeModel::Node* ProjectTreeModel::node(const QModelIndex& index) const {
    if (!index.isValid()) return nullptr;
    const quintptr id = index.internalId();
    if (id == 0) {
        if (index.row() < 0 || index.row() >= int(recordings_.size())) return nullptr;
        return &recordings_[std::size_t(index.row())].node;
    }
    const std::size_t r = id - 1;
    if (r >= recordings_.size() || index.row() < 0 || index.row() >= int(recordings_[r].items.size())) return nullptr;
    return &recordings_[r].items[std::size_t(index.row())];
}

QString ProjectTreeModel::pathOf(const QModelIndex& index) const {
    const Node* n = node(index);
    return n ? n->path : QString();
}

ProjectTreeModel::NodeType ProjectTreeModel::nodeType(const QModelIndex& index) const {
    const Node* n = node(index);
    return n ? n->type : NodeType::Recording;
}

QModelIndex ProjectTreeModel::indexOf(const QString& path) const {
    for (std::size_t r = 0; r < recordings_.size(); ++r) {
        if (recordings_[r].node.path == path) return index(int(r), 0);
        for (std::size_t i = 0; i < recordings_[r].items.size(); ++i)
            if (recordings_[r].items[i].path == path) return createIndex(int(i), 0, quintptr(r + 1));
    }
    return {};
}

QModelIndex ProjectTreeModel::index(int row, int column, const QModelIndex& parent) const {
    if (column < 0 || column >= ColumnCount || row < 0) return {};
    if (!parent.isValid()) {
        if (row >= int(recordings_.size())) return {};
        return createIndex(row, column, quintptr(0));
    }
    if (parent.internalId() != 0 || parent.row() >= int(recordings_.size())) return {};
    if (row >= int(recordings_[std::size_t(parent.row())].items.size())) return {};
    return createIndex(row, column, quintptr(parent.row() + 1));
}

QModelIndex ProjectTreeModel::parent(const QModelIndex& child) const {
    if (!child.isValid() || child.internalId() == 0) return {};
    return createIndex(int(child.internalId() - 1), 0, quintptr(0));
}

int ProjectTreeModel::rowCount(const QModelIndex& parent) const {
    if (!parent.isValid()) return int(recordings_.size());
    if (parent.column() != 0 || parent.internalId() != 0) return 0;
    return int(recordings_[std::size_t(parent.row())].items.size());
}

int ProjectTreeModel::columnCount(const QModelIndex&) const { return ColumnCount; }

QVariant ProjectTreeModel::data(const QModelIndex& index, int role) const {
    const Node* n = node(index);
    if (!n) return {};
    switch (role) {
        case Qt::DisplayRole:
            switch (index.column()) {
                case NameColumn:
                    return n->name;
                case KindColumn:
                    return n->kind;
                case RowsColumn:
                    return n->rows;
                case ColumnsColumn:
                    return n->columns;
            }
            return {};
        case Qt::ToolTipRole:
            return n->toolTip;
        case Qt::DecorationRole:
            if (index.column() != NameColumn) return {};
            if (n->type == NodeType::Recording) return recordingIcon_;
            if (n->result) return resultIcon_;
            return n->type == NodeType::Table ? tableIcon_ : streamIcon_;
        case Qt::TextAlignmentRole:
            if (index.column() == RowsColumn) return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
            return {};
        case PathRole:
            return n->path;
        case NodeTypeRole:
            return int(n->type);
        case KindRole:
            return n->type == NodeType::Recording ? QString() : n->kind;
    }
    return {};
}

QVariant ProjectTreeModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
    switch (section) {
        case NameColumn:
            return tr("Name");
        case KindColumn:
            return tr("Kind");
        case RowsColumn:
            return tr("Rows");
        case ColumnsColumn:
            return tr("Columns");
    }
    return {};
}

}  // namespace athlos::ui
