#include "core/io/MetricaImporter.h"

#include "core/io/CsvReader.h"

#include <QFileInfo>
#include <cmath>
#include <limits>

namespace athlos {
namespace {

constexpr double kPitchLength = 105.0;  // m (Metrica's documented pitch size for its sample data)
constexpr double kPitchWidth = 68.0;

struct Player {
    QString team, number, name;
    int column = 0;  // 0-based file column of x
};

}  // namespace

QString MetricaImporter::description() const {
    return QStringLiteral("Metrica Sports tracking CSV (team, jersey and Period,Frame,Time [s] header rows)");
}

bool MetricaImporter::canRead(const QString& file, const QByteArray& head) const {
    if (QFileInfo(file).suffix().toLower() != QLatin1String("csv")) return false;
    const QList<QByteArray> lines = head.left(8192).split('\n');
    return lines.size() > 3 && lines[2].trimmed().startsWith("Period,Frame,Time [s]") && lines[0].startsWith(",,,");
}

Expected<ImportResult> MetricaImporter::read(const QString& file, const ImportOptions&,
                                             const Progress& progress) const {
    MappedFile mapped;
    if (Status s = mapped.open(file); !s) return s.error();
    CsvReader reader(mapped.begin(), mapped.end());
    QStringList teams, numbers, names;
    if (!reader.readHeader(teams) || !reader.readHeader(numbers) || !reader.readHeader(names))
        return makeError(QStringLiteral("%1: a Metrica file has three header rows (teams, numbers, names)").arg(file));
    const long long nameLine = reader.line();
    if (names.size() < 5 || names[0] != QLatin1String("Period") || names[1] != QLatin1String("Frame") ||
        names[2] != QLatin1String("Time [s]"))
        return makeError(
            QStringLiteral("%1:%2:1: expected the header Period,Frame,Time [s],Player…").arg(file).arg(nameLine));
    std::vector<Player> players;
    for (qsizetype c = 3; c + 1 < names.size() || (c < names.size() && names[c] == QLatin1String("Ball")); c += 2) {
        if (names[c].isEmpty())
            return makeError(QStringLiteral("%1:%2:%3: expected a player or Ball name (x), then an empty cell (y)")
                                 .arg(file)
                                 .arg(nameLine)
                                 .arg(c + 1));
        Player p;
        p.name = names[c];
        p.column = int(c);
        p.team = names[c] == QLatin1String("Ball") ? QString() : teams.value(c).trimmed();
        p.number = names[c] == QLatin1String("Ball") ? QString() : numbers.value(c).trimmed();
        players.push_back(p);
    }
    const int columns = int(names.size());
    std::vector<StreamData> data(players.size());
    for (auto& d : data) d.columns = 3;  // x, y, period
    std::vector<double> row(static_cast<size_t>(columns));
    while (reader.nextRecord()) {
        for (int c = 0; c < columns; ++c) {
            double v = 0.0;
            const auto field = reader.number(v);
            if (field == CsvReader::Field::Missing) {
                if (c == columns - 1 && names.back().isEmpty()) {  // a trailing empty header cell may have no field
                    row[size_t(c)] = std::numeric_limits<double>::quiet_NaN();
                    break;
                }
                return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                     .arg(file)
                                     .arg(reader.line())
                                     .arg(c + 1)
                                     .arg(reader.fieldsOnLine())
                                     .arg(columns));
            }
            if (field == CsvReader::Field::Invalid)
                return makeError(
                    QStringLiteral("%1:%2:%3 (column '%4'): '%5' is not a number")
                        .arg(file)
                        .arg(reader.line())
                        .arg(c + 1)
                        .arg(names[c].isEmpty() ? names.value(c - 1) + QStringLiteral(" y") : names[c],
                             QString::fromUtf8(reader.lastField().data(), qsizetype(reader.lastField().size()))));
            if (c < 3 && field == CsvReader::Field::Empty)
                return makeError(QStringLiteral("%1:%2:%3 (column '%4'): empty")
                                     .arg(file)
                                     .arg(reader.line())
                                     .arg(c + 1)
                                     .arg(names[c]));
            row[size_t(c)] = v;
        }
        if (!reader.finishRecord())
            return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                 .arg(file)
                                 .arg(reader.line())
                                 .arg(columns + 1)
                                 .arg(reader.fieldsOnLine())
                                 .arg(columns));
        const double t = row[2];
        for (size_t p = 0; p < players.size(); ++p) {
            const double x = row[size_t(players[p].column)], y = row[size_t(players[p].column + 1)];
            if (std::isnan(x) || std::isnan(y)) continue;  // not on the pitch
            StreamData& d = data[p];
            if (!d.t.empty() && t <= d.t.back())
                return makeError(QStringLiteral("%1:%2:3 (column 'Time [s]'): time %3 is not after %4")
                                     .arg(file)
                                     .arg(reader.line())
                                     .arg(t)
                                     .arg(d.t.back()));
            d.t.push_back(t);
            d.values.push_back((x - 0.5) * kPitchLength);
            d.values.push_back((0.5 - y) * kPitchWidth);
            d.values.push_back(row[0]);
        }
    }
    ImportResult result;
    for (size_t p = 0; p < players.size(); ++p) {
        if (data[p].t.empty()) continue;
        const Player& pl = players[p];
        StreamInfo info;
        info.kind = QStringLiteral("lps-position");
        info.frame = QStringLiteral("pitch");
        info.columns = {{"x", "m"}, {"y", "m"}, {"period", "1"}};
        const QString name =
            pl.team.isEmpty() ? QStringLiteral("ball") : pl.team.toLower() + QLatin1Char('-') + pl.number;
        info.attributes.insert(QStringLiteral("label"),
                               pl.team.isEmpty() ? QStringLiteral("Ball") : pl.team + QLatin1Char(' ') + pl.number);
        if (!pl.team.isEmpty()) {
            info.attributes.insert(QStringLiteral("team"), pl.team.toLower());
            info.attributes.insert(QStringLiteral("number"), pl.number.toDouble());
            info.attributes.insert(QStringLiteral("athlete"), pl.name);
        }
        info.attributes.insert(QStringLiteral("pitch"), QJsonObject{{"length", kPitchLength}, {"width", kPitchWidth}});
        info.attributes.insert(QStringLiteral("source_format"), QStringLiteral("metrica"));
        info.attributes.insert(QStringLiteral("source_units"),
                               QJsonObject{{"x", "pitch length"}, {"y", "pitch width"}});
        result.items.push_back({name, Stream(std::move(info), std::move(data[p]))});
    }
    if (result.items.empty())
        return makeError(QStringLiteral("%1: no positions after the header (line %2)").arg(file).arg(nameLine));
    progress.report(1.0);
    return result;
}

}  // namespace athlos
