#include "ui/report/GaitReport.h"

#include "core/processing/ProcessorRegistry.h"
#include "core/processing/ProcessorRunner.h"
#include "ui/PlotStyle.h"
#include "ui/report/ReportPage.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <qcustomplot.h>

namespace athlos::ui {

using namespace report;

namespace {

QString tr(const char* text) { return QCoreApplication::translate("athlos::ui::GaitReport", text); }

const QString kStrideKind = QStringLiteral("gait-parameters");

// "left", "right" or "" (the foot gait-parameters recorded).
QString footOf(const Table& t) { return t.attributes.value(QStringLiteral("foot")).toString(); }

// The number of a table cell, NaN where the column or row is missing.
double cell(const Table& t, const QString& column, long long row) {
    const TableColumn* c = t.column(column);
    if (!c || c->isText || row < 0 || row >= static_cast<long long>(c->numbers.size())) return std::nan("");
    return c->numbers[std::size_t(row)];
}

QString parameterLabel(const QString& name) {
    static const std::map<QString, const char*> labels{
        {QStringLiteral("stride_length"), QT_TRANSLATE_NOOP("athlos::ui::GaitReport", "Stride length")},
        {QStringLiteral("stride_height"), QT_TRANSLATE_NOOP("athlos::ui::GaitReport", "Stride height")},
        {QStringLiteral("stride_time"), QT_TRANSLATE_NOOP("athlos::ui::GaitReport", "Stride time")},
        {QStringLiteral("stance_time"), QT_TRANSLATE_NOOP("athlos::ui::GaitReport", "Stance time")},
        {QStringLiteral("swing_time"), QT_TRANSLATE_NOOP("athlos::ui::GaitReport", "Swing time")},
        {QStringLiteral("cadence"), QT_TRANSLATE_NOOP("athlos::ui::GaitReport", "Cadence")},
        {QStringLiteral("gait_speed"), QT_TRANSLATE_NOOP("athlos::ui::GaitReport", "Gait speed")},
        {QStringLiteral("max_toe_clearance"), QT_TRANSLATE_NOOP("athlos::ui::GaitReport", "Max. toe clearance")}};
    const auto it = labels.find(name);
    return it != labels.end() ? tr(it->second) : QString(name).replace(QLatin1Char('_'), QLatin1Char(' '));
}

int decimalsFor(const QString& unit) {
    if (unit == QLatin1String("steps/min")) return 1;
    if (unit == QLatin1String("m/s")) return 2;
    return 3;
}

// The row of `foot` ("left", "right", "both", or a table name) in the summary, -1 if absent.
long long summaryRow(const Table& summary, const QString& foot) {
    const TableColumn* c = summary.column(QStringLiteral("foot"));
    if (!c || !c->isText) return -1;
    return c->texts.indexOf(foot);
}

// Each foot's strides over time (`column` at each stride's start), the turns hollow.
void strideSeriesPlot(ReportPage& page, const std::vector<const Table*>& tables, const QString& column,
                      const QString& yLabel, double maxTurn, double height) {
    std::unique_ptr<QCustomPlot> plot(newPlot());
    plot->legend->setVisible(true);
    plot->legend->setFillOrder(QCPLayoutGrid::foColumnsFirst);  // one row, above the data (the range's headroom)
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignHCenter);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, t0 = lo, t1 = -lo;
    for (std::size_t f = 0; f < tables.size(); ++f) {
        const Table& t = *tables[f];
        const QColor colour = PlotStyle::seriesColor(int(f));
        QCPGraph* straight = plot->addGraph();
        QCPGraph* turns = plot->addGraph();
        straight->setName(footOf(t).isEmpty() ? t.name
                                              : (footOf(t) == QLatin1String("left") ? tr("left") : tr("right")));
        turns->setName(tr("turns (|turning angle| > %1 rad)").arg(maxTurn, 0, 'f', 2));
        straight->setPen(QPen(colour, 1.0));
        straight->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, colour, colour, 6));
        turns->setLineStyle(QCPGraph::lsNone);
        turns->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, colour, Qt::white, 7));
        for (long long r = 0; r < t.rows(); ++r) {
            const double x = cell(t, QStringLiteral("start"), r), y = cell(t, column, r);
            if (!std::isfinite(x) || !std::isfinite(y)) continue;
            const bool turn = std::abs(cell(t, QStringLiteral("turning_angle"), r)) > maxTurn;
            straight->addData(x, y);
            if (turn) turns->addData(x, y);  // hollow over the disc
            lo = std::min(lo, y), hi = std::max(hi, y), t0 = std::min(t0, x), t1 = std::max(t1, x);
        }
        turns->removeFromLegend();
    }
    // One legend entry for the turns, of the first foot that has any.
    for (int g = 1; g < plot->graphCount(); g += 2)
        if (plot->graph(g)->dataCount() > 0) {
            plot->graph(g)->addToLegend();
            break;
        }
    plot->xAxis->setLabel(tr("time (s)"));
    plot->yAxis->setLabel(yLabel);
    if (std::isfinite(lo)) {
        const double pad = std::max(0.05 * (hi - lo), 1e-3);
        plot->yAxis->setRange(std::min(0.0, lo - pad), hi + pad + 0.2 * (hi - std::min(0.0, lo - pad)));
        plot->xAxis->setRange(t0 - 1.0, t1 + 1.0);
    }
    drawPlot(page.painter, *plot, QRectF(page.area.left(), page.y, page.area.width(), height));
    page.y += height + page.area.height() * 0.015;
}

}  // namespace

