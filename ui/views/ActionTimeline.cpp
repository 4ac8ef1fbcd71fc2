#include "ui/views/ActionTimeline.h"

#include "core/model/Project.h"
#include "ui/PlotStyle.h"
#include "ui/TimeController.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <map>

namespace athlos::ui {

namespace {
constexpr int kLaneHeight = 24;  // preferred; lanes grow to fill the widget up to kMaxLaneHeight
constexpr int kMaxLaneHeight = 44;
constexpr int kLaneGap = 4;
constexpr int kAxisHeight = 20;
constexpr int kMargin = 6;
constexpr int kLabelWidth = 210;

// A tick step of 1, 2 or 5 × 10^k giving about `target` ticks over span.
double niceStep(double span, int target) {
    const double raw = span / std::max(1, target);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * p >= raw) return m * p;
    return 10.0 * p;
}
}  // namespace

ActionTimeline::ActionTimeline(TimeController* time, QWidget* parent) : QWidget(parent), time_(time) {
    setMouseTracking(false);
    setAutoFillBackground(true);
    setBackgroundRole(QPalette::Base);
    if (time_) {
        connect(time_, &TimeController::cursorChanged, this, qOverload<>(&QWidget::update));
        connect(time_, &TimeController::visibleRangeChanged, this, qOverload<>(&QWidget::update));
    }
}

QColor ActionTimeline::colorFor(const Project* project, const QString& label) {
    // The same rule as the annotation layer on the time-series panel.
    const int index = project ? int(project->annotationClasses().indexOf(label)) : -1;
    return PlotStyle::seriesColor(index >= 0 ? index : 8 + int(qHash(label) % 8));
}

void ActionTimeline::setAnnotations(const Annotations& annotations, const Project* project) {
    annotations_ = annotations;
    if (highlighted_ >= int(annotations_.size())) highlighted_ = -1;
    rebuild(project);
    updateGeometry();
    update();
}

void ActionTimeline::rebuild(const Project* project) {
    std::map<QString, ClassStats> byLabel;
    std::map<QString, int> durations;
    for (const Annotation& a : annotations_) {
        ClassStats& s = byLabel[a.label];
        s.label = a.label;
        ++s.count;
        if (a.source != QLatin1String("manual")) ++s.predicted;
        s.meanConfidence += a.confidence;
        if (a.tEnd > a.tStart) {
            s.meanDuration += a.tEnd - a.tStart;
            ++durations[a.label];
        }
    }
    lanes_.clear();
    if (project)
        for (const QString& c : project->annotationClasses())
            if (byLabel.count(c)) lanes_ << c;
    for (const auto& [label, s] : byLabel)
        if (!lanes_.contains(label)) lanes_ << label;
    stats_.clear();
    colors_.clear();
    for (const QString& label : lanes_) {
        ClassStats s = byLabel[label];
        s.meanConfidence /= std::max(1, s.count);
        s.meanDuration = durations[label] ? s.meanDuration / durations[label] : 0.0;
        stats_.push_back(s);
        colors_.push_back(colorFor(project, label));
    }
}

void ActionTimeline::setHighlighted(int index) {
    highlighted_ = index;
    update();
}

const ActionTimeline::ClassStats* ActionTimeline::statsFor(const QString& label) const {
    for (const auto& s : stats_)
        if (s.label == label) return &s;
    return nullptr;
}

double ActionTimeline::visibleBegin() const { return time_ ? time_->visibleBegin() : 0.0; }
double ActionTimeline::visibleEnd() const { return time_ ? time_->visibleEnd() : 1.0; }

QRect ActionTimeline::timeArea() const {
    return QRect(kLabelWidth, kMargin, std::max(10, width() - kLabelWidth - kMargin),
                 height() - 2 * kMargin - kAxisHeight);
}

QRect ActionTimeline::laneRect(int lane) const {
    const QRect area = timeArea();
    const int lanes = std::max<int>(1, int(lanes_.size()));
    const int h = std::clamp((area.height() + kLaneGap) / lanes - kLaneGap, kLaneHeight, kMaxLaneHeight);
    return QRect(area.left(), area.top() + lane * (h + kLaneGap), area.width(), h);
}

int ActionTimeline::xAt(double t) const {
    const QRect area = timeArea();
    const double span = std::max(1e-9, visibleEnd() - visibleBegin());
    return area.left() + int(std::lround((t - visibleBegin()) / span * area.width()));
}

double ActionTimeline::timeAt(int x) const {
    const QRect area = timeArea();
    return visibleBegin() + double(x - area.left()) / std::max(1, area.width()) * (visibleEnd() - visibleBegin());
}

QSize ActionTimeline::sizeHint() const {
    const int lanes = std::max<int>(1, int(lanes_.size()));
    return {800, 2 * kMargin + kAxisHeight + lanes * (kLaneHeight + kLaneGap)};
}

QSize ActionTimeline::minimumSizeHint() const { return {kLabelWidth + 100, 2 * kMargin + kAxisHeight + kLaneHeight}; }

