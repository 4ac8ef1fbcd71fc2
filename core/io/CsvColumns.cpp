#include "core/io/CsvColumns.h"

#include "core/io/TdoaLayout.h"
#include "core/util/Units.h"

#include <QHash>
#include <QRegularExpression>

#include <algorithm>
#include <charconv>

namespace athlos {
namespace csv {
namespace {

constexpr char kPrefix[] = "%1:%2:%3 (column '%4')";

const ColumnMapping* findMapping(const ImportOptions& options, const QString& source) {
    for (const ColumnMapping& m : options.columns)
        if (m.source == source) return &m;
    return nullptr;
}

// Checks the mapping against the header names (before any column is planned), so a mistake names
// the option rather than a column.
Status checkMapping(const ImportOptions& options, const QStringList& sources, const QString& file, long long line) {
    const QString known = sources.join(QStringLiteral(", "));
    QStringList seen;
    for (const ColumnMapping& m : options.columns) {
        if (!sources.contains(m.source))
            return makeError(QStringLiteral("%1:%2: column mapping: the file has no column '%3'; columns: %4")
                                 .arg(file)
                                 .arg(line)
                                 .arg(m.source, known));
        if (seen.contains(m.source))
            return makeError(
                QStringLiteral("%1:%2: column mapping: column '%3' is mapped twice").arg(file).arg(line).arg(m.source));
        seen << m.source;
        if (!m.skip && !m.unit.trimmed().isEmpty() && siUnitOf(canonicalUnit(m.unit)).isEmpty())
            return makeError(QStringLiteral("%1:%2: column mapping for '%3': unknown unit '%4' (accepted: %5)")
                                 .arg(file)
                                 .arg(line)
                                 .arg(m.source, m.unit, knownUnitNames()));
    }
    if (!options.timeColumn.isEmpty()) {
        if (!sources.contains(options.timeColumn))
            return makeError(QStringLiteral("%1:%2: time column '%3' is not in the file; columns: %4")
                                 .arg(file)
                                 .arg(line)
                                 .arg(options.timeColumn, known));
        if (const ColumnMapping* m = findMapping(options, options.timeColumn); m && m->skip)
            return makeError(QStringLiteral("%1:%2: time column '%3' is also marked to skip")
                                 .arg(file)
                                 .arg(line)
                                 .arg(options.timeColumn));
    }
    if (!options.labelColumn.isEmpty()) {
        if (!sources.contains(options.labelColumn))
            return makeError(QStringLiteral("%1:%2: label column '%3' is not in the file; columns: %4")
                                 .arg(file)
                                 .arg(line)
                                 .arg(options.labelColumn, known));
        if (const ColumnMapping* m = findMapping(options, options.labelColumn); m)
            return makeError(QStringLiteral("%1:%2: label column '%3' is also mapped or skipped")
                                 .arg(file)
                                 .arg(line)
                                 .arg(options.labelColumn));
    }
    if (!options.timeUnit.isEmpty()) {
        const auto format = parseTimeFormat(options.timeUnit);
        if (!format)
            return makeError(QStringLiteral("%1:%2: time column '%3': %4")
                                 .arg(file)
                                 .arg(line)
                                 .arg(options.timeColumn, format.message()));
    }
    return {};
}

}  // namespace

QString where(const QString& file, long long line, int column, const QString& name) {
    return QString::fromLatin1(kPrefix).arg(file).arg(line).arg(column).arg(name);
}

QString shortest(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return QString::fromLatin1(buf, r.ptr - buf);
}

QString quoted(std::string_view text) {
    constexpr size_t kMax = 40;
    QString s = QString::fromUtf8(text.data(), qsizetype(std::min(text.size(), kMax)));
    return QLatin1Char('\'') + s + (text.size() > kMax ? QStringLiteral("...'") : QStringLiteral("'"));
}

bool isUnnamedColumn(const QString& name) {
    static const QRegularExpression pandas(QStringLiteral("^Unnamed: \\d+$"));
    return name.trimmed().isEmpty() || pandas.match(name.trimmed()).hasMatch();
}

QString knownChannelName(const QString& name) {
    const QString lower = name.trimmed().toLower();
    static const QHash<QString, QString> aliases{
        {"latitude", "lat"}, {"longitude", "lon"},   {"lng", "lon"},      {"long", "lon"},
        {"altitude", "alt"}, {"satellites", "sats"}, {"numsats", "sats"}, {"num_sats", "sats"},
    };
    if (const auto it = aliases.constFind(lower); it != aliases.cend()) return *it;
    if (lower == QLatin1String("t") || lower == name)
        return {};  // the time column is named explicitly; already canonical
    for (const StreamKind& kind : streamKinds())
        if (!kind.unitFor(lower).isEmpty() || kind.requiredColumns.contains(lower)) return lower;
    return {};
}

bool isKindColumn(const StreamKind* kind, const QString& name, bool table) {
    if (!kind) return false;
    if (table && (name == QLatin1String("id") || name == QLatin1String("name") || name == QLatin1String("label")))
        return true;
    return !kind->unitFor(name).isEmpty() || kind->requiredColumns.contains(name);
}

const StreamKind* lookupKind(const QString& kind) {
    if (const StreamKind* k = findStreamKind(kind)) return k;
    for (const auto& k : streamKinds())  // "lps", "tdoa": the default names work as well
        if (k.defaultName == kind) return &k;
    return nullptr;
}

Expected<Header> planHeader(CsvReader& reader, const QString& file, const ImportOptions& options,
                            const QString& kindName, const StreamKind* kind, bool table) {
    Header header;
    QStringList cells;
    if (!reader.readHeader(cells)) return makeError(QStringLiteral("%1: empty file (no header row)").arg(file));
    header.line = reader.line();
    QStringList sources;
    for (const QString& cell : cells) {
        QString name, unit;
        splitNameAndUnit(cell, name, unit);
        sources << name;
    }
    if (Status s = checkMapping(options, sources, file, header.line); !s) return s.error();
    QStringList names;
    std::vector<int> nameColumn;  // file column (1-based) of each name, for messages
    for (int i = 0; i < cells.size(); ++i) {
        ColumnPlan col;
        QString unit;
        splitNameAndUnit(cells[i], col.name, unit);
        col.source = col.name;
        const QString at = where(file, header.line, i + 1, col.name);
        const ColumnMapping* mapping = findMapping(options, col.name);
        if ((mapping && mapping->skip) || (!mapping && isUnnamedColumn(col.name))) {
            col.role = Role::Skip;  // skipped, or an index column without a name (pandas)
            header.columns.push_back(col);
            continue;
        }
        bool mappedUnit = false;
        if (mapping && !mapping->unit.trimmed().isEmpty()) {
            unit = canonicalUnit(mapping->unit);
            mappedUnit = true;
        }
        const bool isTime =
            !table && (options.timeColumn.isEmpty() ? col.name == QLatin1String("t") : col.name == options.timeColumn);
        if (!table && !options.labelColumn.isEmpty() && col.source == options.labelColumn) {
            if (isTime) return makeError(QStringLiteral("%1: the label column is the time column").arg(at));
            col.role = Role::Label;
            header.labelColumn = i;
            header.columns.push_back(col);
            continue;
        }
        if (mapping && !mapping->channel.trimmed().isEmpty())
            col.name = mapping->channel.trimmed();
        else if (const QString known = knownChannelName(col.name); !known.isEmpty())
            col.name = known;  // "Lat", "LATITUDE", "ACC_X"
        if (!isTime && options.dropUnmapped && !mapping && !isKindColumn(kind, col.name, table) &&
            col.name.compare(QLatin1String("date"), Qt::CaseInsensitive) != 0) {  // the date of clock times: below
            col.role = Role::Skip;
            header.columns.push_back(col);
            continue;
        }
        if (isTime) {
            col.name = QStringLiteral("t");
            if (!options.timeUnit.isEmpty()) unit = options.timeUnit.trimmed();
        } else if (!table && !options.timeColumn.isEmpty() && col.name == QLatin1String("t")) {
            return makeError(
                QStringLiteral("%1: the name 't' is taken by the time column '%2'").arg(at, options.timeColumn));
        }
        if (const qsizetype other = names.indexOf(col.name); other >= 0)
            return makeError(mapping ? QStringLiteral("%1: duplicate channel '%2' (also column %3)")
                                           .arg(at, col.name)
                                           .arg(nameColumn[size_t(other)])
                                     : QStringLiteral("%1: duplicate column name (also column %2)")
                                           .arg(at)
                                           .arg(nameColumn[size_t(other)]));
        names << col.name;
        nameColumn.push_back(i + 1);

        if (isTime) {
            col.role = Role::Time;
            header.timeColumn = i;
            const auto format = parseTimeFormat(unit);
            if (!format) return makeError(QStringLiteral("%1: %2").arg(at, format.message()));
            header.timeFormat = *format;
            col.unit = QStringLiteral("s");
            if (!format->absolute() && format->scale != 1.0) {
                col.convert = true;
                col.scale = format->scale;
                col.sourceUnit = format->name;
            }
            header.columns.push_back(col);
            continue;
        }
        QString target;
        if (!table && longLayoutOf(kindName) && col.name == QLatin1String("beacon")) {
            col.role = Role::Id;
        } else if (table && (col.name == QLatin1String("id") || col.name == QLatin1String("name") ||
                             col.name == QLatin1String("label"))) {
            col.role = Role::Text;
        } else if (kind) {
            target = kind->unitFor(col.name);
        }
        if (target.isEmpty() && mappedUnit && col.role == Role::Number)
            target = siUnitOf(unit);  // a mapped unit says what the column is: store it in SI
        if (col.role == Role::Id || col.role == Role::Text) {
            if (!unit.isEmpty())
                return makeError(QStringLiteral("%1: an id column has no unit (got '%2')").arg(at, unit));
        } else if (!target.isEmpty()) {
            // A kind may read a column without a unit in a conventional one (barometer: hPa).
            if (unit.trimmed().isEmpty() && kind && !kind->assumedUnitFor(col.name).isEmpty())
                unit = kind->assumedUnitFor(col.name);
            const auto conversion = conversionTo(unit, target);
            if (!conversion) return makeError(QStringLiteral("%1: %2").arg(at, conversion.message()));
            col.unit = conversion->si;
            col.scale = conversion->scale;
            col.offset = conversion->offset;
            col.convert = col.scale != 1.0 || col.offset != 0.0;
            col.sourceUnit = unit;
        } else {
            col.unit = unit;  // a column the kind does not know keeps what it says
        }
        header.columns.push_back(col);
    }

    if (!options.date.isEmpty()) {
        const QByteArray date = options.date.trimmed().toUtf8();
        if (!parseIsoDate(std::string_view(date.constData(), size_t(date.size())), header.dateDays))
            return makeError(QStringLiteral("date '%1': expected YYYY-MM-DD").arg(options.date));
        header.haveDate = true;
    }
    if (header.timeFormat.kind == TimeKind::Clock && !header.haveDate) {
        // Clock times take their date from a date column of the file.
        for (size_t i = 0; i < header.columns.size(); ++i) {
            ColumnPlan& col = header.columns[i];
            if (col.role == Role::Number && col.name.compare(QLatin1String("date"), Qt::CaseInsensitive) == 0 &&
                col.unit.isEmpty()) {
                col.role = Role::Date;
                header.dateColumn = int(i);
                names.removeAll(col.name);
                break;
            }
        }
    }
    if (options.dropUnmapped) {
        for (ColumnPlan& col : header.columns)
            if (col.role == Role::Number && col.name.compare(QLatin1String("date"), Qt::CaseInsensitive) == 0 &&
                !findMapping(options, col.source) && !isKindColumn(kind, col.name, table)) {
                col.role = Role::Skip;
                names.removeAll(col.name);
            }
    }
    const QString known = names.join(QStringLiteral(", "));
    if (!table && header.timeColumn < 0)
        return makeError(QStringLiteral("%1:%2: no 't' column (time in seconds); columns: %3")
                             .arg(file)
                             .arg(header.line)
                             .arg(known));
    if (kind) {
        for (const QString& required : kind->requiredColumns)
            if (!names.contains(required))
                return makeError(QStringLiteral("%1:%2: kind '%3' needs a column '%4'; columns: %5")
                                     .arg(file)
                                     .arg(header.line)
                                     .arg(kind->kind, required, known));
        if (kind->kind == QLatin1String("gnss") && !(names.contains("lat") && names.contains("lon")) &&
            !(names.contains("x") && names.contains("y")))
            return makeError(
                QStringLiteral("%1:%2: kind 'gnss' needs columns lat, lon (WGS84) or x, y (local ENU); columns: %3")
                    .arg(file)
                    .arg(header.line)
                    .arg(known));
    }
    if (const LongLayout* layout = longLayoutOf(kindName); layout && !table && names.size() != 3)
        return makeError(QStringLiteral("%1:%2: kind '%3' has the columns t, beacon, %4 (long format); columns: %5")
                             .arg(file)
                             .arg(header.line)
                             .arg(kindName, layout->value, known));
    if (names.size() < (table ? 1 : 2))
        return makeError(QStringLiteral("%1:%2: no data columns; columns: %3").arg(file).arg(header.line).arg(known));
    return header;
}

}  // namespace csv

QString siUnitOf(const QString& unit) {
    static const char* const kSi[] = {"s", "m",    "m/s", "m/s^2", "rad/s", "rad", "uT",
                                      "1", "degC", "Hz",  "dB",    "dBm",   "Pa",  "lx"};
    if (unit.trimmed().isEmpty()) return {};
    for (const char* si : kSi)
        if (conversionTo(unit, QLatin1String(si))) return QLatin1String(si);
    return {};
}

QStringList mappedColumnNames(const QStringList& headerCells, const ImportOptions& options) {
    QStringList names;
    for (const QString& cell : headerCells) {
        QString name, unit;
        splitNameAndUnit(cell, name, unit);
        const ColumnMapping* m = csv::findMapping(options, name);
        if ((m && m->skip) || (!m && csv::isUnnamedColumn(name))) continue;
        if (!options.timeColumn.isEmpty() && name == options.timeColumn)
            names << QStringLiteral("t");
        else if (m && !m->channel.trimmed().isEmpty())
            names << m->channel.trimmed();
        else if (const QString known = csv::knownChannelName(name); !known.isEmpty())
            names << known;
        else
            names << name;
    }
    return names;
}

QString inferCsvKind(const QStringList& names) {
    auto has = [&](const char* n) { return names.contains(QLatin1String(n)); };
    auto hasPrefix = [&](const char* p) {
        return std::any_of(names.begin(), names.end(),
                           [p](const QString& n) { return n.startsWith(QLatin1String(p)); });
    };
    if (has("beacon") && has("dt")) return QStringLiteral("lps-tdoa");
    if (has("beacon") && has("range")) return QStringLiteral("lps-range");
    if (has("id") && has("x") && has("y") && !has("t")) return QStringLiteral("beacons");
    if (hasPrefix("acc_") || hasPrefix("gyr_") || hasPrefix("mag_")) return QStringLiteral("imu");
    if (has("qw") && has("qx") && has("qy") && has("qz")) return QStringLiteral("orientation");
    if (has("lat") && has("lon")) return QStringLiteral("gnss");
    if (has("pressure") && !has("x")) return QStringLiteral("barometer");
    if (has("x") && has("y")) return QStringLiteral("lps-position");
    return {};
}

}  // namespace athlos
