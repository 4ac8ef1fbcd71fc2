#include "core/io/RosImporter.h"

#include "core/io/CsvImporter.h"
#include "core/io/CsvReader.h"

#include <QFileInfo>
#include <charconv>
#include <cmath>
#include <map>

namespace athlos {
namespace {

constexpr double kSamePosition = 1e-3;  // m: an anchor's surveyed position repeats in every row

QString stripped(const QString& name) { return name.startsWith(QLatin1String("field.")) ? name.mid(6) : name; }

QString firstOf(const QStringList& sources, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (sources.contains(QLatin1String(n))) return QLatin1String(n);
    return {};
}

bool isNumber(const std::string& text) {
    if (text.empty()) return true;  // an empty cell says nothing
    double v = 0.0;
    const char* b = text.data();
    const char* e = b + text.size();
    const auto [q, ec] = std::from_chars(b + (*b == '+' ? 1 : 0), e, v);
    return ec == std::errc() && q == e;
}

// Beacons from per-row anchor positions: one row per id, the position checked to repeat.
Status collapseBeacons(Table& table, const QString& file, const QStringList& sources) {
    const TableColumn* id = table.column(QStringLiteral("id"));
    if (!id || !id->isText) return makeError(QStringLiteral("%1: no anchor id column (field.id)").arg(file));
    std::vector<int> numeric;
    for (size_t c = 0; c < table.columns.size(); ++c)
        if (!table.columns[c].isText) numeric.push_back(int(c));
    std::map<QString, long long> firstRow;  // id → first row
    std::vector<long long> keep;
    for (long long r = 0; r < table.rows(); ++r) {
        const QString& key = id->texts.at(qsizetype(r));
        const auto [it, added] = firstRow.emplace(key, r);
        if (added) {
            keep.push_back(r);
            continue;
        }
        for (int c : numeric) {
            const TableColumn& col = table.columns[size_t(c)];
            const double a = col.numbers[size_t(it->second)], b = col.numbers[size_t(r)];
            if (std::abs(a - b) > kSamePosition)
                return makeError(
                    QStringLiteral("%1:%2:%3 (column '%4'): anchor '%5' has %4 = %6 here but %7 on line %8; "
                                   "a beacon table needs one position per anchor")
                        .arg(file)
                        .arg(r + 2)
                        .arg(sources.indexOf(QStringLiteral("field.") + col.name) + 1)
                        .arg(col.name, key)
                        .arg(b)
                        .arg(a)
                        .arg(it->second + 2));
        }
    }
    for (TableColumn& col : table.columns) {
        TableColumn kept{col.name, col.unit, col.isText, {}, {}};
        for (long long r : keep) {
            if (col.isText)
                kept.texts << col.texts.at(qsizetype(r));
            else
                kept.numbers.push_back(col.numbers[size_t(r)]);
        }
        col = std::move(kept);
    }
    return {};
}

}  // namespace

QString RosImporter::description() const {
    return QStringLiteral(
        "CSV exported from a ROS bag (%time,field.…; ns stamps): UWB ranges, anchors, NavSatFix, any message");
}

bool RosImporter::canRead(const QString&, const QByteArray& head) const {
    const qsizetype nl = head.indexOf('\n');
    const QByteArray first = head.left(nl < 0 ? head.size() : nl).trimmed();
    return first.startsWith("%time,") && first.contains(",field.");
}

Expected<ImportResult> RosImporter::read(const QString& file, const ImportOptions& options,
                                         const Progress& progress) const {
    MappedFile mapped;
    if (Status s = mapped.open(file); !s) return s.error();
    CsvReader peek(mapped.begin(), mapped.end());
    QStringList sources;
    if (!peek.readHeader(sources)) return makeError(QStringLiteral("%1: empty file (no header row)").arg(file));
    if (sources.isEmpty() || sources.front() != QLatin1String("%time"))
        return makeError(QStringLiteral("%1:%2:1: not a ROS CSV export (the header starts with '%3', not '%time')")
                             .arg(file)
                             .arg(peek.line())
                             .arg(sources.value(0)));
    std::vector<bool> text(size_t(sources.size()), false);  // text in the first data row: frame ids
    if (peek.nextRecord()) {
        std::string cell;
        for (qsizetype c = 0; c < sources.size() && peek.text(cell); ++c) text[size_t(c)] = !isNumber(cell);
    }

    const QString stamp = firstOf(sources, {"field.header.stamp", "field.stamp", "%time"});
    const QString range = firstOf(sources, {"field.distanceFromTag", "field.range", "field.distance"});
    const QString anchor = firstOf(sources, {"field.id", "field.anchor_id", "field.anchorId", "field.anchor"});
    QString kind = options.kind;
    if (kind.isEmpty()) {
        if (!range.isEmpty() && !anchor.isEmpty())
            kind = QStringLiteral("lps-range");
        else if (sources.contains(QLatin1String("field.latitude")) &&
                 sources.contains(QLatin1String("field.longitude")))
            kind = QStringLiteral("gnss");
        else {
            QStringList names;
            for (const QString& s : sources) names << stripped(s);
            kind = inferCsvKind(names);
        }
        if (kind.isEmpty())
            return makeError(QStringLiteral("%1: cannot tell the kind of data from the ROS fields (%2); give a kind")
                                 .arg(file, sources.join(QStringLiteral(", "))));
    }
    const bool table = kind == QLatin1String("beacons");
    const bool ranges = kind == QLatin1String("lps-range");
    if ((ranges || table) && anchor.isEmpty())
        return makeError(QStringLiteral("%1:1: kind '%2' needs the anchor id field (field.id); fields: %3")
                             .arg(file, kind, sources.join(QStringLiteral(", "))));
    if (ranges && range.isEmpty())
        return makeError(
            QStringLiteral("%1:1: kind 'lps-range' needs a distance field (field.distanceFromTag, field.range "
                           "or field.distance); fields: %2")
                .arg(file, sources.join(QStringLiteral(", "))));

    ImportOptions csv = options;
    csv.format = QStringLiteral("csv");
    csv.kind = kind;
    csv.timeColumn = table ? QString() : (options.timeColumn.isEmpty() ? stamp : options.timeColumn);
    csv.timeUnit = table ? QString() : (options.timeColumn.isEmpty() ? QStringLiteral("unix_ns") : options.timeUnit);
    auto userMapped = [&](const QString& source) {
        for (const ColumnMapping& m : options.columns)
            if (m.source == source) return true;
        return false;
    };
    for (qsizetype c = 0; c < sources.size(); ++c) {
        const QString& source = sources[c];
        if (userMapped(source) || source == csv.timeColumn) continue;
        const QString name = stripped(source);
        ColumnMapping m{source, {}, {}, false};
        if (ranges) {
            if (source == anchor)
                m.channel = QStringLiteral("beacon");
            else if (source == range)
                m.channel = QStringLiteral("range"), m.unit = QStringLiteral("m");
            else
                m.skip = true;  // the long form is t, beacon, range
        } else if (table) {
            if (source == anchor)
                m.channel = QStringLiteral("id");
            else if (name == QLatin1String("x") || name == QLatin1String("y") || name == QLatin1String("z"))
                m.channel = name;
            else
                m.skip = true;
        } else if (text[size_t(c)] || source.startsWith(QLatin1Char('%')) || name == QLatin1String("header.seq") ||
                   name == QLatin1String("header.stamp") || name == QLatin1String("stamp")) {
            m.skip = true;  // frame ids, sequence numbers and the stamps that are not t
        } else if (name == QLatin1String("status.status")) {
            m.channel = QStringLiteral("fix_status");
        } else {
            const QString known = csv::knownChannelName(name);  // latitude → lat, ...
            m.channel = known.isEmpty() ? name : known;
        }
        csv.columns.push_back(m);
    }

    auto result = CsvImporter().read(file, csv, progress);
    if (!result) return result;
    for (ImportedItem& item : result->items) {
        if (auto* t = std::get_if<Table>(&item.item)) {
            if (Status s = collapseBeacons(*t, file, sources); !s) return s.error();
            t->attributes.insert(QStringLiteral("source_format"), QStringLiteral("ros"));
        } else {
            std::get<Stream>(item.item).info().attributes.insert(QStringLiteral("source_format"),
                                                                 QStringLiteral("ros"));
        }
    }
    return result;
}

}  // namespace athlos
