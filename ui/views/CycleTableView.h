#pragma once
// Per-cycle result tables (issue #17 item 6, "the gait table with per-stride rows linked to the
// cursor"): any table with numeric `start` and `end` columns in seconds — one row per stride
// (gait-parameters), cross-country cycle (xc-skiing-cycles), zero-velocity phase (velocity-reset), … —
// listed with its units, followed by the mean and the sample SD of every numeric column over the rows.
// The rows follow the window's TimeController both ways: the row whose [start, end) holds the cursor is
// selected as the cursor moves (playback, arrows, a click in a plot); selecting a row puts the cursor
// at its start and shows the cycle with a quarter of its duration on either side.
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <QWidget>

class QComboBox;
class QLabel;
class QTableWidget;

namespace athlos {
class Project;
struct Table;
struct TableColumn;
}  // namespace athlos

namespace athlos::ui {

class TimeController;

class CycleTableView : public QWidget {
    Q_OBJECT

public:
    struct Summary {
        double mean = 0.0, sd = 0.0;  // sd: sample SD (n − 1); 0 for one value
        int count = 0;                // finite values
    };

    explicit CycleTableView(const Project* project, QWidget* parent = nullptr);

    // "rec/table" of every table with numeric columns `start` and `end` (s), in project order.
    static QStringList cycleTables(const Project& project);
    // The first row whose [start, end) holds t, or -1.
    static int rowAt(const Table& table, double t);
    // Mean and sample SD of the finite values of a numeric column.
    static Summary summary(const TableColumn& column);

    Status setTable(const QString& path);
    QString tablePath() const;
    void setTimeController(TimeController* time);

    // The data row selected (following the cursor or clicked), or -1.
    int currentRow() const;
    // Puts the cursor at the row's start and shows the cycle (what a click on the row does).
    void showRow(int row);
    QTableWidget* tableWidget() const { return grid_; }

private:
    void fill();
    void followCursor(double t);

    const Project* project_;
    TimeController* time_ = nullptr;
    QComboBox* choice_ = nullptr;
    QLabel* note_ = nullptr;
    QTableWidget* grid_ = nullptr;
    int rows_ = 0;          // data rows (the summary rows follow)
    bool syncing_ = false;  // selecting a row from the cursor: do not move the cursor back
};

}  // namespace athlos::ui
