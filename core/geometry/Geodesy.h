#pragma once
// A project's geodetic origin and the local East-North-Up coordinates of GNSS streams.
//
// A project has one origin (ProjectMeta::extra["geodetic_origin"] = {lat, lon, height}: deg, deg, m):
// set explicitly (ImportOptions::geodeticOrigin, `athlos import --origin LAT,LON[,H]`) or taken from
// the first fix of the first GNSS stream imported. Every stream of kind gnss with lat and lon columns
// gets x, y (and z with alt) in metres in that shared ENU frame (WGS-84 → ECEF → ENU, exact; heights
// as given, e.g. above mean sea level from NMEA) and attributes["enu_origin"].
#include "core/model/Project.h"
#include "core/model/Stream.h"
#include "core/util/Expected.h"

#include <QJsonObject>
#include <optional>

namespace athlos {

struct GeodeticOrigin {
    double lat = 0.0;     // deg
    double lon = 0.0;     // deg
    double height = 0.0;  // m
    QJsonObject toJson() const;
    static std::optional<GeodeticOrigin> fromJson(const QJsonObject& json);
    bool operator==(const GeodeticOrigin&) const = default;
};

// "LAT,LON[,H]" (deg, deg, m); error if not numbers or out of range.
Expected<GeodeticOrigin> parseGeodeticOrigin(const QString& text);

std::optional<GeodeticOrigin> projectOrigin(const ProjectMeta& meta);
void setProjectOrigin(ProjectMeta& meta, const GeodeticOrigin& origin);

// The first fix (finite lat, lon; alt or 0) of a gnss stream, if any.
std::optional<GeodeticOrigin> firstFix(const Stream& stream);

// Adds (or replaces) x, y[, z] (m, ENU about origin) to a gnss stream with lat/lon; false if the
// stream has no lat/lon columns.
Expected<bool> addLocalEnu(Stream& stream, const GeodeticOrigin& origin);

}  // namespace athlos
