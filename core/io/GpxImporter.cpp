#include "core/io/GpxImporter.h"

#include "core/io/TimeFormats.h"

#include <QFile>
#include <QFileInfo>
#include <QXmlStreamReader>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace athlos {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Point {
    qint64 ns = 0;
    double lat = kNaN, lon = kNaN, ele = kNaN, hr = kNaN, cad = kNaN, speed = kNaN;
};

}  // namespace

QString GpxImporter::description() const {
    return QStringLiteral("GPX 1.1 track (trkpt lat, lon, ele, time; Garmin hr, cad, speed) → gnss stream");
}

bool GpxImporter::canRead(const QString& file, const QByteArray& head) const {
    return QFileInfo(file).suffix().toLower() == QLatin1String("gpx") || head.left(1024).contains("<gpx");
}

Expected<ImportResult> GpxImporter::read(const QString& file, const ImportOptions&, const Progress& progress) const {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("%1: cannot open: %2").arg(file, f.errorString()));
    progress.report(0.0, QStringLiteral("Reading %1").arg(QFileInfo(file).fileName()));
    QXmlStreamReader xml(&f);
    std::vector<Point> points;
    bool root = false;
    auto at = [&](qint64 line, qint64 column) { return QStringLiteral("%1:%2:%3").arg(file).arg(line).arg(column); };
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement()) continue;
        if (!root) {
            if (xml.name() != QLatin1String("gpx"))
                return makeError(QStringLiteral("%1: not a GPX file (root element <%2>)")
                                     .arg(at(xml.lineNumber(), xml.columnNumber()), xml.name().toString()));
            root = true;
            continue;
        }
        if (xml.name() != QLatin1String("trkpt")) continue;
        const qint64 line = xml.lineNumber(), column = xml.columnNumber();
        Point p;
        bool ok = false;
        p.lat = xml.attributes().value(QStringLiteral("lat")).toDouble(&ok);
        if (!ok || std::abs(p.lat) > 90.0)
            return makeError(QStringLiteral("%1: <trkpt> lat '%2' is not a latitude")
                                 .arg(at(line, column), xml.attributes().value(QStringLiteral("lat")).toString()));
        p.lon = xml.attributes().value(QStringLiteral("lon")).toDouble(&ok);
        if (!ok || std::abs(p.lon) > 180.0)
            return makeError(QStringLiteral("%1: <trkpt> lon '%2' is not a longitude")
                                 .arg(at(line, column), xml.attributes().value(QStringLiteral("lon")).toString()));
        bool timed = false;
        while (!xml.atEnd() && !(xml.isEndElement() && xml.name() == QLatin1String("trkpt"))) {
            xml.readNext();
            if (!xml.isStartElement()) continue;
            const QString name = xml.name().toString();
            const qint64 l = xml.lineNumber(), c = xml.columnNumber();
            auto number = [&](double& out, double scale) -> Status {
                const QString text = xml.readElementText().trimmed();
                bool good = false;
                out = text.toDouble(&good) * scale;
                if (!good) return makeError(QStringLiteral("%1: <%2> '%3' is not a number").arg(at(l, c), name, text));
                return {};
            };
            Status s;
            if (name == QLatin1String("ele")) {
                s = number(p.ele, 1.0);
            } else if (name == QLatin1String("time")) {
                const QString text = xml.readElementText().trimmed();
                const QByteArray utf8 = text.toUtf8();
                bool zone = false;
                if (!parseIsoDateTime(std::string_view(utf8.constData(), size_t(utf8.size())), p.ns, zone))
                    return makeError(
                        QStringLiteral("%1: <time> '%2' is not an ISO 8601 date-time").arg(at(l, c), text));
                timed = true;
            } else if (name == QLatin1String("hr")) {
                s = number(p.hr, 1.0 / 60.0);
            } else if (name == QLatin1String("cad")) {
                s = number(p.cad, 1.0 / 60.0);
            } else if (name == QLatin1String("speed")) {
                s = number(p.speed, 1.0);
            }
            if (!s) return s.error();
        }
        if (!timed)
            return makeError(
                QStringLiteral("%1: <trkpt> has no <time>; a track needs time stamps").arg(at(line, column)));
        points.push_back(p);
    }
    if (xml.hasError())
        return makeError(QStringLiteral("%1: %2").arg(at(xml.lineNumber(), xml.columnNumber()), xml.errorString()));
    if (points.empty()) return makeError(QStringLiteral("%1: no track points (<trkpt>)").arg(file));

    auto any = [&](double Point::*m) {
        return std::any_of(points.begin(), points.end(), [&](const Point& p) { return !std::isnan(p.*m); });
    };
    struct Out {
        const char* name;
        const char* unit;
        double Point::*member;
    };
    std::vector<Out> columns{{"lat", "deg", &Point::lat}, {"lon", "deg", &Point::lon}};
    if (any(&Point::ele)) columns.push_back({"alt", "m", &Point::ele});
    if (any(&Point::speed)) columns.push_back({"speed", "m/s", &Point::speed});
    if (any(&Point::hr)) columns.push_back({"hr", "Hz", &Point::hr});
    if (any(&Point::cad)) columns.push_back({"cad", "Hz", &Point::cad});
    StreamData data(points.size(), int(columns.size()));
    const qint64 t0 = points.front().ns;
    for (size_t r = 0; r < points.size(); ++r) {
        data.t[r] = double(points[r].ns - t0) * 1e-9;
        for (size_t c = 0; c < columns.size(); ++c) data.at(r, int(c)) = points[r].*(columns[c].member);
    }
    if (const long long bad = data.firstNonIncreasing(); bad >= 0)
        return makeError(QStringLiteral("%1: track point %2 has time %3, not after the point before (%4)")
                             .arg(file)
                             .arg(bad + 1)
                             .arg(formatUtc(points[size_t(bad)].ns), formatUtc(points[size_t(bad - 1)].ns)));
    StreamInfo info;
    info.kind = QStringLiteral("gnss");
    info.frame = QStringLiteral("WGS84");
    for (const Out& c : columns) info.columns.push_back({QLatin1String(c.name), QLatin1String(c.unit)});
    info.attributes.insert(QStringLiteral("source_format"), QStringLiteral("gpx"));
    if (any(&Point::hr) || any(&Point::cad)) {
        QJsonObject units;
        if (any(&Point::hr)) units.insert(QStringLiteral("hr"), QStringLiteral("bpm"));
        if (any(&Point::cad)) units.insert(QStringLiteral("cad"), QStringLiteral("rpm"));
        info.attributes.insert(QStringLiteral("source_units"), units);
    }
    writeTimeAttributes(info.attributes, TimeBase{true, false, t0}, QStringLiteral("iso"));
    ImportResult result;
    result.items.push_back({QStringLiteral("gnss"), Stream(std::move(info), std::move(data))});
    progress.report(1.0);
    return result;
}

}  // namespace athlos