Expected<GaitReportInput> GaitReport::strideTables(const Project& project, const QString& recording,
                                                   const QStringList& strides) {
    GaitReportInput input;
    if (!strides.isEmpty()) {
        if (strides.size() > 2)
            return makeError(
                QStringLiteral("a gait report takes one or two stride tables, not %1").arg(strides.size()));
        for (const QString& path : strides) {
            const Table* t = project.table(path);
            if (!t) return makeError(QStringLiteral("no table '%1' in the project").arg(path));
            if (!isStrideTable(*t))
                return makeError(
                    QStringLiteral("'%1' is a '%2' table, not a %3 table").arg(path, t->kind, kStrideKind));
            const QString rec = ItemPath::parse(path).recording;
            if (!input.recording.isEmpty() && rec != input.recording)
                return makeError(
                    QStringLiteral("the stride tables are from two recordings (%1, %2)").arg(input.recording, rec));
            input.recording = rec;
            input.strides << path;
        }
        if (strides.size() == 2 && footOf(*project.table(strides[0])) == footOf(*project.table(strides[1])) &&
            !footOf(*project.table(strides[0])).isEmpty())
            return makeError(QStringLiteral("'%1' and '%2' are both of the %3 foot")
                                 .arg(strides[0], strides[1], footOf(*project.table(strides[0]))));
    } else {
        QStringList candidates;
        if (!recording.isEmpty()) {
            if (!project.recording(recording)) return makeError(QStringLiteral("no recording '%1'").arg(recording));
            candidates << recording;
        } else {
            candidates = recordingsWithStrides(project);
            if (candidates.isEmpty())
                return makeError(QStringLiteral("the project has no %1 table: run gait-parameters on a foot IMU first")
                                     .arg(kStrideKind));
            if (candidates.size() > 1)
                return makeError(QStringLiteral("several recordings have stride tables (%1): choose one")
                                     .arg(candidates.join(QStringLiteral(", "))));
        }
        input.recording = candidates.front();
        std::map<QString, QStringList> byFoot;  // "left" < "right" < others
        for (const auto& [tableName, table] : project.recording(input.recording)->tables)
            if (isStrideTable(table)) byFoot[footOf(table)] << tableName;
        if (byFoot.empty())
            return makeError(QStringLiteral("'%1' has no %2 table: run gait-parameters on its foot streams first")
                                 .arg(input.recording, kStrideKind));
        for (const auto& [foot, names] : byFoot)
            if (names.size() > 1)
                return makeError(QStringLiteral("'%1' has %2 %3 tables%4 (%5): name the ones to report")
                                     .arg(input.recording, QString::number(names.size()), kStrideKind,
                                          foot.isEmpty() ? QString() : QStringLiteral(" of the %1 foot").arg(foot),
                                          names.join(QStringLiteral(", "))));
        if (byFoot.size() > 2)
            return makeError(QStringLiteral("'%1' has stride tables of more than two feet: name the ones to report")
                                 .arg(input.recording));
        for (const QString& foot : {QStringLiteral("left"), QStringLiteral("right")})
            if (const auto it = byFoot.find(foot); it != byFoot.end())
                input.strides << input.recording + u'/' + it->second.front();
        for (const auto& [foot, names] : byFoot)
            if (foot != QLatin1String("left") && foot != QLatin1String("right"))
                input.strides << input.recording + u'/' + names.front();
    }
    return input;
}

