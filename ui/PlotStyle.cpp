#include "ui/PlotStyle.h"

#include <QEvent>
#include <QPalette>
#include <qcustomplot.h>

#include <array>

namespace athlos::ui {

namespace {
// Re-styles its plot when the palette changes (system switches between light and dark).
class PaletteFollower : public QObject {
public:
    explicit PaletteFollower(QCustomPlot* plot) : QObject(plot), plot_(plot) { plot->installEventFilter(this); }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (watched == plot_ &&
            (event->type() == QEvent::PaletteChange || event->type() == QEvent::ApplicationPaletteChange)) {
            PlotStyle::applyPalette(plot_, plot_->palette());
            plot_->replot(QCustomPlot::rpQueuedReplot);
        }
        return QObject::eventFilter(watched, event);
    }

private:
    QCustomPlot* plot_;
};
}  // namespace

QColor PlotStyle::seriesColor(int index) {
    static const std::array<QColor, 10> palette = {
        QColor(0, 114, 178),  QColor(213, 94, 0), QColor(0, 158, 115), QColor(204, 121, 167), QColor(230, 159, 0),
        QColor(86, 180, 233), QColor(0, 0, 0),    QColor(140, 86, 75), QColor(127, 127, 127), QColor(188, 189, 34),
    };
    return palette[static_cast<std::size_t>(index) % palette.size()];
}

QString PlotStyle::unitSuffix(const QString& unit) {
    if (unit.isEmpty() || unit == QLatin1String("1")) return {};
    return QStringLiteral(" [%1]").arg(unit);
}

QString PlotStyle::columnLabel(const QString& name, const QString& unit) { return name + unitSuffix(unit); }

void PlotStyle::apply(QCustomPlot* plot) {
    // Antialiasing while dragging costs more than it is worth; the still image is smooth again.
    plot->setNoAntialiasingOnDrag(true);
    plot->setPlottingHint(QCP::phCacheLabels, true);
    plot->setPlottingHint(QCP::phFastPolylines, true);
    plot->legend->setVisible(true);
    QFont legendFont = plot->font();
    legendFont.setPointSizeF(legendFont.pointSizeF() * 0.9);
    plot->legend->setFont(legendFont);
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    for (QCPAxis* axis : {plot->xAxis, plot->yAxis}) axis->grid()->setSubGridVisible(false);
    applyPalette(plot, plot->palette());
    new PaletteFollower(plot);
}

void PlotStyle::applyPalette(QCustomPlot* plot, const QPalette& palette) {
    const QColor base = palette.color(QPalette::Base);
    const QColor text = palette.color(QPalette::Text);
    const bool dark = base.lightnessF() < 0.5;
    plot->setBackground(base);
    QColor legendBrush = base;
    legendBrush.setAlpha(210);
    // Every axis rect (stacked panels have several), each with its legend if it has one.
    for (QCPAxisRect* rect : plot->axisRects()) {
        for (int i = 0; i < rect->insetLayout()->elementCount(); ++i) {
            auto* legend = qobject_cast<QCPLegend*>(rect->insetLayout()->elementAt(i));
            if (!legend) continue;
            legend->setBrush(legendBrush);
            legend->setTextColor(text);
            legend->setBorderPen(QPen(dark ? base.lighter(250) : QColor(180, 180, 180)));
        }
        for (QCPAxis* axis : rect->axes()) {
            axis->setBasePen(QPen(text, 0));
            axis->setTickPen(QPen(text, 0));
            axis->setSubTickPen(QPen(text, 0));
            axis->setTickLabelColor(text);
            axis->setLabelColor(text);
            axis->grid()->setPen(QPen(dark ? base.lighter(220) : QColor(220, 220, 220), 0, Qt::DotLine));
        }
    }
}

}  // namespace athlos::ui
