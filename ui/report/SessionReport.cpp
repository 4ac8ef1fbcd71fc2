#include "ui/report/SessionReport.h"

#include "core/geometry/PitchGeometry.h"
#include "core/processing/ProcessorRegistry.h"
#include "core/processing/ProcessorRunner.h"
#include "ui/PlotStyle.h"
#include "ui/report/ReportPage.h"
#include "ui/venue/VenueDrawing.h"
#include "ui/views/PlaybackTracks.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QPainter>
#include <QPixmap>
#include <QThread>
#include <QtConcurrent>
#include <algorithm>
#include <cmath>
#include <optional>
#include <qcustomplot.h>

namespace athlos::ui {

using namespace report;

namespace {

using Page = ReportPage;

QString tr(const char* text) { return QCoreApplication::translate("athlos::ui::SessionReport", text); }

const QString kWhole = QStringLiteral("whole");

int wholeRow(const Table& table) {
    const TableColumn* period = table.column(QStringLiteral("period"));
    if (!period || !period->isText) return -1;
    return static_cast<int>(period->texts.indexOf(kWhole));
}

double value(const Table& table, const QString& column, int row) {
    const TableColumn* c = table.column(column);
    if (!c || c->isText || row < 0 || row >= static_cast<int>(c->numbers.size())) return std::nan("");
    return c->numbers[std::size_t(row)];
}

void barChart(Page& page, const QStringList& labels, const QVector<double>& values, const QString& xLabel,
              const QString& yLabel, double height, const QColor& color) {
    std::unique_ptr<QCustomPlot> plot(newPlot());
    auto* bars = new QCPBars(plot->xAxis, plot->yAxis);
    QVector<double> keys;
    for (int i = 0; i < labels.size(); ++i) keys << i + 1;
    bars->setData(keys, values);
    bars->setBrush(color);
    bars->setPen(Qt::NoPen);
    QSharedPointer<QCPAxisTickerText> ticker(new QCPAxisTickerText);
    for (int i = 0; i < labels.size(); ++i) ticker->addTick(i + 1, labels[i]);
    plot->xAxis->setTicker(ticker);
    plot->xAxis->setTickLabelRotation(labels.size() > 8 ? 60 : 0);
    plot->xAxis->setRange(0.3, labels.size() + 0.7);
    plot->xAxis->setLabel(xLabel);
    plot->yAxis->setLabel(yLabel);
    double top = 0;
    for (double v : values) top = std::max(top, std::isfinite(v) ? v : 0.0);
    plot->yAxis->setRange(0, top > 0 ? top * 1.1 : 1.0);
    drawPlot(page.painter, *plot, QRectF(page.area.left(), page.y, page.area.width(), height));
    page.y += height + page.area.height() * 0.015;
}

// Speed over time from the metrics' motion stream, decimated to at most ~3000 points (max per bin).
void speedPlot(Page& page, const StreamData& motion, int speedColumn, double height) {
    std::unique_ptr<QCustomPlot> plot(newPlot());
    QCPGraph* graph = plot->addGraph();
    graph->setPen(QPen(PlotStyle::seriesColor(0), 1.2));
    const std::size_t n = motion.rows(), bin = std::max<std::size_t>(1, n / 3000);
    QVector<double> t, v;
    double top = 0;
    for (std::size_t a = 0; a < n; a += bin) {
        double best = -1, at = motion.t[a];
        for (std::size_t k = a; k < std::min(n, a + bin); ++k)
            if (motion.at(k, speedColumn) > best) best = motion.at(k, speedColumn), at = motion.t[k];
        t << at / 60.0;
        v << best * 3.6;
        top = std::max(top, best * 3.6);
    }
    graph->setData(t, v, true);
    plot->xAxis->setLabel(tr("time (min)"));
    plot->yAxis->setLabel(tr("speed (km/h)"));
    plot->xAxis->setRange(t.isEmpty() ? 0 : t.front(), t.isEmpty() ? 1 : t.back());
    plot->yAxis->setRange(0, std::max(10.0, top * 1.05));
    drawPlot(page.painter, *plot, QRectF(page.area.left(), page.y, page.area.width(), height));
    page.y += height + page.area.height() * 0.015;
}

// Heat map: time spent per 1-m cell on the venue, drawn over the venue in the pitch frame.
void heatMap(Page& page, const AthleteTrack& track, const std::optional<PitchGeometry>& pitch,
             VenueDrawing::Venue venue, double height) {
    VenueDrawing::Size size;
    if (pitch) size = {pitch->length(), pitch->width()};
    QRectF world = VenueDrawing::bounds(venue, size);
    if (world.isEmpty()) {
        QRectF extent;
        for (std::size_t k = 0; k < track.x.size(); ++k)
            if (std::isfinite(track.x[k]) && std::isfinite(track.y[k]))
                extent = extent.united(QRectF(track.x[k] - 1, track.y[k] - 1, 2, 2));
        world = extent.adjusted(-5, -5, 5, 5);
    }
    const QRectF screen(page.area.left(), page.y, page.area.width(), height);
    const double scale = std::min(screen.width() / world.width(), screen.height() / world.height());
    QTransform toScreen;
    toScreen.translate(screen.center().x(), screen.center().y());
    toScreen.scale(scale, -scale);
    toScreen.translate(-world.center().x(), -world.center().y());
    const QRectF drawn = toScreen.mapRect(world);
    page.painter.save();
    page.painter.setClipRect(drawn);
    VenueDrawing::draw(page.painter, toScreen, venue, drawn, size);
    // 1-m cells, counts of samples; colour by the share of the busiest cell.
    const double cell = 1.0;
    const int nx = std::max(1, int(std::ceil(world.width() / cell))),
              ny = std::max(1, int(std::ceil(world.height() / cell)));
    std::vector<double> counts(std::size_t(nx) * std::size_t(ny), 0.0);
    double most = 0;
    for (std::size_t k = 0; k < track.x.size(); ++k) {
        if (!std::isfinite(track.x[k]) || !std::isfinite(track.y[k])) continue;
        const int i = int((track.x[k] - world.left()) / cell), j = int((track.y[k] - world.top()) / cell);
        if (i < 0 || j < 0 || i >= nx || j >= ny) continue;
        double& c = counts[std::size_t(j) * std::size_t(nx) + std::size_t(i)];
        most = std::max(most, ++c);
    }
    page.painter.setPen(Qt::NoPen);
    for (int j = 0; j < ny && most > 0; ++j)
        for (int i = 0; i < nx; ++i) {
            const double c = counts[std::size_t(j) * std::size_t(nx) + std::size_t(i)];
            if (c <= 0) continue;
            const double share = std::sqrt(c / most);  // square root: short stays stay visible
            QColor colour = QColor::fromHsvF(std::max(0.0, 0.17 - 0.17 * share), 0.95, 1.0, 0.25 + 0.65 * share);
            const QRectF r = toScreen.mapRect(QRectF(world.left() + i * cell, world.top() + j * cell, cell, cell));
            page.painter.fillRect(r, colour);
        }
    page.painter.restore();
    page.y += height + page.area.height() * 0.015;
}

}  // namespace

Expected<QList<ReportAthlete>> SessionReport::athletes(const Project& project, const QString& recording) {
    QStringList recordings = recording.isEmpty() ? project.recordingNames() : QStringList{recording};
    if (!recording.isEmpty() && !project.recording(recording))
        return makeError(QStringLiteral("--recording '%1': no such recording in %2").arg(recording, project.path()));
    QList<ReportAthlete> list;
    for (const QString& rec : recordings)
        for (const QString& path : PlaybackTracks::positionStreams(project, rec)) {
            const Stream* s = project.stream(path);
            if (!s || !PlaybackTracks::isAthlete(*s)) continue;
            ReportAthlete a;
            a.path = path;
            const QJsonObject attrs = s->info().attributes;
            a.label = attrs.value(QStringLiteral("label")).toString();
            if (a.label.isEmpty()) a.label = attrs.value(QStringLiteral("athlete")).toString();
            if (a.label.isEmpty()) a.label = recordings.size() > 1 ? path : ItemPath::parse(path).item;
            a.team = attrs.value(QStringLiteral("team")).toString();
            a.metricsPath = path + QStringLiteral("-metrics");
            list << a;
        }
    if (list.isEmpty())
        return makeError(recording.isEmpty()
                             ? QStringLiteral("%1 has no athlete position streams (lps-position, gnss or trajectory)")
                                   .arg(project.path())
                             : QStringLiteral("recording '%1' has no athlete position streams").arg(recording));
    return list;
}

bool SessionReport::isUpToDate(const Project& project, const ReportAthlete& athlete) {
    const Table* table = project.table(athlete.metricsPath);
    const Stream* positions = project.stream(athlete.path);
    if (!table || !positions || table->kind != QLatin1String("session-metrics")) return false;
    const auto& inputs = table->provenance.inputs;
    return !inputs.empty() && inputs.front().name == athlete.path &&
           inputs.front().hash == positions->info().contentHash &&
           project.stream(athlete.metricsPath + QStringLiteral("-motion"));
}

Expected<std::vector<ComputedRun>> SessionReport::computeMissingRuns(const Project& project,
                                                                     const QList<ReportAthlete>& athletes,
                                                                     const QVariantMap& parameters,
                                                                     const Progress& progress) {
    auto processor = ProcessorRegistry::instance().find(QStringLiteral("session-metrics"));
    if (!processor) return makeError(QStringLiteral("the session-metrics processor is not available (metrics plugin)"));
    QList<ReportAthlete> missing;
    for (const auto& a : athletes)
        if (!isUpToDate(project, a)) missing << a;
    if (missing.isEmpty()) return std::vector<ComputedRun>{};
    // Compute on the pool (both cores) against the unchanged project; store afterwards, in order.
    std::atomic<int> done{0};
    const Progress quiet(Progress::Callback{}, progress.token());
    QList<QFuture<Expected<ComputedRun>>> futures;
    for (const auto& a : missing)
        futures << QtConcurrent::run([&project, processor, a, parameters, quiet, &done]() {
            auto run = computeRun(project, *processor, RunRequest{processor->id(), {a.path}, a.metricsPath, parameters},
                                  quiet);
            ++done;
            return run;
        });
    for (bool finished = false; !finished;) {
        finished = true;
        for (auto& f : futures) finished = finished && f.isFinished();
        progress.report(double(done.load()) / double(missing.size()),
                        QStringLiteral("session metrics %1/%2").arg(done.load()).arg(missing.size()));
        if (!finished) QThread::msleep(50);
    }
    if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
    std::vector<ComputedRun> runs;
    for (int i = 0; i < futures.size(); ++i) {
        auto result = futures[i].result();
        if (!result) return makeError(QStringLiteral("%1: %2").arg(missing[i].path, result.message()));
        runs.push_back(std::move(*result));
    }
    return runs;
}

Expected<int> SessionReport::computeMissing(Project& project, const QList<ReportAthlete>& athletes,
                                            const QVariantMap& parameters, const Progress& progress) {
    auto runs = computeMissingRuns(project, athletes, parameters, progress);
    if (!runs) return runs.error();
    for (auto& run : *runs) storeRun(project, std::move(run));
    return static_cast<int>(runs->size());
}

Expected<Table> SessionReport::teamTable(const Project& project, const QList<ReportAthlete>& athletes) {
    Table team;
    team.name = QStringLiteral("team");
    team.kind = QStringLiteral("session-metrics-team");
    QStringList numeric;  // numeric columns every athlete's table has, in the first table's order
    for (const auto& a : athletes) {
        const Table* t = project.table(a.metricsPath);
        if (!t || wholeRow(*t) < 0)
            return makeError(QStringLiteral("%1: no session metrics (run session-metrics)").arg(a.path));
        QStringList here;
        for (const auto& c : t->columns)
            if (!c.isText) here << c.name;
        if (&a == &athletes.front())
            numeric = here;
        else
            numeric.erase(
                std::remove_if(numeric.begin(), numeric.end(), [&](const QString& n) { return !here.contains(n); }),
                numeric.end());
    }
    team.columns.push_back(TableColumn{QStringLiteral("athlete"), QString(), true, {}, {}});
    team.columns.push_back(TableColumn{QStringLiteral("team"), QString(), true, {}, {}});
    team.columns.push_back(TableColumn{QStringLiteral("positions"), QString(), true, {}, {}});
    const Table* first = project.table(athletes.front().metricsPath);
    for (const QString& n : numeric) team.columns.push_back(TableColumn{n, first->column(n)->unit, false, {}, {}});
    for (const auto& a : athletes) {
        const Table* t = project.table(a.metricsPath);
        const int row = wholeRow(*t);
        team.columns[0].texts << a.label;
        team.columns[1].texts << a.team;
        team.columns[2].texts << a.path;
        for (int i = 0; i < numeric.size(); ++i)
            team.columns[std::size_t(3 + i)].numbers.push_back(value(*t, numeric[i], row));
    }
    return team;
}

Status SessionReport::writePdf(const Project& project, const QList<ReportAthlete>& athletes, const QString& path,
                               const Progress& progress) {
    auto team = teamTable(project, athletes);
    if (!team) return team.error();
    ReportDocument document(path);  // a cancelled or failed report leaves an older PDF as it was
    if (Status s = document.open(tr("Athlos session report")); !s) return s;
    QPainter& painter = document.painter();
    const QRectF area = document.area();
    const auto pitch = PitchGeometry::firstOf(project.geometry());

    // Team page.
    Page page{painter, area, 0};
    const QString recordingNames = [&] {
        QStringList names;
        for (const auto& a : athletes)
            if (!names.contains(ItemPath::parse(a.path).recording)) names << ItemPath::parse(a.path).recording;
        return names.join(QStringLiteral(", "));
    }();
    heading(page, tr("Session report: %1").arg(recordingNames), 16);
    {
        QFont f = painter.font();
        f.setPointSizeF(9);
        f.setBold(false);
        painter.setFont(f);
        painter.drawText(QRectF(area.left(), page.y, area.width(), page.lineHeight(f)), Qt::AlignLeft,
                         tr("%1 · %2 athletes · generated %3 by Athlos")
                             .arg(QFileInfo(project.path()).fileName())
                             .arg(athletes.size())
                             .arg(QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyy-MM-dd HH:mm 'UTC'"))));
        page.y += page.lineHeight(f) * 1.8;
    }
    const QStringList header{tr("Athlete"), tr("Distance m"), tr("Max km/h"),     tr("HSR m"),    tr("Sprints"),
                             tr("Acc"),     tr("Dec"),        tr("Peak 1 min m"), tr("Met. W/kg")};
    QList<QStringList> rows;
    QStringList labels;
    QVector<double> distances;
    for (long long r = 0; r < team->rows(); ++r) {
        auto v = [&](const char* column) { return value(*team, QLatin1String(column), int(r)); };
        const QString label = team->columns[0].texts[int(r)];
        rows << QStringList{label,
                            number(v("distance"), 0),
                            number(v("max_speed") * 3.6, 1),
                            number(v("hsr_distance"), 0),
                            number(v("sprint_count"), 0),
                            number(v("acceleration_count"), 0),
                            number(v("deceleration_count"), 0),
                            number(v("peak_distance_1min"), 0),
                            number(v("metabolic_power"), 1)};
        labels << label;
        distances << v("distance");
    }
    drawTable(page, header, rows, {2.0, 1.2, 1, 1, 0.9, 0.7, 0.8, 1.5, 1.2});
    if (page.y < area.height() * 0.72)
        barChart(page, labels, distances, QString(), tr("distance (m)"), area.height() * 0.25,
                 PlotStyle::seriesColor(0));
    progress.report(1.0 / double(athletes.size() + 1), QStringLiteral("team page"));

    // A page per athlete.
    for (int i = 0; i < athletes.size(); ++i) {
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        const ReportAthlete& a = athletes[i];
        document.newPage();
        Page p{painter, area, 0};
        heading(p, a.team.isEmpty() ? a.label : QStringLiteral("%1 (%2)").arg(a.label, a.team), 15);
        const Table* t = project.table(a.metricsPath);
        const int whole = wholeRow(*t);
        {
            QFont f = painter.font();
            f.setPointSizeF(9.5);
            f.setBold(false);
            painter.setFont(f);
            auto v = [&](const char* column) { return value(*t, QLatin1String(column), whole); };
            painter.drawText(QRectF(area.left(), p.y, area.width(), p.lineHeight(f) * 2.4),
                             Qt::AlignLeft | Qt::TextWordWrap,
                             tr("%1 · distance %2 m in %3 min · max speed %4 km/h · HSR %5 m · sprints %6 · "
                                "accelerations %7 · decelerations %8 · metabolic power %9 W/kg")
                                 .arg(a.path, number(v("distance"), 0), number(v("duration") / 60.0, 1),
                                      number(v("max_speed") * 3.6, 1), number(v("hsr_distance"), 0),
                                      number(v("sprint_count"), 0), number(v("acceleration_count"), 0),
                                      number(v("deceleration_count"), 0), number(v("metabolic_power"), 1)));
            p.y += p.lineHeight(f) * 2.8;
        }
        const Stream* motion = project.stream(a.metricsPath + QStringLiteral("-motion"));
        if (motion) {
            auto data = motion->data();
            if (!data) return makeError(QStringLiteral("%1: %2").arg(a.metricsPath, data.message()));
            speedPlot(p, **data, motion->info().columnIndex(QStringLiteral("speed")), area.height() * 0.17);
        }
        // Zone bars.
        QStringList zoneLabels;
        QVector<double> zoneValues;
        const QJsonArray edges = t->attributes.value(QStringLiteral("zone_edges_mps")).toArray();
        for (int z = 0;; ++z) {
            const TableColumn* c = t->column(QStringLiteral("distance_zone%1").arg(z + 1));
            if (!c) break;
            const double lo = edges.size() > z ? edges[z].toDouble() * 3.6 : 0;
            zoneLabels
                << (edges.size() > z + 1
                        ? QStringLiteral("%1–%2").arg(lo, 0, 'f', 1).arg(edges[z + 1].toDouble() * 3.6, 0, 'f', 1)
                        : QStringLiteral("> %1").arg(lo, 0, 'f', 1));
            zoneValues << c->numbers[std::size_t(whole)];
        }
        barChart(p, zoneLabels, zoneValues, tr("speed zone (km/h)"), tr("distance (m)"), area.height() * 0.15,
                 PlotStyle::seriesColor(1));
        // Heat map on the venue, in the pitch frame when a pitch is placed.
        if (motion) {
            AthleteTrack track;
            if (PlaybackTracks::read(*motion, a.metricsPath + QStringLiteral("-motion"), track,
                                     pitch ? &*pitch : nullptr)) {
                VenueDrawing::Venue venue = pitch ? VenueDrawing::ofPitch(pitch->kind()) : VenueDrawing::Venue::None;
                if (!pitch) {
                    const Recording* rec = project.recording(ItemPath::parse(a.path).recording);
                    const auto id = rec ? VenueDrawing::fromId(rec->metadata.value(QStringLiteral("venue")).toString())
                                        : std::nullopt;
                    QRectF extent;
                    for (std::size_t k = 0; k < track.x.size(); ++k)
                        if (std::isfinite(track.x[k]))
                            extent = extent.united(QRectF(track.x[k], track.y[k], 0.01, 0.01));
                    venue = id ? *id : VenueDrawing::guess(extent);
                }
                heatMap(p, track, pitch, venue, area.height() * 0.3);
            }
        }
        // Splits (the other rows) and action counts.
        QList<QStringList> splitRows;
        const TableColumn* period = t->column(QStringLiteral("period"));
        for (int r = 0; r < int(t->rows()) && splitRows.size() < 14; ++r) {
            if (r == whole) continue;
            splitRows << QStringList{period->texts[r],
                                     number(value(*t, QStringLiteral("start"), r) / 60.0, 1),
                                     number(value(*t, QStringLiteral("duration"), r) / 60.0, 1),
                                     number(value(*t, QStringLiteral("distance"), r), 0),
                                     number(value(*t, QStringLiteral("max_speed"), r) * 3.6, 1),
                                     number(value(*t, QStringLiteral("hsr_distance"), r), 0),
                                     number(value(*t, QStringLiteral("sprint_count"), r), 0)};
        }
        if (!splitRows.isEmpty())
            drawTable(p,
                      {tr("Period"), tr("Start min"), tr("Min"), tr("Distance m"), tr("Max km/h"), tr("HSR m"),
                       tr("Sprints")},
                      splitRows, {2, 1, 0.8, 1.1, 1, 1, 0.9});
        QStringList actions;
        for (const auto& c : t->columns)
            if (c.name.startsWith(QLatin1String("actions_")))
                actions << QStringLiteral("%1: %2").arg(c.name.mid(8)).arg(c.numbers[std::size_t(whole)]);
        if (!actions.isEmpty()) {
            QFont f = painter.font();
            f.setPointSizeF(9);
            f.setBold(false);
            painter.setFont(f);
            painter.drawText(QRectF(area.left(), p.y, area.width(), p.lineHeight(f) * 3),
                             Qt::AlignLeft | Qt::TextWordWrap,
                             tr("Actions: %1").arg(actions.join(QStringLiteral(", "))));
        }
        progress.report(double(i + 2) / double(athletes.size() + 1), QStringLiteral("page %1").arg(i + 2));
    }
    return document.finish();
}

}  // namespace athlos::ui