bool GaitReport::isStrideTable(const Table& table) { return table.kind == kStrideKind; }

QStringList GaitReport::recordingsWithStrides(const Project& project) {
    QStringList names;
    for (const auto& [name, rec] : project.recordings())
        if (std::any_of(rec.tables.begin(), rec.tables.end(),
                        [](const auto& entry) { return isStrideTable(entry.second); }))
            names << name;
    return names;
}

QString GaitReport::defaultRecording(const Project& project, const QString& selected) {
    const QStringList withStrides = recordingsWithStrides(project);
    if (withStrides.contains(selected)) return selected;
    return withStrides.size() == 1 ? withStrides.front() : QString();
}

Expected<Table> GaitReport::summary(const Project& project, const GaitReportInput& input,
                                    const QVariantMap& parameters) {
    const auto processor = ProcessorRegistry::instance().find(QStringLiteral("gait-summary"));
    if (!processor) return makeError(QStringLiteral("the gait-summary processor is not available (events plugin)"));
    // The output name only labels the run (nothing is stored); one the recording does not hold, so that
    // no item of that name makes the run refuse.
    QString label = input.recording + QStringLiteral("/gait-report");
    for (int n = 2; project.stream(label) || project.table(label); ++n)
        label = input.recording + QStringLiteral("/gait-report-%1").arg(n);
    auto run = computeRun(project, *processor, RunRequest{processor->id(), input.strides, label, parameters});
    if (!run) return run.error();
    for (auto& produced : run->produced)
        if (auto* table = std::get_if<Table>(&produced.item)) return std::move(*table);
    return makeError(QStringLiteral("gait-summary gave no table"));
}

