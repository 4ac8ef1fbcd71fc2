#pragma once
// The gait report: the stride tables of gait-parameters (one foot or both) of a recording as a PDF for
// a clinician or a study file. Page 1: the steady-state summary (gait-summary, computed in memory
// with the caller's parameters: per parameter and foot mean, SD and CV, and the symmetry index),
// stride length and gait speed over time per foot with the turns marked; then every stride in a
// table. Nothing is stored in the project. `athlos report --gait` and File ▸ Export gait report… run
// the same three steps.
#include "core/model/Project.h"
#include "core/model/Table.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QString>
#include <QStringList>
#include <QVariantMap>

namespace athlos::ui {

struct GaitReportInput {
    QString recording;
    QStringList strides;  // "rec/table" of gait-parameters tables, one per foot, left first (1 or 2)
};

class GaitReport {
public:
    // The tables to report: `strides` when given (gait-parameters tables of one recording), else the
    // gait-parameters tables of `recording`, or of the only recording that has any when `recording`
    // is empty. Errors name what is missing or ambiguous (two tables of one foot, several recordings).
    static Expected<GaitReportInput> strideTables(const Project& project, const QString& recording,
                                                  const QStringList& strides = {});

    // Whether a table is a stride table of gait-parameters (kind "gait-parameters").
    static bool isStrideTable(const Table& table);
    // The recordings that hold at least one stride table, in the project's order.
    static QStringList recordingsWithStrides(const Project& project);

    // The recording to offer: `selected` when it has gait-parameters tables, else the only recording
    // that has any; empty when none or several have them.
    static QString defaultRecording(const Project& project, const QString& selected);

    // gait-summary of the tables with `parameters` (its declaration: max_turn, terrain, …), computed
    // without storing anything.
    static Expected<Table> summary(const Project& project, const GaitReportInput& input,
                                   const QVariantMap& parameters = {});

    // Writes the PDF (needs a QApplication: the plots are QCustomPlot widgets) to a temporary file that
    // replaces `path` only when complete. Error names the file; "cancelled" when the progress was.
    static Status writePdf(const Project& project, const GaitReportInput& input, const Table& summary,
                           const QString& path, const Progress& progress = {});
};

}  // namespace athlos::ui
