#include "ui/views/PlaybackCanvas.h"

#include <QMouseEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace athlos::ui {

namespace {

constexpr double kMaxGap = 1.0;      // s: samples further apart are a gap (no line, no interpolation)
constexpr double kTrailWidth = 3.0;  // px
constexpr double kDotRadius = 6.0;   // px
constexpr int kMargin = 16;          // px around the framed venue

QColor teamColor(const QString& team, int index) {
    if (team == QLatin1String("home")) return QColor(250, 250, 250);
    if (team == QLatin1String("away")) return QColor(25, 25, 25);
    static const QColor others[] = {QColor(230, 159, 0),  QColor(86, 180, 233), QColor(0, 158, 115),
                                    QColor(240, 228, 66), QColor(0, 114, 178),  QColor(213, 94, 0),
                                    QColor(204, 121, 167)};
    return others[index % 7];
}

}  // namespace

PlaybackCanvas::PlaybackCanvas(QWidget* parent) : QWidget(parent) {
    setAttribute(Qt::WA_OpaquePaintEvent);  // the venue covers every pixel
    setMouseTracking(false);
    setMinimumSize(200, 150);
    for (int b = 0; b < PlaybackTracks::kBins; ++b) {
        QPen pen(PlaybackTracks::binColor(b), kTrailWidth);
        pen.setCapStyle(Qt::RoundCap);
        binPens_[std::size_t(b)] = pen;
    }
}

void PlaybackCanvas::setTracks(std::shared_ptr<const std::vector<AthleteTrack>> tracks) {
    tracks_ = std::move(tracks);
    if (!userView_) framed_ = false;
    update();
}

const std::vector<AthleteTrack>& PlaybackCanvas::tracks() const {
    static const std::vector<AthleteTrack> none;
    return tracks_ ? *tracks_ : none;
}

void PlaybackCanvas::setVenue(VenueDrawing::Venue venue) {
    if (venue == venue_) return;
    venue_ = venue;
    if (!userView_) framed_ = false;
    update();
}

void PlaybackCanvas::setVenueSize(VenueDrawing::Size size) {
    if (size == venueSize_) return;
    venueSize_ = size;
    if (!userView_) framed_ = false;
    update();
}

void PlaybackCanvas::setTrailSeconds(double seconds) {
    trail_ = std::max(0.0, seconds);
    update();
}

void PlaybackCanvas::setTime(double t) {
    if (t == cursor_) return;
    cursor_ = t;
    update();
}

QTransform PlaybackCanvas::worldToScreen() const {
    // x' = w/2 + (x − cx)·s, y' = h/2 − (y − cy)·s
    return QTransform(scale_, 0, 0, -scale_, width() / 2.0 - centre_.x() * scale_,
                      height() / 2.0 + centre_.y() * scale_);
}

void PlaybackCanvas::frameAll() {
    QRectF region = VenueDrawing::bounds(venue_, venueSize_);
    const QRectF data = PlaybackTracks::extent(tracks());
    if (region.isEmpty()) region = data.isValid() ? data.adjusted(-2, -2, 2, 2) : QRectF(-50, -35, 100, 70);
    if (region.width() <= 0) region.adjust(-5, 0, 5, 0);
    if (region.height() <= 0) region.adjust(0, -5, 0, 5);
    const double w = std::max(1, width() - 2 * kMargin), h = std::max(1, height() - 2 * kMargin);
    scale_ = std::min(w / region.width(), h / region.height());
    centre_ = region.center();
    framed_ = true;
    userView_ = false;
    update();
}

void PlaybackCanvas::ensureFramed() {
    if (!framed_) frameAll();
}

void PlaybackCanvas::resizeEvent(QResizeEvent* event) {
    QWidget::resizeEvent(event);
    if (!userView_) framed_ = false;
}

void PlaybackCanvas::paintEvent(QPaintEvent*) {
    QPainter painter(this);
    paintFrame(painter);
}

void PlaybackCanvas::paintFrame(QPainter& painter) {
    ensureFramed();
    drawVenue(painter);
    const QTransform t = worldToScreen();
    painter.setRenderHint(QPainter::Antialiasing, true);
    drawTrails(painter, t);
    drawAthletes(painter, t);
    drawLegend(painter);
}