Status GaitReport::writePdf(const Project& project, const GaitReportInput& input, const Table& summary,
                            const QString& path, const Progress& progress) {
    std::vector<const Table*> tables;
    for (const QString& p : input.strides) {
        const Table* t = project.table(p);
        if (!t) return makeError(QStringLiteral("no table '%1' in the project").arg(p));
        tables.push_back(t);
    }
    ReportDocument document(path);  // a cancelled or failed report leaves an older PDF as it was
    if (Status s = document.open(tr("Athlos gait report")); !s) return s;
    QPainter& painter = document.painter();
    const QRectF area = document.area();

    // Page 1: what was measured, the steady state, the strides over time.
    ReportPage page{painter, area, 0};
    heading(page, tr("Gait report: %1").arg(input.recording), 16);
    const QString method = tables.front()->attributes.value(QStringLiteral("method")).toString();
    text(page,
         tr("%1 · %2 · generated %3 by Athlos")
             .arg(QFileInfo(project.path()).fileName(), input.strides.join(QStringLiteral(", ")),
                  QDateTime::currentDateTimeUtc().toString(QStringLiteral("yyyy-MM-dd HH:mm 'UTC'"))),
         9);
    const QJsonObject& a = summary.attributes;
    const double maxTurn = a.value(QStringLiteral("max_turn")).toDouble();  // rad
    text(page,
         tr("Strides from mid-stance to mid-stance of a foot-mounted IMU (gait-parameters, method %1). Steady "
            "state (gait-summary): strides with |turning angle| ≤ %2 rad on terrain '%3', without the first and "
            "last %4 stride(s) of each run of straight strides. SD: sample standard deviation; CV = SD / mean; "
            "SI: symmetry index 100 |left − right| / mean of both (Robinson et al. 1987).")
             .arg(method.isEmpty() ? QStringLiteral("–") : method)
             .arg(maxTurn, 0, 'f', 2)
             .arg(a.value(QStringLiteral("terrain")).toString())
             .arg(a.value(QStringLiteral("edge_strides")).toInt()),
         9, 4.2, 4.6);

    QStringList feet;  // the summary's rows, one per table
    for (const Table* t : tables) feet << (footOf(*t).isEmpty() ? t->name : footOf(*t));
    QStringList counts;
    for (const QString& foot : feet) {
        const long long r = summaryRow(summary, foot);
        counts << tr("%1: %2 of %3 strides in the steady state")
                      .arg(foot)
                      .arg(cell(summary, QStringLiteral("used"), r))
                      .arg(cell(summary, QStringLiteral("strides"), r));
    }
    text(page, counts.join(QStringLiteral(" · ")), 9);

    const bool two = feet.size() == 2 && summaryRow(summary, QStringLiteral("both")) >= 0;
    QStringList header{tr("Parameter")};
    for (const QString& foot : feet) header << tr("%1 mean").arg(foot) << tr("SD") << tr("CV %");
    if (two) header << tr("both mean") << tr("SI %");
    QList<double> weights{2.2};
    for (int f = 0; f < feet.size(); ++f) weights << 1.2 << 1.0 << 0.8;
    if (two) weights << 1.2 << 0.8;
    QList<QStringList> rows;
    for (const TableColumn& c : summary.columns) {
        if (!c.name.endsWith(QLatin1String("_mean"))) continue;
        const QString p = c.name.chopped(5);
        const int decimals = decimalsFor(c.unit);
        QStringList row{QStringLiteral("%1 (%2)").arg(parameterLabel(p), c.unit)};
        for (const QString& foot : feet) {
            const long long r = summaryRow(summary, foot);
            row << number(cell(summary, p + QStringLiteral("_mean"), r), decimals)
                << number(cell(summary, p + QStringLiteral("_sd"), r), decimals)
                << number(cell(summary, p + QStringLiteral("_cv"), r), 1);
        }
        if (two) {
            const long long r = summaryRow(summary, QStringLiteral("both"));
            row << number(cell(summary, p + QStringLiteral("_mean"), r), decimals)
                << number(cell(summary, p + QStringLiteral("_si"), r), 1);
        }
        rows << row;
    }
    drawTable(page, header, rows, weights);
    const double plotHeight = std::max(area.height() * 0.15, (area.bottom() - page.y) / 2.0 - area.height() * 0.02);
    strideSeriesPlot(page, tables, QStringLiteral("stride_length"), tr("stride length (m)"), maxTurn, plotHeight);
    strideSeriesPlot(page, tables, QStringLiteral("gait_speed"), tr("gait speed (m/s)"), maxTurn, plotHeight);
    progress.report(0.3, QStringLiteral("summary page"));

    // Then every stride, in time order over both feet.
    struct Row {
        double start;
        QStringList cells;
    };
    std::vector<Row> strideRows;
    for (std::size_t f = 0; f < tables.size(); ++f) {
        const Table& t = *tables[f];
        for (long long r = 0; r < t.rows(); ++r) {
            const auto v = [&](const char* column) { return cell(t, QLatin1String(column), r); };
            strideRows.push_back(
                {v("start"),
                 {feet[int(f)], number(v("start"), 2), number(v("stride_length"), 3), number(v("stride_height"), 3),
                  number(v("stride_time"), 3), number(100.0 * v("stance_time") / v("stride_time"), 1),
                  number(v("cadence"), 1), number(v("gait_speed"), 2), number(v("max_toe_clearance"), 3),
                  number(v("turning_angle") * 180.0 / std::numbers::pi, 1)}});
        }
    }
    std::stable_sort(strideRows.begin(), strideRows.end(),
                     [](const Row& x, const Row& y) { return x.start < y.start; });
    const QStringList strideHeader{tr("Foot"),     tr("Start s"), tr("Length m"),  tr("Height m"),    tr("Time s"),
                                   tr("Stance %"), tr("Cadence"), tr("Speed m/s"), tr("Clearance m"), tr("Turn °")};
    const QList<double> strideWeights{1.1, 1, 1, 1, 0.9, 0.9, 0.9, 1.1, 1.3, 0.9};
    std::size_t next = 0;
    for (int pageNumber = 2; next < strideRows.size(); ++pageNumber) {
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        document.newPage();
        ReportPage p{painter, area, 0};
        heading(p, tr("Strides (%1)").arg(input.recording), 13);
        const auto fit = std::size_t(std::max(1.0, std::floor((area.bottom() - p.y) / tableRowHeight(p)) - 2.0));
        QList<QStringList> chunk;
        for (; next < strideRows.size() && std::size_t(chunk.size()) < fit; ++next) chunk << strideRows[next].cells;
        drawTable(p, strideHeader, chunk, strideWeights);
        progress.report(0.3 + 0.7 * double(next) / double(strideRows.size()),
                        QStringLiteral("page %1").arg(pageNumber));
    }
    if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
    return document.finish();
}

}  // namespace athlos::ui
