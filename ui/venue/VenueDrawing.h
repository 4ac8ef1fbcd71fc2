#pragma once
// Venues drawn from above in metres with a QPainter: a football pitch 105 × 68 m with the IFAB
// markings, a rugby union pitch (100 m between the try lines, 70 m wide, 10 m in-goal), the 400 m
// track with its lanes (core's TrackGeometry, as the filters use it), or none (a 10 m grid). All are
// centred at the origin with x along the length. The caller gives the world → screen transform
// (equal metres per pixel on both axes, y up); lines are drawn in pixels so they stay crisp at any zoom.
#include <QRectF>
#include <QString>
#include <QStringList>
#include <QTransform>
#include <optional>

class QPainter;

namespace athlos::ui {

class VenueDrawing {
public:
    enum class Venue { None, Football, Rugby, Track };

    // Stable ids stored in metadata: "none", "football", "rugby", "track".
    static QString id(Venue venue);
    static std::optional<Venue> fromId(const QString& id);
    static QStringList ids();
    // Translated display name.
    static QString displayName(Venue venue);

    // The area to frame (m): the venue with its surroundings; empty for None.
    static QRectF bounds(Venue venue);
    // The venue that fits a data extent (m) best: the smallest whose bounds hold it, else None.
    static Venue guess(const QRectF& extent);

    // Draws the venue (grass or track surface and its lines) over the whole device rectangle.
    static void draw(QPainter& painter, const QTransform& worldToScreen, Venue venue, const QRectF& screen);

    // Football dimensions (IFAB Law 1), m.
    static constexpr double kPitchLength = 105.0, kPitchWidth = 68.0;
    static constexpr double kCentreCircle = 9.15, kPenaltyDepth = 16.5, kPenaltyWidth = 40.32;
    static constexpr double kGoalAreaDepth = 5.5, kGoalAreaWidth = 18.32, kPenaltySpot = 11.0;
    static constexpr double kCornerArc = 1.0, kGoalWidth = 7.32, kGoalDepth = 2.0;
    // Rugby union (World Rugby Law 1), m.
    static constexpr double kRugbyLength = 100.0, kRugbyWidth = 70.0, kRugbyInGoal = 10.0;
};

}  // namespace athlos::ui