void PlaybackCanvas::drawVenue(QPainter& painter) {
    const qreal dpr = devicePixelRatioF();
    if (venuePixmap_.isNull() || cacheSize_ != size() || cacheCentre_ != centre_ || cacheScale_ != scale_ ||
        cacheVenue_ != venue_ || cacheVenueSize_ != venueSize_ || cacheDpr_ != dpr) {
        venuePixmap_ = QPixmap(size() * dpr);
        venuePixmap_.setDevicePixelRatio(dpr);
        QPainter p(&venuePixmap_);
        VenueDrawing::draw(p, worldToScreen(), venue_, QRectF(QPointF(0, 0), QSizeF(size())), venueSize_);
        cacheSize_ = size();
        cacheCentre_ = centre_;
        cacheScale_ = scale_;
        cacheVenue_ = venue_;
        cacheVenueSize_ = venueSize_;
        cacheDpr_ = dpr;
    }
    painter.drawPixmap(0, 0, venuePixmap_);
}

void PlaybackCanvas::drawTrails(QPainter& painter, const QTransform& t) {
    if (!tracks_ || trail_ <= 0) return;
    for (auto& bin : segments_) bin.clear();
    const double from = cursor_ - trail_;
    const double sx = t.m11(), sy = t.m22(), ox = t.dx(), oy = t.dy();
    for (const AthleteTrack& tr : *tracks_) {
        if (tr.t.empty() || tr.t.back() < from || tr.t.front() > cursor_) continue;
        const long last = tr.indexAt(cursor_);
        if (last < 0) continue;
        // The trail starts at the first sample at or after cursor − trail.
        const long first = long(std::lower_bound(tr.t.begin(), tr.t.end(), from) - tr.t.begin());
        if (first > last) continue;
        QPointF prev(ox + sx * tr.x[std::size_t(first)], oy + sy * tr.y[std::size_t(first)]);
        bool prevOk = std::isfinite(tr.x[std::size_t(first)]) && std::isfinite(tr.y[std::size_t(first)]);
        for (long k = first + 1; k <= last; ++k) {
            const std::size_t i = std::size_t(k);
            const bool ok = std::isfinite(tr.x[i]) && std::isfinite(tr.y[i]);
            const QPointF p(ox + sx * tr.x[i], oy + sy * tr.y[i]);
            const bool joined = ok && prevOk && tr.t[i] - tr.t[i - 1] <= kMaxGap;
            // Pieces shorter than 2 px are merged into the next one (long trails, zoomed out): the
            // cost stays with what can be seen.
            if (joined && k < last && (p - prev).manhattanLength() < 2.0) continue;
            if (joined) segments_[tr.bin[i]].emplace_back(prev, p);
            prev = p;
            prevOk = ok;
        }
        // The last piece up to the interpolated current position.
        float cx, cy;
        if (prevOk && tr.positionAt(cursor_, kMaxGap, cx, cy) && std::size_t(last) + 1 < tr.t.size())
            segments_[tr.bin[std::size_t(last) + 1]].emplace_back(prev, QPointF(ox + sx * cx, oy + sy * cy));
    }
    for (int b = 0; b < PlaybackTracks::kBins; ++b) {
        const auto& lines = segments_[std::size_t(b)];
        if (lines.empty()) continue;
        painter.setPen(binPens_[std::size_t(b)]);
        painter.drawLines(lines.data(), int(lines.size()));
    }
}

void PlaybackCanvas::drawAthletes(QPainter& painter, const QTransform& t) {
    if (!tracks_) return;
    QFont font = painter.font();
    font.setPixelSize(11);
    font.setBold(true);
    painter.setFont(font);
    int index = 0;
    for (const AthleteTrack& tr : *tracks_) {
        float x, y;
        const int i = index++;
        if (!tr.positionAt(cursor_, kMaxGap, x, y)) continue;
        const QPointF p = t.map(QPointF(x, y));
        const QColor fill = teamColor(tr.team, i);
        painter.setPen(QPen(fill.lightness() > 128 ? QColor(30, 30, 30) : QColor(240, 240, 240), 1.5));
        painter.setBrush(fill);
        painter.drawEllipse(p, kDotRadius, kDotRadius);
        // Label up-right of the dot with a dark outline so it reads on grass, track and white.
        const QPointF at = p + QPointF(kDotRadius + 2, -kDotRadius - 1);
        painter.setPen(QColor(0, 0, 0, 170));
        painter.drawText(at + QPointF(1, 1), tr.label);
        painter.setPen(QColor(255, 255, 255));
        painter.drawText(at, tr.label);
    }
}

