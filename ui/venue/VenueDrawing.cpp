#include "ui/venue/VenueDrawing.h"

#include "core/geometry/TrackGeometry.h"
#include "ui/venue/TrackOverlay.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>
#include <QPolygonF>
#include <cmath>
#include <numbers>

namespace athlos::ui {

namespace {

constexpr double kPi = std::numbers::pi;
const QColor kGrass(76, 141, 72), kGrassStripe(84, 152, 79), kSurround(66, 124, 63), kLine(245, 245, 245);

// Points of a circular arc (world, angles in rad counter-clockwise from +x).
QPolygonF arc(QPointF centre, double r, double a0, double a1, int segments = 48) {
    QPolygonF p;
    for (int i = 0; i <= segments; ++i) {
        const double a = a0 + (a1 - a0) * double(i) / segments;
        p << QPointF(centre.x() + r * std::cos(a), centre.y() + r * std::sin(a));
    }
    return p;
}

QPolygonF rect(double x0, double y0, double x1, double y1) {
    return QPolygonF({QPointF(x0, y0), QPointF(x1, y0), QPointF(x1, y1), QPointF(x0, y1), QPointF(x0, y0)});
}

class Pen {
public:
    Pen(QPainter& painter, const QTransform& t) : p_(painter), t_(t) {}
    void line(double x0, double y0, double x1, double y1) { p_.drawLine(t_.map(QLineF(x0, y0, x1, y1))); }
    void poly(const QPolygonF& world) { p_.drawPolyline(t_.map(world)); }
    // A spot of radius r (m), at least 1.5 px so it stays visible zoomed out.
    void spot(double x, double y, double r) {
        const double px = std::max(1.5, r * t_.m11());
        p_.save();
        p_.setBrush(p_.pen().color());
        p_.setPen(Qt::NoPen);
        p_.drawEllipse(t_.map(QPointF(x, y)), px, px);
        p_.restore();
    }
    void fill(const QPolygonF& world, const QColor& color) { p_.fillPath(path(world), color); }
    static QPainterPath pathOf(const QPolygonF& screen) {
        QPainterPath path;
        path.addPolygon(screen);
        path.closeSubpath();
        return path;
    }
    QPainterPath path(const QPolygonF& world) const { return pathOf(t_.map(world)); }

private:
    QPainter& p_;
    const QTransform& t_;
};

QPen linePen(double pixelsPerMetre, double metres = 0.12) {
    QPen pen(kLine, std::clamp(metres * pixelsPerMetre, 1.0, 4.0));
    pen.setCapStyle(Qt::FlatCap);
    pen.setJoinStyle(Qt::MiterJoin);
    return pen;
}

// Mowing stripes across the length, as on most stadium pitches.
void grass(Pen& pen, double halfLength, double halfWidth, int stripes) {
    pen.fill(rect(-halfLength, -halfWidth, halfLength, halfWidth), kGrass);
    const double w = 2.0 * halfLength / stripes;
    for (int i = 1; i < stripes; i += 2)
        pen.fill(rect(-halfLength + i * w, -halfWidth, -halfLength + (i + 1) * w, halfWidth), kGrassStripe);
}

void drawFootball(QPainter& painter, const QTransform& t, VenueDrawing::Size size) {
    using V = VenueDrawing;
    Pen pen(painter, t);
    const double hl = size.length / 2, hw = size.width / 2;
    grass(pen, hl, hw, 18);
    painter.setPen(linePen(t.m11()));
    painter.setBrush(Qt::NoBrush);
    pen.poly(rect(-hl, -hw, hl, hw));
    pen.line(0, -hw, 0, hw);
    pen.poly(arc({0, 0}, V::kCentreCircle, 0, 2 * kPi, 96));
    pen.spot(0, 0, 0.22);
    for (const double s : {-1.0, 1.0}) {
        const double goalLine = s * hl;
        const double box = goalLine - s * V::kPenaltyDepth, six = goalLine - s * V::kGoalAreaDepth;
        pen.poly(QPolygonF({QPointF(goalLine, -V::kPenaltyWidth / 2), QPointF(box, -V::kPenaltyWidth / 2),
                            QPointF(box, V::kPenaltyWidth / 2), QPointF(goalLine, V::kPenaltyWidth / 2)}));
        pen.poly(QPolygonF({QPointF(goalLine, -V::kGoalAreaWidth / 2), QPointF(six, -V::kGoalAreaWidth / 2),
                            QPointF(six, V::kGoalAreaWidth / 2), QPointF(goalLine, V::kGoalAreaWidth / 2)}));
        const double spot = goalLine - s * V::kPenaltySpot;
        pen.spot(spot, 0, 0.22);
        // The penalty arc: the part of the 9.15 m circle round the spot outside the penalty area.
        const double half = std::acos((V::kPenaltyDepth - V::kPenaltySpot) / V::kCentreCircle);
        const double towardsCentre = s > 0 ? kPi : 0.0;
        pen.poly(arc({spot, 0}, V::kCentreCircle, towardsCentre - half, towardsCentre + half, 32));
        // The goal behind the line.
        pen.poly(QPolygonF(
            {QPointF(goalLine, -V::kGoalWidth / 2), QPointF(goalLine + s * V::kGoalDepth, -V::kGoalWidth / 2),
             QPointF(goalLine + s * V::kGoalDepth, V::kGoalWidth / 2), QPointF(goalLine, V::kGoalWidth / 2)}));
        // Corner arcs, a quarter circle inside the field at each corner.
        for (const double u : {-1.0, 1.0}) {
            const double a0 = std::atan2(-u, -s);  // pointing into the field from the corner
            pen.poly(arc({goalLine, u * hw}, V::kCornerArc, a0 - kPi / 4, a0 + kPi / 4, 12));
        }
    }
}

void drawRugby(QPainter& painter, const QTransform& t, VenueDrawing::Size size) {
    using V = VenueDrawing;
    Pen pen(painter, t);
    const double hl = size.length / 2, hw = size.width / 2, dead = hl + V::kRugbyInGoal;
    grass(pen, dead, hw, 12);
    QPen solid = linePen(t.m11());
    QPen dashed = solid;
    dashed.setDashPattern({4.0, 4.0});
    painter.setBrush(Qt::NoBrush);
    painter.setPen(solid);
    pen.poly(rect(-dead, -hw, dead, hw));  // touch-in-goal and dead-ball lines
    pen.line(0, -hw, 0, hw);               // halfway
    for (const double s : {-1.0, 1.0}) {
        painter.setPen(solid);
        pen.line(s * hl, -hw, s * hl, hw);                    // try line
        pen.line(s * (hl - 22.0), -hw, s * (hl - 22.0), hw);  // 22 m line
        painter.setPen(dashed);
        pen.line(s * 10.0, -hw, s * 10.0, hw);                          // 10 m line
        pen.line(s * (hl - 5.0), -hw + 5.0, s * (hl - 5.0), hw - 5.0);  // 5 m from the try line
        // 5 m and 15 m lines parallel to the touch lines, between the 5 m lines of both ends.
        for (const double d : {5.0, 15.0}) pen.line(-(hl - 5.0), s * (hw - d), hl - 5.0, s * (hw - d));
        // Goal posts 5.6 m apart on the try line.
        painter.setPen(solid);
        for (const double u : {-2.8, 2.8}) pen.spot(s * hl, u, 0.25);
    }
}

// A surveyed rectangle without markings: its outline, the halfway line and the centre spot.
void drawRectangle(QPainter& painter, const QTransform& t, VenueDrawing::Size size) {
    Pen pen(painter, t);
    const double hl = size.length / 2, hw = size.width / 2;
    grass(pen, hl, hw, std::max(2, int(std::lround(size.length / 6.0))));
    painter.setPen(linePen(t.m11()));
    painter.setBrush(Qt::NoBrush);
    pen.poly(rect(-hl, -hw, hl, hw));
    pen.line(0, -hw, 0, hw);
    pen.spot(0, 0, 0.22);
}

void drawTrack(QPainter& painter, const QTransform& t) {
    const TrackGeometry track = TrackGeometry::iaaf400m();
    const auto& oval = track.ovalParams();
    Pen pen(painter, t);
    const double outer = oval.lanes * oval.laneWidth;
    // Infield grass, then the surface as the ring between kerb and outer lane line.
    pen.fill(QPolygonF(TrackOverlay::line(track, 0.0, 360)), kGrass);
    QPainterPath surface = pen.path(QPolygonF(TrackOverlay::line(track, outer, 360)));
    surface.addPath(pen.path(QPolygonF(TrackOverlay::line(track, 0.0, 360))));
    surface.setFillRule(Qt::OddEvenFill);
    painter.fillPath(surface, QColor(178, 74, 58));
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(235, 235, 235), 1.6));
    pen.poly(QPolygonF(TrackOverlay::line(track, 0.0, 360)));
    painter.setPen(QPen(QColor(245, 245, 245), 1.0));
    for (int lane = 1; lane <= oval.lanes; ++lane)
        pen.poly(QPolygonF(TrackOverlay::line(track, lane * oval.laneWidth, 360)));
    // Finish line at the end of the home straight.
    const double x = oval.straightLength / 2, y0 = -oval.kerbRadius;
    painter.setPen(QPen(QColor(250, 250, 250), 2.0));
    pen.line(x, y0, x, y0 - outer);
}

