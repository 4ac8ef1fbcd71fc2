#pragma once
// The coach's session report: the session-metrics of every athlete of a recording, computed where
// missing (in parallel, one athlete per core), then a PDF with a team page (table and distance bars)
// and a page per athlete (key figures, speed over time, zone bars, heat map on the venue, splits,
// action counts), drawn with QPainter on a QPdfWriter and QCustomPlot, as the GUI's panels are.
// `athlos report` and File ▸ Export report… run the same three steps.
#include "core/model/Project.h"
#include "core/model/Table.h"
#include "core/processing/ProcessorRunner.h"
#include "core/util/Expected.h"
#include "core/util/Progress.h"

#include <QList>
#include <QString>
#include <QVariantMap>
#include <vector>

namespace athlos::ui {

struct ReportAthlete {
    QString path;         // "rec/stream" of the positions
    QString label;        // "H7", else the stream name
    QString team;         // "home", "away" or empty
    QString metricsPath;  // "rec/stream-metrics" (session-metrics table; "-motion" is its motion)
};

class SessionReport {
public:
    // The athletes' position streams (PlaybackTracks::isAthlete) of one recording, or of every
    // recording when `recording` is empty. Error if there are none.
    static Expected<QList<ReportAthlete>> athletes(const Project& project, const QString& recording = {});

    // Whether an athlete's metrics table exists and was computed from the current positions.
    static bool isUpToDate(const Project& project, const ReportAthlete& athlete);

    // Runs session-metrics (with `parameters`) for the athletes whose table is missing or stale: the
    // runs are computed on the thread pool (both cores) against the unchanged project and stored in
    // order when all succeeded; on an error or cancellation nothing is stored. Returns how many ran.
    static Expected<int> computeMissing(Project& project, const QList<ReportAthlete>& athletes,
                                        const QVariantMap& parameters, const Progress& progress = {});
    // The computing half of computeMissing(): only reads the project, so it may run on a worker while
    // the GUI thread keeps reading the project; store the runs on the owning thread (storeRun()).
    static Expected<std::vector<ComputedRun>> computeMissingRuns(const Project& project,
                                                                 const QList<ReportAthlete>& athletes,
                                                                 const QVariantMap& parameters,
                                                                 const Progress& progress = {});

    // The team table: one row per athlete with the `whole` row of its metrics (athlete, team and the
    // numeric columns every athlete has).
    static Expected<Table> teamTable(const Project& project, const QList<ReportAthlete>& athletes);

    // Writes the PDF (needs a QApplication: the plots are QCustomPlot widgets). Error names the file.
    static Status writePdf(const Project& project, const QList<ReportAthlete>& athletes, const QString& path,
                           const Progress& progress = {});
};

}  // namespace athlos::ui
