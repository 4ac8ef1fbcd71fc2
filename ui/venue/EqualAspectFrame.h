#pragma once
// Keeps a map-like QCustomPlot (metres on both axes) at equal metres per pixel while framing a
// region: the ranges are recomputed from the frame after every layout pass (afterLayout), so the
// aspect stays right however the widget is resized, including plots laid out only when shown
// (wizard pages). Once the user drags or zooms, the user's view wins.
#include <QObject>
#include <QRectF>

class QCustomPlot;

namespace athlos::ui {

class EqualAspectFrame : public QObject {
    Q_OBJECT

public:
    explicit EqualAspectFrame(QCustomPlot* plot);

    // Frames everything plotted, with a relative margin on each side.
    void frameAll(double margin = 0.05);
    void frameTo(const QRectF& region);
    bool isFraming() const { return framing_; }

private:
    void fit();

    QCustomPlot* plot_;
    QRectF frame_;
    bool framing_ = true;  // until the user takes over
};

}  // namespace athlos::ui