void drawGrid(QPainter& painter, const QTransform& t, const QRectF& screen) {
    const QTransform inv = t.inverted();
    const QRectF world = inv.mapRect(screen);
    const double step = t.m11() * 10.0 < 12.0 ? 50.0 : 10.0;  // 10 m, or 50 m when zoomed far out
    Pen pen(painter, t);
    painter.setPen(QPen(QColor(215, 215, 215), 1.0));
    for (double x = std::floor(world.left() / step) * step; x <= world.right(); x += step)
        pen.line(x, world.top(), x, world.bottom());
    for (double y = std::floor(world.top() / step) * step; y <= world.bottom(); y += step)
        pen.line(world.left(), y, world.right(), y);
    painter.setPen(QPen(QColor(170, 170, 170), 1.0));
    pen.line(world.left(), 0, world.right(), 0);
    pen.line(0, world.top(), 0, world.bottom());
}

}  // namespace

QString VenueDrawing::id(Venue venue) {
    switch (venue) {
        case Venue::Football:
            return QStringLiteral("football");
        case Venue::Rugby:
            return QStringLiteral("rugby");
        case Venue::Track:
            return QStringLiteral("track");
        case Venue::Rectangle:
            return QStringLiteral("rectangle");
        default:
            return QStringLiteral("none");
    }
}

