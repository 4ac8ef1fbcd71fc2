#include "core/io/VendorCsvImporter.h"

#include "core/io/CsvImporter.h"
#include "core/io/CsvReader.h"
#include "core/io/TimeFormats.h"
#include "core/util/Units.h"

#include <QFile>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <algorithm>
#include <map>

namespace athlos {

namespace {

QString lowerName(const QString& cell) {
    QString name, unit;
    splitNameAndUnit(cell, name, unit);
    return name.trimmed().toLower();
}

// Header cells (without units, lower case) → the source name as written.
std::map<QString, QString> headerNames(const QStringList& cells) {
    std::map<QString, QString> out;
    for (const QString& cell : cells) {
        QString name, unit;
        splitNameAndUnit(cell, name, unit);
        out.emplace(name.trimmed().toLower(), name);
    }
    return out;
}

QString streamName(const QString& athlete) {
    QString name = athlete.trimmed().toLower();
    static const QRegularExpression other(QStringLiteral("[^a-z0-9_.\\-]+"));
    name.replace(other, QStringLiteral("-"));
    return name.isEmpty() ? QStringLiteral("athlete") : name;
}

// The first header line as text (after comment lines), for detection.
QStringList headerOf(const QByteArray& head) {
    CsvReader reader(head.constData(), head.constData() + head.size());
    QStringList cells;
    reader.readHeader(cells);
    return cells;
}

QString replaced(QString message, const QString& from, const QString& to) { return message.replace(from, to); }

}  // namespace

const std::vector<VendorProfile>& VendorCsvImporter::profiles() {
    static const std::vector<VendorProfile> list{
        {"statsports",
         "STATSports Apex/Sonra raw export (10 Hz GNSS: Player Display Name, Time, Lat, Lon, Speed)",
         "gnss",
         {{"player display name", "lat", "lon"}, {"player display name", "latitude", "longitude"}},
         {"time", "elapsed time"},
         "",
         {{"lat", "lat", ""},
          {"latitude", "lat", ""},
          {"lon", "lon", ""},
          {"longitude", "lon", ""},
          {"speed", "speed", "m/s"},
          {"heart rate", "hr", "bpm"},
          {"instantaneous acceleration impulse", "acc_impulse", ""},
          {"elapsed time", "elapsed", "s"}},
         {"player display name", "player name"}},
        {"catapult",
         "Catapult OpenField raw CSV export (Timestamp, Seconds, Velocity, Latitude, Longitude, ...)",
         "gnss",
         {{"seconds", "velocity", "latitude", "longitude"}, {"seconds", "velocity", "lat", "long"}},
         {"seconds"},
         "s",
         {{"latitude", "lat", ""},
          {"longitude", "lon", ""},
          {"lat", "lat", ""},
          {"long", "lon", ""},
          {"velocity", "speed", "m/s"},
          {"acceleration", "acc", "m/s^2"},
          {"odometer", "distance", "m"},
          {"heart rate", "hr", "bpm"},
          {"player load", "player_load", ""},
          {"positional quality", "quality", "%"},
          {"hdop", "hdop", ""},
          {"#sats", "sats", ""}},
         {"athlete", "player"}},
        {"kinexon",
         "Kinexon position export (ts in ms, sensor id, full name, x in m, y in m)",
         "lps-position",
         {{"ts in ms", "x in m", "y in m"}},
         {"ts in ms"},
         "unix_ms",
         {{"x in m", "x", "m"}, {"y in m", "y", "m"}, {"z in m", "z", "m"}, {"speed in m/s", "speed", "m/s"}},
         {"full name", "sensor id", "mapped id"}},
    };
    return list;
}

QString VendorCsvImporter::format() const { return QLatin1String(profile_.format); }
QString VendorCsvImporter::description() const { return QLatin1String(profile_.description); }

bool VendorCsvImporter::canRead(const QString& file, const QByteArray& head) const {
    if (!extensions().contains(QFileInfo(file).suffix().toLower()) || head.contains('\0')) return false;
    QStringList names;
    for (const QString& cell : headerOf(head)) names << lowerName(cell);
    for (const auto& signature : profile_.signatures)
        if (std::all_of(signature.begin(), signature.end(),
                        [&](const char* n) { return names.contains(QLatin1String(n)); }))
            return true;
    return false;
}

Expected<ImportResult> VendorCsvImporter::read(const QString& file, const ImportOptions& options,
                                               const Progress& progress) const {
    MappedFile mapped;
    if (Status s = mapped.open(file); !s) return s.error();
    CsvReader reader(mapped.begin(), mapped.end());
    QStringList cells;
    if (!reader.readHeader(cells)) return makeError(QStringLiteral("%1: empty file (no header row)").arg(file));
    const long long headerLine = reader.line();
    const auto names = headerNames(cells);
    auto present = [&](const char* n) -> QString {
        const auto it = names.find(QLatin1String(n));
        return it == names.end() ? QString() : it->second;
    };
    QString timeSource;
    for (const char* t : profile_.timeColumns)
        if (timeSource = present(t); !timeSource.isEmpty()) break;
    if (timeSource.isEmpty() && options.timeColumn.isEmpty())
        return makeError(QStringLiteral("%1:%2: %3 export without its time column (%4)")
                             .arg(file)
                             .arg(headerLine)
                             .arg(QLatin1String(profile_.format), QLatin1String(profile_.timeColumns.front())));
    QString athleteSource;
    for (const char* a : profile_.athleteColumns)
        if (athleteSource = present(a); !athleteSource.isEmpty()) break;
    int timeIndex = -1, athleteIndex = -1;
    for (qsizetype c = 0; c < cells.size(); ++c) {
        QString name, unit;
        splitNameAndUnit(cells[c], name, unit);
        if (name == timeSource) timeIndex = int(c);
        if (name == athleteSource) athleteIndex = int(c);
    }

    // One pass over the records: the first time cell (for the format) and each line's athlete.
    QString firstTime;
    QStringList athletes;
    std::map<long long, int> athleteOfLine;
    std::string text;
    while (reader.nextRecord()) {
        int athlete = -1;
        for (int c = 0; c <= std::max(timeIndex, athleteIndex); ++c) {
            if (!reader.text(text)) break;
            const QString value = QString::fromUtf8(text.data(), qsizetype(text.size())).trimmed();
            if (c == timeIndex && firstTime.isEmpty()) firstTime = value;
            if (c == athleteIndex) {
                athlete = int(athletes.indexOf(value));
                if (athlete < 0) {
                    athlete = int(athletes.size());
                    athletes << value;
                }
            }
        }
        if (athlete >= 0) athleteOfLine[reader.line()] = athlete;
        while (reader.text(text)) {}  // the rest of the line
        reader.finishRecord();
        if (athleteIndex < 0 && !firstTime.isEmpty()) break;
    }

    ImportOptions csv = options;
    csv.format = QStringLiteral("csv");
    if (csv.kind.isEmpty()) csv.kind = QLatin1String(profile_.kind);
    csv.dropUnmapped = true;
    if (options.timeColumn.isEmpty()) {
        csv.timeColumn = timeSource;
        QString format = QLatin1String(profile_.timeFormat);
        if (format.isEmpty()) {
            const QByteArray utf8 = firstTime.toUtf8();
            const std::string_view cell(utf8.constData(), size_t(utf8.size()));
            qint64 ns = 0;
            bool zone = false;
            format = parseIsoDateTime(cell, ns, zone) ? QStringLiteral("iso")
                     : parseClockTime(cell, ns)       ? QStringLiteral("hh:mm:ss")
                                                      : QStringLiteral("s");
            if (timeSource.compare(QLatin1String("elapsed time"), Qt::CaseInsensitive) == 0)
                format = QStringLiteral("s");
        }
        csv.timeUnit = format;
    }
    auto mappedByUser = [&](const QString& source) {
        return std::any_of(options.columns.begin(), options.columns.end(),
                           [&](const ColumnMapping& m) { return m.source == source; });
    };
    QStringList channels;
    for (const VendorColumn& v : profile_.columns) {
        const QString source = present(v.source);
        if (source.isEmpty() || source == csv.timeColumn || mappedByUser(source) ||
            channels.contains(QLatin1String(v.channel)))
            continue;
        channels << QLatin1String(v.channel);
        csv.columns.push_back({source, QLatin1String(v.channel), QLatin1String(v.unit), false});
    }

    auto attributesFor = [&](const QString& athlete) {
        QJsonObject a{{QStringLiteral("source_format"), QLatin1String(profile_.format)}};
        if (!athlete.isEmpty()) {
            a.insert(QStringLiteral("athlete"), athlete);
            a.insert(QStringLiteral("label"), athlete);
        }
        return a;
    };
    auto decorate = [&](ImportResult& result, const QString& athlete, bool several) {
        for (ImportedItem& item : result.items) {
            if (several) item.path = streamName(athlete);
            if (auto* s = std::get_if<Stream>(&item.item)) {
                const QJsonObject a = attributesFor(athlete);
                for (auto it = a.begin(); it != a.end(); ++it) s->info().attributes.insert(it.key(), it.value());
            }
        }
    };
    if (athletes.size() <= 1) {
        auto result = CsvImporter().read(file, csv, progress);
        if (result) decorate(*result, athletes.value(0), false);
        return result;
    }

    // Several athletes: one file per athlete with the others' lines blanked (line numbers stay).
    QTemporaryDir temp;
    if (!temp.isValid())
        return makeError(QStringLiteral("%1: cannot create a temporary folder to split the athletes").arg(file));
    ImportResult all;
    const QByteArray content = QByteArray::fromRawData(mapped.begin(), qsizetype(mapped.size()));
    const QList<QByteArray> lines = content.split('\n');
    for (qsizetype a = 0; a < athletes.size(); ++a) {
        const QString part = temp.filePath(QStringLiteral("%1.csv").arg(a));
        QFile out(part);
        if (!out.open(QIODevice::WriteOnly)) return makeError(QStringLiteral("%1: cannot write %2").arg(file, part));
        for (qsizetype l = 0; l < lines.size(); ++l) {
            const auto owner = athleteOfLine.find(l + 1);
            if (owner == athleteOfLine.end() || owner->second == a) out.write(lines[l]);
            if (l + 1 < lines.size()) out.write("\n");
        }
        out.close();
        auto result = CsvImporter().read(
            part, csv, progress.sub(double(a) / double(athletes.size()), double(a + 1) / double(athletes.size())));
        if (!result) return makeError(replaced(result.message(), part, file));
        decorate(*result, athletes[a], true);
        for (const QString& w : result->warnings) all.warnings << replaced(w, part, file);
        for (ImportedItem& item : result->items) all.items.push_back(std::move(item));
    }
    return all;
}

}  // namespace athlos
