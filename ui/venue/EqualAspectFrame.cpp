#include "ui/venue/EqualAspectFrame.h"

#include <qcustomplot.h>
#include <algorithm>

namespace athlos::ui {

EqualAspectFrame::EqualAspectFrame(QCustomPlot* plot) : QObject(plot), plot_(plot) {
    connect(plot_, &QCustomPlot::afterLayout, this, &EqualAspectFrame::fit);
    connect(plot_, &QCustomPlot::mousePress, this, [this] { framing_ = false; });
    connect(plot_, &QCustomPlot::mouseWheel, this, [this] { framing_ = false; });
    connect(plot_, &QCustomPlot::mouseDoubleClick, this, [this] { frameAll(); });
}

void EqualAspectFrame::frameAll(double margin) {
    plot_->rescaleAxes();
    const QCPRange x = plot_->xAxis->range(), y = plot_->yAxis->range();
    const double mx = std::max(margin * x.size(), 1.0), my = std::max(margin * y.size(), 1.0);
    frameTo(QRectF(QPointF(x.lower - mx, y.lower - my), QPointF(x.upper + mx, y.upper + my)));
}

void EqualAspectFrame::frameTo(const QRectF& region) {
    frame_ = region.normalized();
    framing_ = true;
    plot_->xAxis->setRange(frame_.left(), frame_.right());
    plot_->yAxis->setRange(frame_.top(), frame_.bottom());
    plot_->replot();
}

void EqualAspectFrame::fit() {
    const QRect rect = plot_->axisRect()->rect();
    if (rect.width() <= 0 || rect.height() <= 0) return;
    if (!framing_) {
        // User's view: keep its centre and x scale, only restore the aspect.
        plot_->yAxis->setScaleRatio(plot_->xAxis, 1.0);
        return;
    }
    if (frame_.isEmpty()) return;
    // Widen whichever axis has fewer metres per pixel, around the frame's centre.
    const double perPixel = std::max(frame_.width() / rect.width(), frame_.height() / rect.height());
    const QPointF c = frame_.center();
    plot_->xAxis->setRange(c.x() - 0.5 * perPixel * rect.width(), c.x() + 0.5 * perPixel * rect.width());
    plot_->yAxis->setRange(c.y() - 0.5 * perPixel * rect.height(), c.y() + 0.5 * perPixel * rect.height());
}

}  // namespace athlos::ui
