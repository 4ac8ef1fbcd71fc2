#include "ui/views/CycleTableView.h"

#include "core/model/Project.h"
#include "ui/TimeController.h"
#include "ui/ToolRegistry.h"
#include "ui/Workspace.h"
#include "ui/WorkspaceNotifier.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

namespace athlos::ui {

namespace {

const TableColumn* numericColumn(const Table& table, const QString& name) {
    const TableColumn* c = table.column(name);
    return c && !c->isText ? c : nullptr;
}

// Five significant digits, without an exponent for the magnitudes of gait and skiing tables.
QString number(double v) {
    if (!std::isfinite(v)) return QStringLiteral("–");
    const double a = std::abs(v);
    const int decimals = a >= 1000.0 ? 1 : a >= 100.0 ? 2 : a >= 1.0 || a == 0.0 ? 3 : 4;
    return QString::number(v, 'f', decimals);
}

}  // namespace

QStringList CycleTableView::cycleTables(const Project& project) {
    QStringList out;
    for (const QString& name : project.recordingNames())
        for (const auto& [tableName, table] : project.recording(name)->tables)
            if (numericColumn(table, QStringLiteral("start")) && numericColumn(table, QStringLiteral("end")))
                out << name + QLatin1Char('/') + tableName;
    return out;
}

int CycleTableView::rowAt(const Table& table, double t) {
    const TableColumn* start = numericColumn(table, QStringLiteral("start"));
    const TableColumn* end = numericColumn(table, QStringLiteral("end"));
    if (!start || !end) return -1;
    const std::size_t n = std::min(start->numbers.size(), end->numbers.size());
    for (std::size_t i = 0; i < n; ++i)
        if (start->numbers[i] <= t && t < end->numbers[i]) return static_cast<int>(i);
    return -1;
}

CycleTableView::Summary CycleTableView::summary(const TableColumn& column) {
    Summary s;
    if (column.isText) return s;
    double sum = 0.0;
    for (double v : column.numbers)
        if (std::isfinite(v)) {
            sum += v;
            ++s.count;
        }
    if (s.count == 0) return s;
    s.mean = sum / s.count;
    if (s.count > 1) {
        double ss = 0.0;
        for (double v : column.numbers)
            if (std::isfinite(v)) ss += (v - s.mean) * (v - s.mean);
        s.sd = std::sqrt(ss / (s.count - 1));
    }
    return s;
}

CycleTableView::CycleTableView(const Project* project, QWidget* parent) : QWidget(parent), project_(project) {
    auto* layout = new QVBoxLayout(this);
    auto* row = new QHBoxLayout;
    choice_ = new QComboBox(this);
    row->addWidget(new QLabel(tr("Table"), this));
    row->addWidget(choice_, 1);
    layout->addLayout(row);
    note_ = new QLabel(this);
    layout->addWidget(note_);
    grid_ = new QTableWidget(this);
    grid_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    grid_->setSelectionBehavior(QAbstractItemView::SelectRows);
    grid_->setSelectionMode(QAbstractItemView::SingleSelection);
    layout->addWidget(grid_, 1);
    if (project_) choice_->addItems(cycleTables(*project_));
    connect(choice_, &QComboBox::currentIndexChanged, this, [this] { fill(); });
    connect(grid_, &QTableWidget::itemSelectionChanged, this, [this] {
        if (syncing_) return;
        if (const int r = currentRow(); r >= 0) showRow(r);
    });
    fill();
}

Status CycleTableView::setTable(const QString& path) {
    const int i = choice_->findText(path);
    if (i < 0) return makeError(tr("'%1' is not a table with start and end columns").arg(path));
    choice_->setCurrentIndex(i);
    fill();
    return {};
}

QString CycleTableView::tablePath() const { return choice_->currentText(); }

void CycleTableView::setTimeController(TimeController* time) {
    if (time_) disconnect(time_, nullptr, this, nullptr);
    time_ = time;
    if (!time_) return;
    connect(time_, &TimeController::cursorChanged, this, &CycleTableView::followCursor);
    connect(time_, &QObject::destroyed, this, [this] { time_ = nullptr; });
    followCursor(time_->cursor());
}

int CycleTableView::currentRow() const {
    const QList<QTableWidgetItem*> items = grid_->selectedItems();
    if (items.isEmpty()) return -1;
    const int r = items.front()->row();
    return r < rows_ ? r : -1;
}

void CycleTableView::showRow(int row) {
    const Table* table = project_ ? project_->table(tablePath()) : nullptr;
    if (!table || !time_ || row < 0 || row >= rows_) return;
    const double a = table->column(QStringLiteral("start"))->numbers[std::size_t(row)];
    const double b = table->column(QStringLiteral("end"))->numbers[std::size_t(row)];
    if (!(std::isfinite(a) && std::isfinite(b) && b > a)) return;
    const double margin = 0.25 * (b - a);
    time_->setVisibleRange(a - margin, b + margin);
    time_->setCursor(a);
}

void CycleTableView::fill() {
    grid_->clear();
    rows_ = 0;
    const Table* table = project_ ? project_->table(tablePath()) : nullptr;
    if (!table) {
        grid_->setRowCount(0);
        grid_->setColumnCount(0);
        note_->setText(
            tr("No table with start and end columns in this project (run gait-parameters, xc-skiing-cycles or "
               "velocity-reset first)."));
        return;
    }
    rows_ = static_cast<int>(table->rows());
    const int columns = static_cast<int>(table->columns.size());
    grid_->setColumnCount(columns);
    grid_->setRowCount(rows_ + 2);
    QStringList header, rowHeader;
    for (const TableColumn& c : table->columns)
        header << (c.isText || c.unit.isEmpty() || c.unit == QLatin1String("1") ? c.name
                                                                                : c.name + "\n[" + c.unit + "]");
    for (int r = 0; r < rows_; ++r) rowHeader << QString::number(r + 1);
    rowHeader << tr("mean") << tr("SD");
    grid_->setHorizontalHeaderLabels(header);
    grid_->setVerticalHeaderLabels(rowHeader);
    const QColor summaryBackground = palette().color(QPalette::AlternateBase);
    for (int c = 0; c < columns; ++c) {
        const TableColumn& column = table->columns[std::size_t(c)];
        for (int r = 0; r < rows_; ++r) {
            auto* item =
                new QTableWidgetItem(column.isText ? column.texts.value(r) : number(column.numbers[std::size_t(r)]));
            if (!column.isText) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            grid_->setItem(r, c, item);
        }
        const Summary s = summary(column);
        for (int k = 0; k < 2; ++k) {
            auto* item =
                new QTableWidgetItem(column.isText || s.count == 0 ? QString() : number(k == 0 ? s.mean : s.sd));
            item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            item->setBackground(summaryBackground);
            QFont bold = item->font();
            bold.setBold(true);
            item->setFont(bold);
            item->setFlags(Qt::ItemIsEnabled);  // not selectable: no cycle to show
            grid_->setItem(rows_ + k, c, item);
        }
    }
    grid_->resizeColumnsToContents();
    note_->setText(tr("%n row(s); the row under the cursor is selected, a click shows its cycle", nullptr, rows_));
    if (time_) followCursor(time_->cursor());
}

void CycleTableView::followCursor(double t) {
    const Table* table = project_ ? project_->table(tablePath()) : nullptr;
    const int row = table ? rowAt(*table, t) : -1;
    if (row == currentRow()) return;
    syncing_ = true;
    if (row < 0) {
        grid_->clearSelection();
    } else {
        grid_->selectRow(row);
        grid_->scrollToItem(grid_->item(row, 0));
    }
    syncing_ = false;
}

namespace {

QString trView(const char* text) { return QCoreApplication::translate("athlos::ui::CycleTableView", text); }

QDockWidget* makeDock(const Project* project, TimeController* time, QWidget* parent) {
    auto* dock = new QDockWidget(trView("Stride and cycle table"), parent);
    dock->setObjectName(QStringLiteral("cycleTableDock"));
    auto* view = new CycleTableView(project, dock);
    view->setTimeController(time);
    dock->setWidget(view);
    dock->setAttribute(Qt::WA_DeleteOnClose);
    return dock;
}

void launchCycleTable(Workspace& workspace) {
    if (!workspace.project()) return;
    QDockWidget* dock = makeDock(workspace.project(), workspace.timeController(), workspace.window());
    QObject::connect(workspace.notifier(), &WorkspaceNotifier::projectChanged, dock, &QWidget::close);
    workspace.addDock(dock, Qt::BottomDockWidgetArea);
}

// Screenshot: the first cycle table beside the plot of its recording's first stream, the cursor in its
// third row.
Status prepareCycleTable(Workspace& workspace) {
    Project* project = workspace.project();
    const QStringList tables = project ? CycleTableView::cycleTables(*project) : QStringList();
    if (tables.isEmpty())
        return makeError(
            trView("no table with start and end columns in this project (run gait-parameters, xc-skiing-cycles or "
                   "velocity-reset first)"));
    const QString path = tables.front();
    const QString recording = path.section(QLatin1Char('/'), 0, 0);
    // Plot the stream the table was computed from when its provenance names one, else the recording's first.
    const Table* table = project->table(path);
    QString stream = table->provenance.inputs.empty() ? QString() : table->provenance.inputs.front().name;
    if (!project->stream(stream)) {
        const Recording* rec = project->recording(recording);
        stream = rec->streams.empty() ? QString() : recording + QLatin1Char('/') + rec->streams.begin()->first;
    }
    if (!stream.isEmpty()) workspace.selectItem(stream);
    workspace.showTimeSeriesView();
    workspace.waitForPlots();
    TimeController* time = workspace.timeController();
    QDockWidget* dock = makeDock(project, time, workspace.window());
    auto* view = dock->findChild<CycleTableView*>();
    (void)view->setTable(path);  // a name from cycleTables(): cannot fail
    workspace.addDock(dock, Qt::BottomDockWidgetArea);
    workspace.resizeDock(dock, workspace.window()->height() * 2 / 5, Qt::Vertical);
    view->showRow(std::min<int>(2, static_cast<int>(table->rows()) - 1));
    QCoreApplication::processEvents();
    workspace.waitForPlots();
    return {};
}

}  // namespace

ATHLOS_REGISTER_TOOL({QStringLiteral("cycle-table-view"), QT_TRANSLATE_NOOP("Tools", "Stride and cycle table…"),
                      QT_TRANSLATE_NOOP("Tools", "Inertial"), launchCycleTable});
ATHLOS_REGISTER_VIEW({QStringLiteral("cycle-table"), prepareCycleTable});

}  // namespace athlos::ui
