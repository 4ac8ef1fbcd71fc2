#pragma once
// Venues drawn from above in metres with a QPainter: a football pitch 105 × 68 m with the IFAB
// markings, a rugby union pitch (100 m between the try lines, 70 m wide, 10 m in-goal), the 400 m
// track with its lanes (core's TrackGeometry, as the filters use it), a plain rectangle (a surveyed
// pitch without markings), or none (a 10 m grid). All are centred at the origin with x along the
// length (the pitch frame of core's PitchGeometry). Pitches can have their real size (Size, from a
// pitch placed by its corners): only the length and width change; markings of fixed size by the
// laws (centre circle 9.15 m, penalty area 16.5 × 40.32 m, rugby 22 m and 5 m lines, in-goal)
// stay as they are. The caller gives the world → screen transform (equal metres per pixel on both
// axes, y up); lines are drawn in pixels so they stay crisp at any zoom.
#include "core/geometry/PitchGeometry.h"

#include <QRectF>
#include <QString>
#include <QStringList>
#include <QTransform>
#include <optional>

class QPainter;

namespace athlos::ui {

// Length (along x) and width of a pitch, m; 0 = the standard size of the venue.
struct VenueSize {
    double length = 0.0;
    double width = 0.0;
    bool operator==(const VenueSize&) const = default;
};

class VenueDrawing {
public:
    enum class Venue { None, Football, Rugby, Track, Rectangle };

    using Size = VenueSize;
    // The size drawn for a venue given a requested size (0 → standard: football 105 × 68, rugby
    // 100 × 70 between the try lines, rectangle 100 × 64).
    static Size sizeOf(Venue venue, Size size = {});
    // The venue that draws a pitch of this kind.
    static Venue ofPitch(PitchGeometry::Kind kind);

    // Stable ids stored in metadata: "none", "football", "rugby", "track", "rectangle".
    static QString id(Venue venue);
    static std::optional<Venue> fromId(const QString& id);
    static QStringList ids();
    // Translated display name.
    static QString displayName(Venue venue);

    // The area to frame (m): the venue with its surroundings; empty for None.
    static QRectF bounds(Venue venue, Size size = {});
    // The venue that fits a data extent (m) best: the smallest whose bounds hold it, else None.
    static Venue guess(const QRectF& extent);

    // Draws the venue (grass or track surface and its lines) over the whole device rectangle.
    static void draw(QPainter& painter, const QTransform& worldToScreen, Venue venue, const QRectF& screen,
                     Size size = {});

    // Football dimensions (IFAB Law 1), m.
    static constexpr double kPitchLength = 105.0, kPitchWidth = 68.0;
    static constexpr double kCentreCircle = 9.15, kPenaltyDepth = 16.5, kPenaltyWidth = 40.32;
    static constexpr double kGoalAreaDepth = 5.5, kGoalAreaWidth = 18.32, kPenaltySpot = 11.0;
    static constexpr double kCornerArc = 1.0, kGoalWidth = 7.32, kGoalDepth = 2.0;
    // Rugby union (World Rugby Law 1), m.
    static constexpr double kRugbyLength = 100.0, kRugbyWidth = 70.0, kRugbyInGoal = 10.0;
};

}  // namespace athlos::ui
