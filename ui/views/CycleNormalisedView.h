#pragma once
// Cycle-normalised curves (issue #18 item 4, Fasel 2017 §11.4): a signal of a recording cut at its
// annotations of one label (e.g. "xc cycle" from xc-skiing-cycles, "stride left" from gait-events)
// and resampled to 0–100 % of each cycle, drawn as mean ± SD band. "Double turn" cuts from each
// "turn left" (alpine-turns) to the end of the "turn right" that follows: 0–100 % left, 100–200 %
// right.
#include "core/model/Annotation.h"
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <QWidget>
#include <utility>
#include <vector>

class QComboBox;
class QCustomPlot;
class QLabel;

namespace athlos {
class Project;
}

namespace athlos::ui {

struct NormalisedCurves {
    std::vector<double> percent, mean, sd;
    int cycles = 0;
};

class CycleNormalisedView : public QWidget {
    Q_OBJECT

public:
    static constexpr const char* kDoubleTurn = "double turn (left + right)";

    explicit CycleNormalisedView(const Project* project, QWidget* parent = nullptr);

    // Resamples v(t) linearly at `points` instants of each [start, end] and returns mean ± SD per
    // instant over the cycles fully inside t (`span` percent for the whole cycle: 100 or 200).
    static NormalisedCurves normalise(const std::vector<double>& t, const std::vector<double>& v,
                                      const std::vector<std::pair<double, double>>& cycles, int points, double span);
    // Intervals of `label`, or for kDoubleTurn each "turn left" joined to the "turn right" starting where it ends.
    static std::vector<std::pair<double, double>> cyclesOf(const Annotations& annotations, const QString& label);
    // Labels with at least two intervals, plus kDoubleTurn when both turn labels are there.
    static QStringList cycleLabels(const Annotations& annotations);

    Status show(const QString& recording, const QString& stream, const QString& column, const QString& label);
    QCustomPlot* plot() const { return plot_; }
    const NormalisedCurves& curves() const { return curves_; }

private:
    void fillRecordings();
    void fillChoices();
    void refresh();

    const Project* project_;
    QComboBox* recording_ = nullptr;
    QComboBox* stream_ = nullptr;
    QComboBox* column_ = nullptr;
    QComboBox* label_ = nullptr;
    QLabel* note_ = nullptr;
    QCustomPlot* plot_ = nullptr;
    NormalisedCurves curves_;
    bool filling_ = false;
};

}  // namespace athlos::ui
