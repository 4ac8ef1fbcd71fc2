#pragma once
// Drawing a PDF report page with QPainter (SessionReport, GaitReport): a cursor down the printable
// area, headings, text, simple tables and QCustomPlot plots laid out as the GUI's panels are.
#include "core/util/Expected.h"

#include <QFont>
#include <QList>
#include <QPainter>
#include <QRectF>
#include <QSaveFile>
#include <QString>
#include <QStringList>
#include <memory>

class QCustomPlot;
class QPdfWriter;

namespace athlos::ui {

// A PDF being written: A4, 200 dpi, 15 mm margins, into a temporary file that replaces `path` only in
// finish() (QSaveFile), so a cancelled or failed report leaves an older PDF as it was.
class ReportDocument {
public:
    explicit ReportDocument(const QString& path);
    ~ReportDocument();  // unfinished: the temporary file is discarded
    ReportDocument(const ReportDocument&) = delete;
    ReportDocument& operator=(const ReportDocument&) = delete;

    // Opens the file and starts the first page; errors name the file.
    Status open(const QString& title);
    QPainter& painter() { return painter_; }
    QRectF area() const;  // printable area of a page in device pixels
    void newPage();
    Status finish();

private:
    QString path_;
    QSaveFile file_;
    std::unique_ptr<QPdfWriter> writer_;
    QPainter painter_;
};

struct ReportPage {
    QPainter& painter;
    QRectF area;  // printable area in device pixels
    double y = 0;
    double lineHeight(const QFont& font) const { return QFontMetricsF(font, painter.device()).height(); }
};

namespace report {

// "1.23" with `decimals` digits, "–" for NaN or infinite.
QString number(double v, int decimals);

// A bold heading of `points` size; the cursor moves below it.
void heading(ReportPage& page, const QString& text, double points);

// Plain text of `points` size, wrapped within `lines` lines; the cursor moves down `advance` lines.
void text(ReportPage& page, const QString& text, double points, double lines = 1.0, double advance = 1.8);

// The height of one row of drawTable() (to split a long table over pages).
double tableRowHeight(const ReportPage& page);

// A simple table: header row, then rows (every other one shaded); column widths proportional to
// `weights`; the first column left-aligned, the others right-aligned.
void drawTable(ReportPage& page, const QStringList& header, const QList<QStringList>& rows,
               const QList<double>& weights);

// A QCustomPlot in the GUI's style, not shown on screen, without a legend.
QCustomPlot* newPlot();

// Draws a QCustomPlot laid out at 800 px wide (the GUI's look: fonts and lines in proportion) into the
// target rectangle, rasterised at the target's device resolution.
void drawPlot(QPainter& painter, QCustomPlot& plot, const QRectF& target);

}  // namespace report
}  // namespace athlos::ui
