// athlos venue: place a pitch (or any rectangle) from its four surveyed corners, or list the venues.
#include "CommandParser.h"
#include "Commands.h"

#include "core/geometry/Geodesy.h"
#include "core/geometry/LocalTangentPlane.h"
#include "core/geometry/PitchGeometry.h"
#include "core/geometry/TrackPlacement.h"
#include "core/model/Project.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace athlos::cli {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

void printPitch(const PitchGeometry& g) {
    std::printf(
        "pitch '%s' (%s): length %.2f m, width %.2f m, rotation %.2f deg (%.5f rad, pitch x from East, "
        "counter-clockwise)\n",
        qUtf8Printable(g.name()), qUtf8Printable(PitchGeometry::kindId(g.kind())), g.length(), g.width(),
        g.rotation() * kDegPerRad, g.rotation());
    std::printf("  centre spot: x %.2f m, y %.2f m (ENU)\n", g.centre().x(), g.centre().y());
    if (!g.residuals().empty()) {
        QStringList r;
        for (std::size_t i = 0; i < g.residuals().size(); ++i)
            r << QStringLiteral("%1: %2").arg(i + 1).arg(g.residuals()[i], 0, 'f', 3);
        std::printf("  corner residuals (m): %s\n", qUtf8Printable(r.join(QStringLiteral(", "))));
    }
}

Expected<std::vector<Eigen::Vector2d>> toEnu(const std::vector<Eigen::Vector2d>& latLon, const GeodeticOrigin& origin,
                                             const QString& option) {
    const LocalTangentPlane plane(origin.lat, origin.lon, origin.height);
    std::vector<Eigen::Vector2d> enu;
    for (std::size_t i = 0; i < latLon.size(); ++i) {
        const Eigen::Vector2d& p = latLon[i];
        if (std::abs(p.x()) > 90.0 || std::abs(p.y()) > 180.0)
            return makeError(
                QStringLiteral("%1: point %2 (%3, %4): latitude must be in [-90, 90], longitude in [-180, 180]")
                    .arg(option)
                    .arg(i + 1)
                    .arg(p.x(), 0, 'g', 10)
                    .arg(p.y(), 0, 'g', 10));
        enu.push_back(plane.toEnu(p.x(), p.y(), origin.height).head<2>());
    }
    return enu;
}

// A placed track's document (TrackGeometry::toJson) with the frame and, from lat/lon, the points surveyed.
QJsonObject trackDocument(const TrackGeometry& track, const QString& name,
                          const std::optional<std::vector<Eigen::Vector2d>>& latLon,
                          const std::optional<GeodeticOrigin>& origin) {
    QJsonObject json = track.toJson();
    json.insert(QStringLiteral("name"), name);
    json.insert(QStringLiteral("frame"), QStringLiteral("enu"));
    json.insert(QStringLiteral("units"), QJsonObject{{QStringLiteral("length"), QStringLiteral("m")},
                                                     {QStringLiteral("rotation"), QStringLiteral("rad")},
                                                     {QStringLiteral("points_geodetic"), QStringLiteral("deg")}});
    if (latLon) {
        QJsonArray points;
        for (const auto& p : *latLon) points.append(QJsonArray{p.x(), p.y()});
        json.insert(QStringLiteral("points_geodetic"), points);
    }
    if (origin) json.insert(QStringLiteral("geodetic_origin"), origin->toJson());
    return json;
}

int listVenues(const Project& project, bool json) {
    QJsonObject all;
    for (const auto& [name, doc] : project.geometry()) {
        all.insert(name, doc);
        if (json) continue;
        if (PitchGeometry::isPitchJson(doc)) {
            if (auto g = PitchGeometry::fromJson(doc)) {
                printPitch(*g);
                continue;
            }
        }
        const QJsonObject pose = doc.value(QStringLiteral("pose")).toObject();
        if (!pose.isEmpty())
            std::printf("%s '%s': pose x %.2f m, y %.2f m, rotation %.2f deg\n",
                        qUtf8Printable(doc.value(QStringLiteral("type")).toString()), qUtf8Printable(name),
                        pose.value(QStringLiteral("x")).toDouble(), pose.value(QStringLiteral("y")).toDouble(),
                        pose.value(QStringLiteral("rotation")).toDouble() * kDegPerRad);
        else
            std::printf("%s '%s'\n", qUtf8Printable(doc.value(QStringLiteral("type")).toString()),
                        qUtf8Printable(name));
    }
    if (json) std::fputs(QJsonDocument(all).toJson(QJsonDocument::Indented).constData(), stdout);
    return Ok;
}

}  // namespace