std::optional<VenueDrawing::Venue> VenueDrawing::fromId(const QString& id) {
    for (Venue v : {Venue::None, Venue::Football, Venue::Rugby, Venue::Track, Venue::Rectangle})
        if (VenueDrawing::id(v) == id) return v;
    return std::nullopt;
}

QStringList VenueDrawing::ids() {
    return {id(Venue::Football), id(Venue::Rugby), id(Venue::Track), id(Venue::Rectangle), id(Venue::None)};
}

QString VenueDrawing::displayName(Venue venue) {
    switch (venue) {
        case Venue::Football:
            return QCoreApplication::translate("athlos::ui::VenueDrawing", "Football pitch 105 × 68 m");
        case Venue::Rugby:
            return QCoreApplication::translate("athlos::ui::VenueDrawing", "Rugby pitch 100 × 70 m");
        case Venue::Track:
            return QCoreApplication::translate("athlos::ui::VenueDrawing", "400 m track");
        case Venue::Rectangle:
            return QCoreApplication::translate("athlos::ui::VenueDrawing", "Rectangle (surveyed pitch)");
        default:
            return QCoreApplication::translate("athlos::ui::VenueDrawing", "None");
    }
}

VenueDrawing::Size VenueDrawing::sizeOf(Venue venue, Size size) {
    if (size.length > 0 && size.width > 0) return size;
    switch (venue) {
        case Venue::Football:
            return {kPitchLength, kPitchWidth};
        case Venue::Rugby:
            return {kRugbyLength, kRugbyWidth};
        case Venue::Rectangle:
            return {100.0, 64.0};
        default:
            return {};
    }
}

VenueDrawing::Venue VenueDrawing::ofPitch(PitchGeometry::Kind kind) {
    switch (kind) {
        case PitchGeometry::Kind::Football:
            return Venue::Football;
        case PitchGeometry::Kind::Rugby:
            return Venue::Rugby;
        default:
            return Venue::Rectangle;
    }
}

QRectF VenueDrawing::bounds(Venue venue, Size requested) {
    const Size size = sizeOf(venue, requested);
    switch (venue) {
        case Venue::Football:
            return QRectF(-size.length / 2 - 3, -size.width / 2 - 3, size.length + 6, size.width + 6);
        case Venue::Rectangle:
            return QRectF(-size.length / 2 - 2, -size.width / 2 - 2, size.length + 4, size.width + 4);
        case Venue::Rugby: {
            const double hl = size.length / 2 + kRugbyInGoal + 2;
            return QRectF(-hl, -size.width / 2 - 2, 2 * hl, size.width + 4);
        }
        case Venue::Track: {
            const TrackGeometry track = TrackGeometry::iaaf400m();
            const auto& o = track.ovalParams();
            const double r = o.kerbRadius + o.lanes * o.laneWidth + 2;
            return QRectF(-o.straightLength / 2 - r, -r, o.straightLength + 2 * r, 2 * r);
        }
        default:
            return {};
    }
}

VenueDrawing::Venue VenueDrawing::guess(const QRectF& extent) {
    if (!extent.isValid()) return Venue::None;
    for (Venue v : {Venue::Football, Venue::Rugby, Venue::Track}) {
        const QRectF b = bounds(v).adjusted(-1, -1, 1, 1);
        // Most of a venue's area should be used too: a 5 m walk is not a match.
        if (b.contains(extent) && extent.width() > 0.4 * b.width()) return v;
    }
    return Venue::None;
}

void VenueDrawing::draw(QPainter& painter, const QTransform& worldToScreen, Venue venue, const QRectF& screen,
                        Size size) {
    painter.save();
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.fillRect(screen, venue == Venue::None    ? QColor(250, 250, 250)
                             : venue == Venue::Track ? QColor(96, 140, 90)
                                                     : kSurround);
    switch (venue) {
        case Venue::Football:
            drawFootball(painter, worldToScreen, sizeOf(venue, size));
            break;
        case Venue::Rugby:
            drawRugby(painter, worldToScreen, sizeOf(venue, size));
            break;
        case Venue::Rectangle:
            drawRectangle(painter, worldToScreen, sizeOf(venue, size));
            break;
        case Venue::Track:
            drawTrack(painter, worldToScreen);
            break;
        default:
            drawGrid(painter, worldToScreen, screen);
            break;
    }
    painter.restore();
}

}  // namespace athlos::ui