void PlaybackCanvas::drawLegend(QPainter& painter) {
    // Speed scale bottom-right: a bar of the colour bins with ticks every 3 m/s.
    const int barW = 180, barH = 10;
    const QRect box(width() - barW - 24, height() - 46, barW + 16, 40);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 215));
    painter.drawRect(box);
    const int x0 = box.left() + 8, y0 = box.top() + 6;
    for (int b = 0; b < PlaybackTracks::kBins; ++b) {
        const int xa = x0 + b * barW / PlaybackTracks::kBins, xb = x0 + (b + 1) * barW / PlaybackTracks::kBins;
        painter.fillRect(QRect(xa, y0, xb - xa, barH), PlaybackTracks::binColor(b));
    }
    QFont font = painter.font();
    font.setPixelSize(10);
    font.setBold(false);
    painter.setFont(font);
    painter.setPen(QColor(40, 40, 40));
    for (int v = 0; v <= int(PlaybackTracks::kSpeedMax); v += 3) {
        const int x = x0 + int(std::lround(v / PlaybackTracks::kSpeedMax * barW));
        painter.drawLine(x, y0 + barH, x, y0 + barH + 3);
        painter.drawText(QRect(x - 20, y0 + barH + 3, 40, 12), Qt::AlignHCenter | Qt::AlignTop, QString::number(v));
    }
    painter.drawText(QRect(x0, y0 + barH + 14, barW, 12), Qt::AlignHCenter, tr("speed [m/s]"));

    // Match time top-left.
    const int minutes = int(std::floor(cursor_ / 60.0));
    const double seconds = cursor_ - 60.0 * minutes;
    const QString time =
        QStringLiteral("%1:%2").arg(minutes, 2, 10, QLatin1Char('0')).arg(seconds, 4, 'f', 1, QLatin1Char('0'));
    font.setPixelSize(14);
    font.setBold(true);
    painter.setFont(font);
    const QRect timeBox(8, 8, 92, 24);
    painter.setPen(Qt::NoPen);
    painter.setBrush(QColor(255, 255, 255, 215));
    painter.drawRect(timeBox);
    painter.setPen(QColor(20, 20, 20));
    painter.drawText(timeBox, Qt::AlignCenter, time);
}

void PlaybackCanvas::wheelEvent(QWheelEvent* event) {
    const double steps = event->angleDelta().y() / 120.0;
    if (steps == 0) return;
    const QPointF mouse = event->position();
    const QPointF before = worldToScreen().inverted().map(mouse);
    scale_ = std::clamp(scale_ * std::pow(1.2, steps), 0.05, 500.0);
    // Keep the world point under the mouse where it was.
    const QPointF after = worldToScreen().inverted().map(mouse);
    centre_ += before - after;
    userView_ = true;
    update();
    event->accept();
}

void PlaybackCanvas::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return QWidget::mousePressEvent(event);
    dragging_ = true;
    dragFrom_ = event->position().toPoint();
    setCursor(Qt::ClosedHandCursor);
}

void PlaybackCanvas::mouseMoveEvent(QMouseEvent* event) {
    if (!dragging_) return QWidget::mouseMoveEvent(event);
    const QPoint now = event->position().toPoint();
    const QPoint d = now - dragFrom_;
    dragFrom_ = now;
    centre_ -= QPointF(d.x() / scale_, -d.y() / scale_);
    userView_ = true;
    update();
}

void PlaybackCanvas::mouseReleaseEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) return QWidget::mouseReleaseEvent(event);
    dragging_ = false;
    unsetCursor();
}

void PlaybackCanvas::mouseDoubleClickEvent(QMouseEvent*) { frameAll(); }

}  // namespace athlos::ui
