#include "ui/PlotStyle.h"

#include <qcustomplot.h>

#include <array>

namespace athlos::ui {

QColor PlotStyle::seriesColor(int index)
{
    static const std::array<QColor, 10> palette = {
        QColor(0, 114, 178),   QColor(213, 94, 0),    QColor(0, 158, 115),  QColor(204, 121, 167),
        QColor(230, 159, 0),   QColor(86, 180, 233),  QColor(0, 0, 0),      QColor(140, 86, 75),
        QColor(127, 127, 127), QColor(188, 189, 34),
    };
    return palette[static_cast<std::size_t>(index) % palette.size()];
}

QString PlotStyle::unitSuffix(const QString& unit)
{
    if (unit.isEmpty() || unit == QLatin1String("1")) return {};
    return QStringLiteral(" [%1]").arg(unit);
}

QString PlotStyle::columnLabel(const QString& name, const QString& unit)
{
    return name + unitSuffix(unit);
}

void PlotStyle::apply(QCustomPlot* plot)
{
    plot->setBackground(Qt::white);
    // Antialiasing while dragging costs more than it is worth; the still image is smooth again.
    plot->setNoAntialiasingOnDrag(true);
    plot->setPlottingHint(QCP::phCacheLabels, true);
    plot->setPlottingHint(QCP::phFastPolylines, true);
    plot->legend->setVisible(true);
    QFont legendFont = plot->font();
    legendFont.setPointSizeF(legendFont.pointSizeF() * 0.9);
    plot->legend->setFont(legendFont);
    plot->legend->setBrush(QColor(255, 255, 255, 210));
    plot->legend->setBorderPen(QPen(QColor(180, 180, 180)));
    plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignRight);
    for (QCPAxis* axis : {plot->xAxis, plot->yAxis}) {
        axis->grid()->setSubGridVisible(false);
        axis->grid()->setPen(QPen(QColor(220, 220, 220), 0, Qt::DotLine));
    }
}

}  // namespace athlos::ui
