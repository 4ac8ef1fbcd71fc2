#pragma once
// Export of a plot panel as PNG (at the screen's device pixel ratio, so high-DPI exports stay
// sharp), SVG (QSvgGenerator) or PDF (QCustomPlot::savePdf), chosen by the file suffix. The last
// folder, format and size are remembered (QSettings).
#include "core/util/Expected.h"

#include <QCoreApplication>
#include <QSize>
#include <QString>

class QCustomPlot;
class QWidget;

namespace athlos::ui {

class PlotExporter {
    Q_DECLARE_TR_FUNCTIONS(athlos::ui::PlotExporter)

public:
    // size empty: the plot's current size. scale 0: the plot's device pixel ratio (PNG only).
    static Status exportPlot(QCustomPlot* plot, const QString& path, QSize size = {}, double scale = 0);
    // File dialog, then export; errors are shown. Returns the written path or empty.
    static QString exportDialog(QCustomPlot* plot, QWidget* parent);
};

}  // namespace athlos::ui
