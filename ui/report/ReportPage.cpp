#include "ui/report/ReportPage.h"

#include "ui/PlotStyle.h"

#include <QPageSize>
#include <QPdfWriter>
#include <QPixmap>
#include <algorithm>
#include <cmath>
#include <qcustomplot.h>

namespace athlos::ui {

ReportDocument::ReportDocument(const QString& path) : path_(path), file_(path) {}

ReportDocument::~ReportDocument() {
    if (painter_.isActive()) painter_.end();
}

Status ReportDocument::open(const QString& title) {
    if (!file_.open(QIODevice::WriteOnly))
        return makeError(QStringLiteral("%1: cannot write: %2").arg(path_, file_.errorString()));
    writer_ = std::make_unique<QPdfWriter>(&file_);
    writer_->setPageSize(QPageSize(QPageSize::A4));
    writer_->setResolution(200);
    writer_->setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    writer_->setTitle(title);
    writer_->setCreator(QStringLiteral("Athlos"));
    if (!painter_.begin(writer_.get())) return makeError(QStringLiteral("%1: cannot write the PDF").arg(path_));
    painter_.setRenderHint(QPainter::Antialiasing);
    return {};
}

QRectF ReportDocument::area() const { return QRectF(0, 0, writer_->width(), writer_->height()); }

void ReportDocument::newPage() { writer_->newPage(); }

Status ReportDocument::finish() {
    if (!painter_.end()) return makeError(QStringLiteral("%1: cannot finish the PDF").arg(path_));
    if (!file_.commit()) return makeError(QStringLiteral("%1: cannot write: %2").arg(path_, file_.errorString()));
    return {};
}

}  // namespace athlos::ui

namespace athlos::ui::report {

QString number(double v, int decimals) {
    return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("–");
}

void heading(ReportPage& page, const QString& text, double points) {
    QFont font = page.painter.font();
    font.setPointSizeF(points);
    font.setBold(true);
    page.painter.setFont(font);
    const double h = page.lineHeight(font);
    page.painter.drawText(QRectF(page.area.left(), page.y, page.area.width(), h), Qt::AlignLeft, text);
    page.y += h * 1.3;
}

void text(ReportPage& page, const QString& text, double points, double lines, double advance) {
    QFont font = page.painter.font();
    font.setPointSizeF(points);
    font.setBold(false);
    page.painter.setFont(font);
    const double h = page.lineHeight(font);
    page.painter.drawText(QRectF(page.area.left(), page.y, page.area.width(), h * lines),
                          Qt::AlignLeft | Qt::TextWordWrap, text);
    page.y += h * advance;
}

namespace {
QFont tableFont(const QPainter& painter) {
    QFont font = painter.font();
    font.setPointSizeF(8.0);
    font.setBold(true);
    return font;
}
}  // namespace

double tableRowHeight(const ReportPage& page) { return page.lineHeight(tableFont(page.painter)) * 1.35; }

void drawTable(ReportPage& page, const QStringList& header, const QList<QStringList>& rows,
               const QList<double>& weights) {
    QFont font = tableFont(page.painter);
    const double h = tableRowHeight(page);
    double total = 0;
    for (double w : weights) total += w;
    auto drawRow = [&](const QStringList& cells, bool bold, bool shaded) {
        font.setBold(bold);
        page.painter.setFont(font);
        if (shaded)
            page.painter.fillRect(QRectF(page.area.left(), page.y, page.area.width(), h), QColor(240, 243, 247));
        double x = page.area.left();
        for (int c = 0; c < cells.size() && c < weights.size(); ++c) {
            const double w = page.area.width() * weights[c] / total;
            page.painter.drawText(QRectF(x + 4, page.y, w - 8, h),
                                  (c == 0 ? Qt::AlignLeft : Qt::AlignRight) | Qt::AlignVCenter, cells[c]);
            x += w;
        }
        page.y += h;
    };
    drawRow(header, true, false);
    page.painter.drawLine(QPointF(page.area.left(), page.y), QPointF(page.area.right(), page.y));
    for (int r = 0; r < rows.size(); ++r) drawRow(rows[r], false, r % 2 == 1);
    page.y += h * 0.6;
}

QCustomPlot* newPlot() {
    auto* plot = new QCustomPlot;
    PlotStyle::apply(plot);
    plot->legend->setVisible(false);
    plot->setAttribute(Qt::WA_DontShowOnScreen);
    return plot;
}

void drawPlot(QPainter& painter, QCustomPlot& plot, const QRectF& target) {
    const int w = 800, h = std::max(150, int(800 * target.height() / target.width()));
    plot.resize(w, h);
    plot.replot(QCustomPlot::rpImmediateRefresh);
    const QPixmap pixmap = plot.toPixmap(w, h, target.width() / w);
    painter.drawPixmap(target, pixmap, QRectF(pixmap.rect()));
}

}  // namespace athlos::ui::report
