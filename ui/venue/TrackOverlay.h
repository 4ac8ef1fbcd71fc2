#pragma once
// Draws a track (kerb, lane lines, lane-1 running line) into a QCustomPlot in LPS coordinates,
// sampled from TrackGeometry itself so that what the user aligns by eye is exactly the geometry
// the filter's track models use.
#include "core/geometry/TrackGeometry.h"

#include <QList>
#include <QVector>
#include <QPointF>

class QCPCurve;
class QCustomPlot;

namespace athlos::ui {

class TrackOverlay {
public:
    explicit TrackOverlay(QCustomPlot* plot);
    ~TrackOverlay();
    TrackOverlay(const TrackOverlay&) = delete;
    TrackOverlay& operator=(const TrackOverlay&) = delete;

    // Replaces the drawn track (does not replot).
    void setTrack(const TrackGeometry& track);
    void clear();

    // Points of the line at lateral offset d (m) from the reference line, in LPS coordinates.
    static QVector<QPointF> line(const TrackGeometry& track, double offset, int samples = 720);

    // Curves in drawing order: kerb, lane lines 1..lanes (outer edges), lane-1 running line.
    const QList<QCPCurve*>& curves() const { return curves_; }
    QCPCurve* kerbCurve() const { return curves_.isEmpty() ? nullptr : curves_.front(); }
    QCPCurve* laneOneRunningLine() const { return curves_.isEmpty() ? nullptr : curves_.back(); }

private:
    QCPCurve* addLine(const TrackGeometry& track, double offset, const QPen& pen, const QString& name);

    QCustomPlot* plot_;
    QList<QCPCurve*> curves_;
};

}  // namespace athlos::ui