int cmdVenue(const QStringList& args) {
    CommandParser p(
        QStringLiteral("venue <project> [--name N] [--kind football|rugby|rectangle] "
                       "--corners \"LAT,LON;…\" | --corners-xy \"X,Y;…\" | --track T --straight \"A;B\" | "
                       "--straight-xy \"A;B\" | --polyline \"LAT,LON;…\" | --polyline-xy \"X,Y;…\" [--json]"),
        QStringLiteral("Place a pitch (or any rectangle) from its four corners, surveyed in lat/lon or in the "
                       "project's local East-North-Up x, y (m), given in order round the pitch (any start, "
                       "either direction). Prints the least-squares length, width, rotation (pitch x axis "
                       "from East, counter-clockwise) and each corner's residual, and stores the pitch in "
                       "the project; views then draw the real pitch. A track is placed by the two ends of "
                       "its home straight (on the kerb, start then finish), a polyline by its points. "
                       "Without points: lists the venues."));
    p.addPositional(QStringLiteral("project"), QStringLiteral("The .athlos file."));
    p.addOption({QStringLiteral("name"),
                 QStringLiteral("Name of the venue document (default: pitch, track or polyline)."),
                 QStringLiteral("N")});
    p.addOption({QStringLiteral("kind"),
                 QStringLiteral("What the rectangle is: football (IFAB markings), rugby (field of play: try lines and "
                                "touch lines) or rectangle (no markings). Default: football."),
                 QStringLiteral("K"), QStringLiteral("football")});
    p.addOption({QStringLiteral("corners"),
                 QStringLiteral("The 4 corners as latitude,longitude (deg, WGS-84), ';' between corners."),
                 QStringLiteral("LAT,LON;…")});
    p.addOption({QStringLiteral("corners-xy"), QStringLiteral("The 4 corners as x,y (m) in the project's ENU frame."),
                 QStringLiteral("X,Y;…")});
    p.addOption({QStringLiteral("track"), QStringLiteral("An oval track to place: iaaf-400m or indoor-200m."),
                 QStringLiteral("T")});
    p.addOption(
        {QStringLiteral("straight"),
         QStringLiteral("The start and the end (finish line) of the track's home straight on the kerb, lat,lon."),
         QStringLiteral("LAT,LON;LAT,LON")});
    p.addOption(
        {QStringLiteral("straight-xy"), QStringLiteral("As --straight, in x,y (m, ENU)."), QStringLiteral("X,Y;X,Y")});
    p.addOption({QStringLiteral("polyline"),
                 QStringLiteral("A track as a polyline of lat,lon points in running order."),
                 QStringLiteral("LAT,LON;…")});
    p.addOption(
        {QStringLiteral("polyline-xy"), QStringLiteral("As --polyline, in x,y (m, ENU)."), QStringLiteral("X,Y;…")});
    p.addOption({QStringLiteral("closed"), QStringLiteral("The polyline is a closed loop.")});
    p.addOption(
        {QStringLiteral("max-residual"),
         QStringLiteral(
             "Refuse when a corner (or straight end) is further than this from the fitted venue (m, default 1)."),
         QStringLiteral("M"), QStringLiteral("1")});
    p.addOption({QStringLiteral("origin"),
                 QStringLiteral("The project's geodetic origin when it has none yet (default: the first point)."),
                 QStringLiteral("LAT,LON[,H]")});
    p.addOption({QStringLiteral("overwrite"), QStringLiteral("Replace a venue of the same name.")});
    p.addOption({QStringLiteral("json"), QStringLiteral("Machine-readable output (the stored document).")});
    if (auto code = p.parse(args, 1, 1)) return *code;
    const auto& opt = p.parser();
    const QString projectPath = p.positional()[0];

    // Exactly one way of giving points.
    QStringList given;
    for (const char* o : {"corners", "corners-xy", "straight", "straight-xy", "polyline", "polyline-xy"})
        if (opt.isSet(QLatin1String(o))) given << QLatin1String(o);
    if (given.isEmpty()) {
        for (const char* only : {"kind", "max-residual", "origin", "overwrite", "track", "closed", "name"})
            if (opt.isSet(QLatin1String(only)))
                return fail(QStringLiteral("--%1 needs --corners or --corners-xy (or a track's points)")
                                .arg(QLatin1String(only)),
                            Usage);
        auto project = Project::open(projectPath);
        if (!project) return fail(project.message());
        return listVenues(**project, opt.isSet(QStringLiteral("json")));
    }
    if (given.size() > 1 && given.contains(QStringLiteral("corners")) && given.contains(QStringLiteral("corners-xy")))
        return fail(QStringLiteral("give either --corners (lat/lon) or --corners-xy (m), not both"), Usage);
    if (given.size() > 1)
        return fail(QStringLiteral("give one of --%1, not several").arg(given.join(QStringLiteral(", --"))), Usage);
    const QString pointsOption = QStringLiteral("--") + given.front();
    const bool latLon = !given.front().endsWith(QLatin1String("-xy"));
    enum class Mode { Pitch, Oval, Polyline };
    const Mode mode = given.front().startsWith(QLatin1String("corners"))    ? Mode::Pitch
                      : given.front().startsWith(QLatin1String("straight")) ? Mode::Oval
                                                                            : Mode::Polyline;
    if (mode == Mode::Oval && !opt.isSet(QStringLiteral("track")))
        return fail(QStringLiteral("%1 needs --track (%2)")
                        .arg(pointsOption, TrackGeometry::builtinNames().join(QStringLiteral(", "))),
                    Usage);
    if (mode != Mode::Oval && opt.isSet(QStringLiteral("track")))
        return fail(QStringLiteral("--track needs --straight or --straight-xy"), Usage);
    if (mode != Mode::Polyline && opt.isSet(QStringLiteral("closed")))
        return fail(QStringLiteral("--closed applies to --polyline"), Usage);

    const QString defaultName = mode == Mode::Pitch  ? QStringLiteral("pitch")
                                : mode == Mode::Oval ? QStringLiteral("track")
                                                     : QStringLiteral("polyline");
    const QString name = opt.isSet(QStringLiteral("name")) ? opt.value(QStringLiteral("name")).trimmed() : defaultName;
    if (name.isEmpty() || name.contains(QLatin1Char('/')))
        return fail(QStringLiteral("--name '%1': a venue name must be non-empty and without '/'").arg(name), Usage);
    const auto kind = PitchGeometry::kindFromId(opt.value(QStringLiteral("kind")).trimmed().toLower());
    if (!kind)
        return fail(QStringLiteral("--kind '%1': use one of %2")
                        .arg(opt.value(QStringLiteral("kind")), PitchGeometry::kindIds().join(QStringLiteral(", "))),
                    Usage);
    PitchGeometry::Params params;
    bool ok = false;
    params.maxResidual = opt.value(QStringLiteral("max-residual")).toDouble(&ok);
    if (!ok || !(params.maxResidual > 0) || !std::isfinite(params.maxResidual))
        return fail(QStringLiteral("--max-residual '%1': expected a positive number of metres")
                        .arg(opt.value(QStringLiteral("max-residual"))),
                    Usage);
    const auto points = mode == Mode::Pitch ? PitchGeometry::parseCorners(opt.value(given.front()), pointsOption)
                                            : PitchGeometry::parsePoints(opt.value(given.front()), pointsOption,
                                                                         mode == Mode::Oval ? 2 : -1);
    if (!points) return fail(points.message(), Usage);
    std::optional<TrackGeometry> oval;
    if (mode == Mode::Oval) {
        auto builtin = TrackGeometry::builtin(opt.value(QStringLiteral("track")).trimmed());
        if (!builtin || builtin->kind() != TrackGeometry::Kind::Oval)
            return fail(
                QStringLiteral("--track '%1': use one of %2")
                    .arg(opt.value(QStringLiteral("track")), TrackGeometry::builtinNames().join(QStringLiteral(", "))),
                Usage);
        oval = *builtin;
    }
    std::optional<GeodeticOrigin> explicitOrigin;
    if (opt.isSet(QStringLiteral("origin"))) {
        if (!latLon)
            return fail(QStringLiteral("--origin applies to lat/lon points (--corners, --straight, --polyline)"),
                        Usage);
        auto origin = parseGeodeticOrigin(opt.value(QStringLiteral("origin")));
        if (!origin) return fail(QStringLiteral("--%1").arg(origin.message()), Usage);
        explicitOrigin = *origin;
    }

    if (!QFileInfo::exists(projectPath))
        return fail(QStringLiteral("'%1' does not exist (create it with: athlos new %1)").arg(projectPath));
    auto project = openForChange(projectPath);
    if (!project) return fail(project.message());
    Project& pr = **project;
    if (pr.geometry().count(name) && !opt.isSet(QStringLiteral("overwrite")))
        return fail(QStringLiteral("venue '%1' already exists in the project (--overwrite to replace it)").arg(name));

    std::optional<GeodeticOrigin> origin = projectOrigin(pr.meta());
    bool newOrigin = false;
    std::vector<Eigen::Vector2d> enu = *points;
    if (latLon) {
        if (origin && explicitOrigin && !(*origin == *explicitOrigin))
            return fail(
                QStringLiteral("the project's geodetic origin is %1, %2, %3 m; it cannot change (all GNSS streams "
                               "and venues share it)")
                    .arg(origin->lat, 0, 'g', 12)
                    .arg(origin->lon, 0, 'g', 12)
                    .arg(origin->height));
        if (!origin) {
            // Like the first fix of the first GNSS import: the first point, unless given.
            origin = explicitOrigin ? *explicitOrigin : GeodeticOrigin{points->front().x(), points->front().y(), 0.0};
            newOrigin = true;
        }
        if (mode != Mode::Pitch) {
            auto converted = toEnu(*points, *origin, pointsOption);
            if (!converted) return fail(converted.message());
            enu = std::move(*converted);
        }
    }

    QJsonObject document;
    QStringList notes;
    QString summary;  // tracks; a pitch prints itself
    if (mode == Mode::Pitch) {
        auto pitch = latLon ? PitchGeometry::fitGeodetic(*points, *origin, *kind, params, name)
                            : PitchGeometry::fit(*points, *kind, params, name);
        if (!pitch) return fail(pitch.message());
        document = pitch->toJson();
        notes = pitch->notes();
    } else {
        auto placed = mode == Mode::Oval ? placeOval(*oval, enu[0], enu[1], params.maxResidual)
                                         : placePolyline(enu, opt.isSet(QStringLiteral("closed")), name);
        if (!placed) return fail(placed.message());
        document = trackDocument(placed->track, name, latLon ? std::optional(*points) : std::nullopt,
                                 latLon ? origin : std::nullopt);
        if (mode == Mode::Oval) {
            const TrackPose& pose = placed->track.pose();
            summary = QStringLiteral(
                          "track '%1' (%2): centre x %3 m, y %4 m (ENU), rotation %5 deg (%6 rad, track x from "
                          "East, counter-clockwise)\n  straight residuals (m): 1: %7, 2: %8\n")
                          .arg(name, oval->name())
                          .arg(pose.x, 0, 'f', 2)
                          .arg(pose.y, 0, 'f', 2)
                          .arg(pose.rotation * kDegPerRad, 0, 'f', 2)
                          .arg(pose.rotation, 0, 'f', 5)
                          .arg(placed->residuals[0], 0, 'f', 3)
                          .arg(placed->residuals[1], 0, 'f', 3);
        } else {
            summary = QStringLiteral("polyline '%1': %2 points, %3 m%4\n")
                          .arg(name)
                          .arg(enu.size())
                          .arg(placed->track.referenceLength(), 0, 'f', 2)
                          .arg(opt.isSet(QStringLiteral("closed")) ? QStringLiteral(" (closed)") : QString());
        }
    }
    if (newOrigin) {
        setProjectOrigin(pr.meta(), *origin);
        std::fprintf(stderr, "athlos: note: the project's geodetic origin is now %s, %s%s\n",
                     qUtf8Printable(QString::number(origin->lat, 'g', 12)),
                     qUtf8Printable(QString::number(origin->lon, 'g', 12)),
                     explicitOrigin        ? ""
                     : mode == Mode::Pitch ? " (the first corner)"
                                           : " (the first point)");
    }
    pr.geometry()[name] = document;
    pr.setModified();
    if (Status s = pr.save(); !s) return fail(s.message());
    for (const QString& note : notes) std::fprintf(stderr, "athlos: note: %s\n", qUtf8Printable(note));
    if (opt.isSet(QStringLiteral("json")))
        std::fputs(QJsonDocument(document).toJson(QJsonDocument::Indented).constData(), stdout);
    else if (mode == Mode::Pitch)
        printPitch(*PitchGeometry::fromJson(document));
    else
        std::fputs(qUtf8Printable(summary), stdout);
    return Ok;
}

}  // namespace athlos::cli
