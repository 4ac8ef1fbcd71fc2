#include "core/geometry/Geodesy.h"

#include "core/geometry/LocalTangentPlane.h"

#include <QStringList>
#include <cmath>

namespace athlos {

QJsonObject GeodeticOrigin::toJson() const {
    return QJsonObject{{QStringLiteral("lat"), lat},
                       {QStringLiteral("lon"), lon},
                       {QStringLiteral("height"), height},
                       {QStringLiteral("datum"), QStringLiteral("WGS84")}};
}

std::optional<GeodeticOrigin> GeodeticOrigin::fromJson(const QJsonObject& json) {
    if (!json.value(QStringLiteral("lat")).isDouble() || !json.value(QStringLiteral("lon")).isDouble())
        return std::nullopt;
    return GeodeticOrigin{json.value(QStringLiteral("lat")).toDouble(), json.value(QStringLiteral("lon")).toDouble(),
                          json.value(QStringLiteral("height")).toDouble(0.0)};
}

Expected<GeodeticOrigin> parseGeodeticOrigin(const QString& text) {
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() < 2 || parts.size() > 3)
        return makeError(QStringLiteral("origin '%1': expected LAT,LON[,HEIGHT] (deg, deg, m)").arg(text));
    double v[3] = {0.0, 0.0, 0.0};
    for (qsizetype i = 0; i < parts.size(); ++i) {
        bool ok = false;
        v[i] = parts[i].trimmed().toDouble(&ok);
        if (!ok || !std::isfinite(v[i]))
            return makeError(QStringLiteral("origin '%1': '%2' is not a number").arg(text, parts[i].trimmed()));
    }
    if (std::abs(v[0]) > 90.0 || std::abs(v[1]) > 180.0)
        return makeError(
            QStringLiteral("origin '%1': latitude must be in [-90, 90], longitude in [-180, 180]").arg(text));
    return GeodeticOrigin{v[0], v[1], v[2]};
}

std::optional<GeodeticOrigin> projectOrigin(const ProjectMeta& meta) {
    return GeodeticOrigin::fromJson(meta.extra.value(QStringLiteral("geodetic_origin")).toObject());
}

void setProjectOrigin(ProjectMeta& meta, const GeodeticOrigin& origin) {
    meta.extra.insert(QStringLiteral("geodetic_origin"), origin.toJson());
}

std::optional<GeodeticOrigin> firstFix(const Stream& stream) {
    const StreamInfo& info = stream.info();
    const int lat = info.columnIndex(QStringLiteral("lat")), lon = info.columnIndex(QStringLiteral("lon"));
    const int alt = info.columnIndex(QStringLiteral("alt"));
    if (lat < 0 || lon < 0) return std::nullopt;
    const auto data = stream.data();
    if (!data) return std::nullopt;
    for (size_t r = 0; r < (*data)->rows(); ++r) {
        const double la = (*data)->at(r, lat), lo = (*data)->at(r, lon);
        if (std::isfinite(la) && std::isfinite(lo)) {
            const double h = alt >= 0 ? (*data)->at(r, alt) : 0.0;
            return GeodeticOrigin{la, lo, std::isfinite(h) ? h : 0.0};
        }
    }
    return std::nullopt;
}

Expected<bool> addLocalEnu(Stream& stream, const GeodeticOrigin& origin) {
    StreamInfo info = stream.info();
    const int lat = info.columnIndex(QStringLiteral("lat")), lon = info.columnIndex(QStringLiteral("lon"));
    const int alt = info.columnIndex(QStringLiteral("alt"));
    if (lat < 0 || lon < 0) return false;
    const auto loaded = stream.data();
    if (!loaded) return loaded.error();
    const StreamData& in = **loaded;
    // Existing x, y, z are replaced (a re-import, or a stream converted before).
    std::vector<int> keep;
    Columns columns;
    for (int c = 0; c < in.columns; ++c) {
        const QString& name = info.columns[size_t(c)].name;
        if (name == QLatin1String("x") || name == QLatin1String("y") || name == QLatin1String("z")) continue;
        keep.push_back(c);
        columns.push_back(info.columns[size_t(c)]);
    }
    const int added = alt >= 0 ? 3 : 2;
    columns.push_back({QStringLiteral("x"), QStringLiteral("m")});
    columns.push_back({QStringLiteral("y"), QStringLiteral("m")});
    if (alt >= 0) columns.push_back({QStringLiteral("z"), QStringLiteral("m")});
    StreamData out(in.rows(), int(keep.size()) + added);
    out.t = in.t;
    const LocalTangentPlane plane(origin.lat, origin.lon, origin.height);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (size_t r = 0; r < in.rows(); ++r) {
        int c = 0;
        for (int k : keep) out.at(r, c++) = in.at(r, k);
        const double la = in.at(r, lat), lo = in.at(r, lon);
        const double h = alt >= 0 ? in.at(r, alt) : origin.height;
        if (std::isfinite(la) && std::isfinite(lo)) {
            const Eigen::Vector3d enu = plane.toEnu(la, lo, std::isfinite(h) ? h : origin.height);
            out.at(r, c++) = enu.x();
            out.at(r, c++) = enu.y();
            if (alt >= 0) out.at(r, c++) = std::isfinite(h) ? enu.z() : nan;
        } else {
            for (int k = 0; k < added; ++k) out.at(r, c++) = nan;
        }
    }
    info.columns = std::move(columns);
    info.attributes.insert(QStringLiteral("enu_origin"), origin.toJson());
    stream = Stream(std::move(info), std::move(out));
    return true;
}

}  // namespace athlos
