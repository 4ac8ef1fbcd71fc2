#include "ui/venue/TrackOverlay.h"

#include <qcustomplot.h>

namespace athlos::ui {

TrackOverlay::TrackOverlay(QCustomPlot* plot) : plot_(plot) {}

TrackOverlay::~TrackOverlay() = default;  // the plot owns the curves

QVector<QPointF> TrackOverlay::line(const TrackGeometry& track, double offset, int samples) {
    const double length = track.referenceLength();
    const bool closed = track.kind() == TrackGeometry::Kind::Oval || track.polylineParams().closed;
    QVector<QPointF> points;
    points.reserve(samples + 1);
    // A closed line repeats its first point so that the curve closes visually.
    const int last = closed ? samples : samples - 1;
    for (int i = 0; i <= last; ++i) {
        const double s = length * double(i) / double(closed ? samples : samples - 1);
        const Eigen::Vector2d p = track.pointAt(closed && i == samples ? 0.0 : s, offset).position;
        points.append(QPointF(p.x(), p.y()));
    }
    return points;
}

void TrackOverlay::clear() {
    for (QCPCurve* curve : std::as_const(curves_)) plot_->removePlottable(curve);
    curves_.clear();
}

void TrackOverlay::setTrack(const TrackGeometry& track) {
    clear();
    const bool oval = track.kind() == TrackGeometry::Kind::Oval;
    const double width = oval ? track.ovalParams().laneWidth : track.polylineParams().laneWidth;
    const int lanes = oval ? track.ovalParams().lanes : track.polylineParams().lanes;
    addLine(track, 0.0, QPen(QColor(90, 90, 90), 1.6), QStringLiteral("kerb"));
    for (int lane = 1; lane <= lanes; ++lane)
        addLine(track, lane * width, QPen(QColor(150, 150, 150), 0.8), QStringLiteral("lane line %1").arg(lane));
    QPen running(QColor(0, 114, 178), 1.0, Qt::DashLine);
    addLine(track, track.laneOffset(1), running, QStringLiteral("lane 1 running line"));
}

QCPCurve* TrackOverlay::addLine(const TrackGeometry& track, double offset, const QPen& pen, const QString& name) {
    const QVector<QPointF> points = line(track, offset);
    QVector<double> x, y;
    x.reserve(points.size());
    y.reserve(points.size());
    for (const QPointF& p : points) {
        x.append(p.x());
        y.append(p.y());
    }
    auto* curve = new QCPCurve(plot_->xAxis, plot_->yAxis);
    curve->setData(x, y);
    curve->setPen(pen);
    curve->setName(name);
    curve->removeFromLegend();
    curve->setSelectable(QCP::stNone);
    curves_.append(curve);
    return curve;
}

}  // namespace athlos::ui
