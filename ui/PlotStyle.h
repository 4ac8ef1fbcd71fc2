#pragma once
// The look shared by all plot panels, so that time series and trajectories read as one app.
#include <QColor>
#include <QString>

class QCustomPlot;
class QPalette;

namespace athlos::ui {

class PlotStyle {
public:
    // Colour for series index i: a palette that stays distinguishable for colour-blind users
    // (Okabe–Ito order, then Tableau), cycling after that.
    static QColor seriesColor(int index);
    // "acc_x [m/s^2]"; dimensionless ("1") and unit-less columns show just the name.
    static QString columnLabel(const QString& name, const QString& unit);
    static QString unitSuffix(const QString& unit);
    // Fonts, legend and interaction defaults for a fresh plot.
    static void apply(QCustomPlot* plot);
    // Background, text, axes and grid from the palette (light or dark system theme); apply()
    // uses the plot's palette, panels call this again on a palette change.
    static void applyPalette(QCustomPlot* plot, const QPalette& palette);
};

}  // namespace athlos::ui