void ActionTimeline::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing, false);
    const QPalette& pal = palette();
    const QRect area = timeArea();
    const double t0 = visibleBegin(), t1 = visibleEnd();

    if (lanes_.isEmpty()) {
        p.setPen(pal.color(QPalette::PlaceholderText));
        p.drawText(rect(), Qt::AlignCenter,
                   tr("No annotations in this recording. Annotate on the time series "
                      "or run an event detector (e.g. gait-events)."));
    }
    // Lanes: label column with count and mean duration, then the bars.
    for (int lane = 0; lane < lanes_.size(); ++lane) {
        const QRect r = laneRect(lane);
        const ClassStats& s = stats_[std::size_t(lane)];
        p.fillRect(r, lane % 2 ? pal.color(QPalette::AlternateBase) : pal.color(QPalette::Base));
        QRect label(kMargin, r.top(), kLabelWidth - 2 * kMargin, r.height());
        p.fillRect(QRect(label.left(), r.center().y() - 5, 10, 10), colors_[std::size_t(lane)]);
        p.setPen(pal.color(QPalette::Text));
        QString text = tr("%1  %2").arg(s.label).arg(s.count);
        if (s.meanDuration > 0.0) text += tr(" · %1 s").arg(s.meanDuration, 0, 'f', 2);
        p.drawText(label.adjusted(14, 0, 0, 0), Qt::AlignVCenter | Qt::AlignLeft,
                   p.fontMetrics().elidedText(text, Qt::ElideMiddle, label.width() - 14));
    }
    p.save();
    p.setClipRect(area);
    for (std::size_t k = 0; k < annotations_.size(); ++k) {
        const Annotation& a = annotations_[k];
        if (a.tEnd < t0 || a.tStart > t1) continue;
        const int lane = int(lanes_.indexOf(a.label));
        if (lane < 0) continue;
        const QRect r = laneRect(lane).adjusted(0, 4, 0, -4);
        QColor color = colors_[std::size_t(lane)];
        const bool manual = a.source == QLatin1String("manual");
        const int x0 = xAt(a.tStart), x1 = std::max(xAt(a.tEnd), x0 + 1);
        if (a.tEnd <= a.tStart) {  // an instant: a tick with a small head
            p.setPen(QPen(color.darker(130), 2));
            p.drawLine(x0, r.top(), x0, r.bottom());
            continue;
        }
        // One pixel of gap on the right keeps back-to-back actions (strides) apart.
        const QRect bar(x0, r.top(), std::max(1, x1 - x0 - 1), r.height());
        if (manual) {
            p.fillRect(bar, color);
            p.setPen(QPen(color.darker(150), 1));
        } else {
            // Predicted: translucent by confidence, hatched, so it never looks like a checked label.
            const double c = std::clamp(a.confidence, 0.0, 1.0);
            QColor fill = color;
            fill.setAlphaF(0.15 + 0.55 * c);
            p.fillRect(bar, fill);
            p.fillRect(bar, QBrush(color.darker(160), Qt::BDiagPattern));
            p.setPen(QPen(color.darker(170), 1));
        }
        p.drawRect(bar.adjusted(0, 0, -1, -1));
        if (int(k) == highlighted_) {
            p.setPen(QPen(pal.color(QPalette::Highlight), 3));
            p.drawRect(bar.adjusted(-2, -2, 1, 1));
        }
    }
    p.restore();

    // Time axis.
    const int axisY = area.bottom() + 2;
    p.setPen(pal.color(QPalette::Mid));
    p.drawLine(area.left(), axisY, area.right(), axisY);
    if (t1 > t0) {
        const double step = niceStep(t1 - t0, std::max(2, area.width() / 90));
        p.setPen(pal.color(QPalette::Text));
        for (double t = std::ceil(t0 / step) * step; t <= t1 + 1e-9; t += step) {
            const int x = xAt(t);
            p.drawLine(x, axisY, x, axisY + 4);
            const QString label = QString::number(t, 'f', step < 1.0 ? (step < 0.1 ? 2 : 1) : 0) + tr(" s");
            p.drawText(QRect(x - 40, axisY + 4, 80, kAxisHeight - 4), Qt::AlignHCenter | Qt::AlignTop, label);
        }
    }
    // Cursor.
    if (time_) {
        const double c = time_->cursor();
        if (c >= t0 && c <= t1) {
            const int x = xAt(c);
            p.setPen(QPen(QColor(220, 30, 30), 2));
            p.drawLine(x, area.top(), x, axisY);
        }
    }
}

void ActionTimeline::mousePressEvent(QMouseEvent* event) {
    if (event->button() == Qt::LeftButton && time_ &&
        timeArea().adjusted(0, 0, 0, kAxisHeight).contains(event->position().toPoint())) {
        time_->setCursor(timeAt(event->position().toPoint().x()));
        event->accept();
        return;
    }
    QWidget::mousePressEvent(event);
}

void ActionTimeline::mouseMoveEvent(QMouseEvent* event) {
    // Dragging scrubs the cursor like on the time-series panels.
    if ((event->buttons() & Qt::LeftButton) && time_ &&
        timeArea().adjusted(0, 0, 0, kAxisHeight).contains(event->position().toPoint())) {
        time_->setCursor(timeAt(event->position().toPoint().x()));
        event->accept();
        return;
    }
    QWidget::mouseMoveEvent(event);
}

}  // namespace athlos::ui
