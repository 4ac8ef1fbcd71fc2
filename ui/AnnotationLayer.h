#pragma once
// Annotations of one recording drawn over a time-series panel as coloured spans (one colour per
// class), and the mouse work on them: in annotate mode (or with Shift) a drag creates an interval
// of the current class, dragging a span's edge moves it, a click selects, Delete removes.
// Every change goes through the AnnotationEditor (undo, journal).
#include <QObject>
#include <QPointer>
#include <QString>
#include <vector>

class QCPItemRect;
class QCPItemText;
class QCustomPlot;
class QMouseEvent;

namespace athlos::ui {

class AnnotationEditor;
class TimeSeriesPanel;

class AnnotationLayer : public QObject {
    Q_OBJECT

public:
    AnnotationLayer(TimeSeriesPanel* panel, AnnotationEditor* editor);

    void setRecording(const QString& recording);
    QString recording() const { return recording_; }
    // Without annotate mode a plain drag pans; Shift+drag annotates either way.
    void setAnnotateMode(bool on) { annotateMode_ = on; }
    bool annotateMode() const { return annotateMode_; }

    int selected() const { return selected_; }
    void setSelected(int index);
    int spanCount() const { return int(spans_.size()); }
    QCPItemRect* span(int index) const { return spans_.at(std::size_t(index)).rect; }
    // The span's shades in the other lanes of a stacked panel (lane 1, 2, ...).
    const std::vector<QCPItemRect*>& shades(int index) const { return spans_.at(std::size_t(index)).shades; }

public slots:
    void rebuild();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct Span {
        QCPItemRect* rect = nullptr;  // in the top lane (the plot's main axis rect), with the label
        QCPItemText* label = nullptr;
        std::vector<QCPItemRect*> shades;  // the same interval in the other stacked lanes
    };
    bool inAnyLane(const QPoint& pos) const;
    enum class Drag { None, Create, MoveStart, MoveEnd };

    void onPress(QMouseEvent* event);
    void onMove(QMouseEvent* event);
    void onRelease(QMouseEvent* event);
    int spanAt(double x, Drag* edge) const;
    void clearSpans();
    QCustomPlot* plot() const;

    QPointer<TimeSeriesPanel> panel_;
    AnnotationEditor* editor_ = nullptr;
    QString recording_;
    std::vector<Span> spans_;
    QCPItemRect* preview_ = nullptr;
    bool annotateMode_ = false;
    int selected_ = -1;
    Drag drag_ = Drag::None;
    int dragIndex_ = -1;
    double dragOrigin_ = 0;
    bool savedRangeDrag_ = false;
};

}  // namespace athlos::ui
