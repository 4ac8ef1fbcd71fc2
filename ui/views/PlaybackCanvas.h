#pragma once
// The drawing surface of the playback view, painted with QPainter only (no plot library: a frame
// must take milliseconds): the venue from a pixmap cached per size and view, then per athlete the
// trail of the last N seconds coloured by speed (segments grouped by colour bin, one drawLines per
// bin), the current position as a dot in the team colour with its label, the speed colour scale
// and the time. World → screen has equal metres per pixel on both axes, y up; the wheel zooms
// about the mouse, dragging pans, a double-click frames the venue again.
#include "ui/venue/VenueDrawing.h"
#include "ui/views/PlaybackTracks.h"

#include <QLineF>
#include <QPen>
#include <QPixmap>
#include <QPointF>
#include <QTransform>
#include <QWidget>
#include <array>
#include <memory>
#include <vector>

namespace athlos::ui {

class PlaybackCanvas : public QWidget {
    Q_OBJECT

public:
    explicit PlaybackCanvas(QWidget* parent = nullptr);

    void setTracks(std::shared_ptr<const std::vector<AthleteTrack>> tracks);
    const std::vector<AthleteTrack>& tracks() const;
    void setVenue(VenueDrawing::Venue venue);
    VenueDrawing::Venue venue() const { return venue_; }
    // The real size of the pitch (a surveyed one); {} = the venue's standard size.
    void setVenueSize(VenueDrawing::Size size);
    VenueDrawing::Size venueSize() const { return venueSize_; }
    void setTrailSeconds(double seconds);
    double trailSeconds() const { return trail_; }
    double time() const { return cursor_; }

    // World (m) → widget pixels.
    QTransform worldToScreen() const;
    QPointF toScreen(double x, double y) const { return worldToScreen().map(QPointF(x, y)); }
    // Frames the venue (or the data when there is none) in the widget.
    void frameAll();
    double pixelsPerMetre() const { return scale_; }

    // What paintEvent draws, into any painter of the widget's size (benchmarks, tests).
    void paintFrame(QPainter& painter);

public slots:
    void setTime(double t);

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void mouseDoubleClickEvent(QMouseEvent* event) override;

private:
    void ensureFramed();
    void drawVenue(QPainter& painter);
    void drawTrails(QPainter& painter, const QTransform& t);
    void drawAthletes(QPainter& painter, const QTransform& t);
    void drawLegend(QPainter& painter);

    std::shared_ptr<const std::vector<AthleteTrack>> tracks_;
    VenueDrawing::Venue venue_ = VenueDrawing::Venue::None;
    VenueDrawing::Size venueSize_;
    double trail_ = 10.0;
    double cursor_ = 0.0;
    // View: world point at the widget centre and pixels per metre; framed until the user zooms/pans.
    QPointF centre_;
    double scale_ = 5.0;
    bool framed_ = false;
    bool userView_ = false;
    QPoint dragFrom_;
    bool dragging_ = false;
    // Venue cache and its key.
    QPixmap venuePixmap_;
    QSize cacheSize_;
    QPointF cacheCentre_;
    double cacheScale_ = 0.0;
    VenueDrawing::Venue cacheVenue_ = VenueDrawing::Venue::None;
    VenueDrawing::Size cacheVenueSize_;
    qreal cacheDpr_ = 0.0;
    // Per-bin segment buffers, kept between frames to avoid allocations.
    std::array<std::vector<QLineF>, PlaybackTracks::kBins> segments_;
    std::array<QPen, PlaybackTracks::kBins> binPens_;
};

}  // namespace athlos::ui
