#pragma once
// A pitch (or any rectangle) placed from its four surveyed corners: the least-squares rectangle
// through them gives the real length, width, centre and rotation, and the pitch frame.
//
// Frames (ARCHITECTURE.md):
//   ENU    the project's local East-North-Up frame (m) about its geodetic origin (Geodesy.h), the
//          frame of GNSS x, y; corners given as x, y are taken to be in it (or any local metric frame).
//   pitch  origin at the centre spot, x along the length, y across, z up (right-handed), in m.
//          rotation = angle of the pitch x axis from East (ENU x), counter-clockwise, in rad, in
//          (−π/2, π/2]: of the two ends, +x points to the one towards East (a rectangle is symmetric).
//          p_enu = R(rotation) · p_pitch + centre; z is the same in both frames.
//
// The fit: with the corners in cyclic order (either direction, any start) the model corner i is
// centre + R(θ)·(±L/2, ±W/2). Minimising Σ|corner_i − model_i|² has a closed form: the centre is
// the mean of the corners; with a = Σ sᵢ qᵢ and b = Σ tᵢ qᵢ (qᵢ the centred corners as complex
// numbers, sᵢ, tᵢ = ±1 the model signs), 2θ = arg(a² − b²), L/2 = Re(a·e^{−iθ})/4,
// W/2 = Im(b·e^{−iθ})/4. The residual of a corner is its distance to its model corner (m).
#include "core/geometry/Geodesy.h"
#include "core/util/Expected.h"

#include <Eigen/Core>
#include <QJsonObject>
#include <QString>
#include <QStringList>
#include <map>
#include <optional>
#include <vector>

namespace athlos {

// Tolerances of PitchGeometry::fit (names as in the messages).
struct PitchFitParams {
    double maxResidual = 1.0;  // m, largest corner residual accepted ("max_residual")
    double minSide = 5.0;      // m, shortest side and smallest corner distance accepted ("min_side")
};

class PitchGeometry {
public:
    // What the rectangle is: markings are drawn for football (IFAB Law 1) and rugby union (World
    // Rugby Law 1: the corners are those of the field of play, try lines × touch lines); a plain
    // rectangle has none.
    enum class Kind { Football, Rugby, Rectangle };

    using Params = PitchFitParams;

    // Least-squares rectangle through 4 corners (m, ENU) in cyclic order. Refuses (naming the
    // corner and the parameter) fewer or more than 4 corners, non-finite values, an outline that
    // crosses itself or is not convex, sides shorter than minSide, residuals above maxResidual.
    static Expected<PitchGeometry> fit(const std::vector<Eigen::Vector2d>& corners, Kind kind,
                                       const Params& params = {}, QString name = {});
    // Corners as (lat, lon) in deg, converted to ENU about origin; the geodetic corners are kept.
    static Expected<PitchGeometry> fitGeodetic(const std::vector<Eigen::Vector2d>& latLon, const GeodeticOrigin& origin,
                                               Kind kind, const Params& params = {}, QString name = {});
    // A pitch of known size and pose (no survey).
    static PitchGeometry placed(Kind kind, double length, double width, const Eigen::Vector2d& centre, double rotation,
                                QString name = {});

    // "x,y;x,y;x,y;x,y" or "lat,lon;…" (whitespace allowed): the 4 pairs, errors name the pair.
    static Expected<std::vector<Eigen::Vector2d>> parseCorners(const QString& text, const QString& option);
    // "A,B;A,B;…" (an option's value) → points; count > 0: exactly that many. Errors name the option
    // and the item ("--polyline: point 2 '3,x' is not a pair of numbers A,B").
    static Expected<std::vector<Eigen::Vector2d>> parsePoints(const QString& text, const QString& option,
                                                              int count = -1,
                                                              const QString& noun = QStringLiteral("point"));

    // Stable ids "football", "rugby", "rectangle".
    static QString kindId(Kind kind);
    static std::optional<Kind> kindFromId(const QString& id);
    static QStringList kindIds();

    // JSON document for Project::geometry():
    //   {"type": "pitch", "name", "kind", "length", "width", "rotation", "centre": [x, y],
    //    "frame": "enu", "pitch_frame": "pitch", "units": {…}, "rotation_convention": "…",
    //    "corners": [[x, y]×4], "residuals": [m×4], optional "corners_geodetic": [[lat, lon]×4],
    //    "geodetic_origin": {lat, lon, height}}
    static bool isPitchJson(const QJsonObject& json);
    static Expected<PitchGeometry> fromJson(const QJsonObject& json);
    QJsonObject toJson() const;
    // The first pitch document of a project (by name), if any.
    static std::optional<PitchGeometry> firstOf(const std::map<QString, QJsonObject>& projectGeometry);

    Kind kind() const { return kind_; }
    const QString& name() const { return name_; }
    double length() const { return length_; }                  // m, along pitch x
    double width() const { return width_; }                    // m, along pitch y
    double rotation() const { return rotation_; }              // rad, pitch x from East, counter-clockwise
    const Eigen::Vector2d& centre() const { return centre_; }  // m, ENU
    // The corners as given (ENU, m) and their residuals (m), in input order; empty for placed().
    const std::vector<Eigen::Vector2d>& corners() const { return corners_; }
    const std::vector<double>& residuals() const { return residuals_; }
    double maxResidual() const;
    const std::vector<Eigen::Vector2d>& cornersGeodetic() const { return cornersGeodetic_; }

    // Notes for the user (e.g. dimensions outside the laws of the game); not errors.
    QStringList notes() const;

    Eigen::Vector2d toPitch(const Eigen::Vector2d& enu) const;
    Eigen::Vector2d toEnu(const Eigen::Vector2d& pitch) const;

private:
    Kind kind_ = Kind::Rectangle;
    QString name_;
    double length_ = 0.0, width_ = 0.0, rotation_ = 0.0;
    Eigen::Vector2d centre_ = Eigen::Vector2d::Zero();
    std::vector<Eigen::Vector2d> corners_;
    std::vector<double> residuals_;
    std::vector<Eigen::Vector2d> cornersGeodetic_;
    std::optional<GeodeticOrigin> origin_;
};

}  // namespace athlos
