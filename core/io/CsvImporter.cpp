// CSV import, put together: the header is planned (CsvColumns.h), the records parsed (CsvRecords.h),
// time order repaired (TimeOrder.h); this file builds the stream or table of the kind.
#include "core/io/CsvImporter.h"

#include "core/io/AnnotationIo.h"
#include "core/io/CsvColumns.h"
#include "core/io/CsvReader.h"
#include "core/io/CsvRecords.h"
#include "core/io/ImportPreview.h"
#include "core/io/TdoaLayout.h"
#include "core/io/TimeFormats.h"
#include "core/io/TimeOrder.h"
#include "core/model/StreamKinds.h"
#include "core/util/Units.h"

#include <QFileInfo>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

namespace athlos {
namespace {

using namespace csv;

constexpr double kGyrPlausibleMax = 35.0;  // rad/s; human motion stays well below (35 rad/s ≈ 2000 deg/s)

// Long rows (t, beacon index, dt or range) → the wide stream of TdoaLayout.h.
Expected<Stream> longStream(const StreamData& rows, const TimeOrigin& origin, const Header& header,
                            const std::vector<std::string>& ids, const LongLayout& layout) {
    int beacon = -1, dt = -1, dtFileColumn = 0, c = 0;
    for (size_t i = 0; i < header.columns.size(); ++i) {
        const auto& col = header.columns[i];
        if (!isDataRole(col.role)) continue;
        if (col.name == QLatin1String("beacon"))
            beacon = c;
        else if (col.name == layout.value)
            dt = c, dtFileColumn = int(i) + 1;
        ++c;
    }
    std::vector<TdoaSample> samples(rows.rows());
    for (size_t r = 0; r < rows.rows(); ++r) {
        if (std::isnan(rows.at(r, dt)))
            return makeError(QStringLiteral("%1: empty %2")
                                 .arg(where(origin.file, origin.lines[r], dtFileColumn, layout.value), layout.value));
        const std::string& id = ids[size_t(rows.at(r, beacon))];
        samples[r] = {rows.t[r], QString::fromUtf8(id.data(), qsizetype(id.size())), rows.at(r, dt), origin.lines[r]};
    }
    return longStreamFromSamples(samples, origin.file, layout);
}

StreamData withColumn(const StreamData& data, const std::vector<double>& column) {
    StreamData out(data.rows(), data.columns + 1);
    out.t = data.t;
    for (size_t r = 0; r < data.rows(); ++r) {
        std::copy_n(data.values.begin() + ptrdiff_t(r * size_t(data.columns)), data.columns,
                    out.values.begin() + ptrdiff_t(r * size_t(out.columns)));
        out.at(r, data.columns) = column[r];
    }
    return out;
}

StreamData withoutLastColumn(const StreamData& data) {
    StreamData out(data.rows(), data.columns - 1);
    out.t = data.t;
    for (size_t r = 0; r < data.rows(); ++r)
        std::copy_n(data.values.begin() + ptrdiff_t(r * size_t(data.columns)), out.columns,
                    out.values.begin() + ptrdiff_t(r * size_t(out.columns)));
    return out;
}

// The distinct labels, named by ImportOptions::labelNames (numbers match numerically: "1.0" is "1"),
// and each record's index into them (NaN: no label).
Expected<std::pair<QStringList, std::vector<double>>> nameLabels(const ParsedLabels& labels,
                                                                 const ImportOptions& options, const TimeOrigin& origin,
                                                                 const QString& column, int fileColumn) {
    QStringList names;
    std::vector<double> index(labels.size(), std::numeric_limits<double>::quiet_NaN());
    std::unordered_map<std::string, int> seen;
    auto lookup = [&](const QString& text) -> std::optional<QString> {
        if (options.labelNames.empty()) return text;
        if (const auto it = options.labelNames.find(text); it != options.labelNames.end()) return it->second;
        bool ok = false;
        const double v = text.toDouble(&ok);
        if (ok)
            for (const auto& [key, name] : options.labelNames)
                if (bool keyOk = false; key.toDouble(&keyOk) == v && keyOk) return name;
        return std::nullopt;
    };
    for (size_t r = 0; r < labels.size(); ++r) {
        if (labels[r].empty()) continue;
        const auto [it, added] = seen.try_emplace(labels[r], int(names.size()));
        if (added) {
            const QString text = QString::fromUtf8(labels[r].data(), qsizetype(labels[r].size()));
            const auto name = lookup(text);
            if (!name) {
                QStringList keys;
                for (const auto& [key, value] : options.labelNames) keys << key + QLatin1Char('=') + value;
                return makeError(QStringLiteral("%1: label '%2' has no name in the label names (%3)")
                                     .arg(where(origin.file, origin.lines[r], fileColumn, column), text,
                                          keys.join(QStringLiteral(", "))));
            }
            names << *name;
        }
        index[r] = it->second;
    }
    return std::pair{names, index};
}

// The absolute start and time format of a parsed stream (TimeFormats.h); t starts at 0 for absolute
// formats. Warnings for assumptions (no zone, no date) and an implausible sampling rate.
Expected<QJsonObject> timeAttributesOf(StreamData& data, const Header& header, const ParsedTime& time,
                                       const ImportOptions& options, const TimeOrigin& origin, QStringList& warnings) {
    const TimeFormat& format = header.timeFormat;
    TimeBase base = time.base;
    const QString what = QStringLiteral("%1 (column '%2')").arg(origin.file, origin.columnName);
    if (format.absolute()) {
        startAtZero(data.t, base);
        if (!options.start.isEmpty())
            warnings << QStringLiteral("%1: the times are absolute (%2); the start option is ignored")
                            .arg(what, format.name);
    } else if (!options.start.isEmpty()) {
        const auto start = parseUtc(options.start);
        if (!start) return makeError(QStringLiteral("start: %1").arg(start.message()));
        base.known = true;
        base.t0Ns = *start;
    }
    if (time.missingZone)
        warnings << QStringLiteral("%1: date-times without a zone (Z or +hh:mm) are taken as UTC").arg(what);
    if (base.timeOfDayOnly)
        warnings << QStringLiteral(
                        "%1: clock times without a date; the start is known as a time of day (%2) only "
                        "(give the date: --date YYYY-MM-DD)")
                        .arg(what, formatTimeOfDay(base.t0Ns));
    if (const QString w = samplingRateWarning(data.t, format.name, what); !w.isEmpty()) warnings << w;
    QJsonObject attributes;
    writeTimeAttributes(attributes, base, format.name);
    if (format.kind == TimeKind::Uptime)
        attributes.insert(QStringLiteral("time_base"), QStringLiteral("device uptime"));
    return attributes;
}

Expected<ImportResult> readStream(CsvReader& reader, const MappedFile& mapped, const QString& file,
                                  const ImportOptions& options, const QString& kindName, const StreamKind* kind,
                                  const Progress& progress) {
    auto header = planHeader(reader, file, options, kindName, kind, false);
    if (!header) return header.error();
    StreamData data;
    TimeOrigin origin{
        file, header->timeColumn + 1, options.timeColumn.isEmpty() ? QStringLiteral("t") : options.timeColumn, {}};
    std::vector<std::string> ids;
    ParsedTime time;
    ParsedLabels labels;
    const bool labelled = header->labelColumn >= 0;
    if (Status s = parseStreamRecords(reader, mapped, file, *header, progress, data, origin.lines, ids, time,
                                      labelled ? &labels : nullptr);
        !s)
        return s.error();
    // The labels ride along as a last column through the time repair.
    QStringList labelNames;
    if (labelled) {
        auto names = nameLabels(labels, options, origin, header->columns[size_t(header->labelColumn)].source,
                                header->labelColumn + 1);
        if (!names) return names.error();
        labelNames = std::move(names->first);
        data = withColumn(data, names->second);
    }

    ImportResult result;
    const LongLayout* layout = longLayoutOf(kindName);
    if (Status s = repairTimeOrder(data, origin, options.timeRepair, layout != nullptr, result.warnings); !s)
        return s.error();
    auto timeAttributes = timeAttributesOf(data, *header, time, options, origin, result.warnings);
    if (!timeAttributes) return timeAttributes.error();
    if (labelled) {
        QStringList perRow;
        perRow.reserve(qsizetype(data.rows()));
        for (size_t r = 0; r < data.rows(); ++r) {
            const double index = data.at(r, data.columns - 1);
            perRow << (std::isnan(index) ? QString() : labelNames[qsizetype(index)]);
        }
        data = withoutLastColumn(data);
        result.annotations[QString()] = labelRuns(data.t, perRow, QStringLiteral("import"), QFileInfo(file).fileName());
        if (result.annotations[QString()].empty())
            result.warnings << QStringLiteral("%1 (column '%2'): no labels").arg(file, options.labelColumn);
    }

    QJsonObject sourceUnits;
    Columns columns;
    for (const auto& col : header->columns) {
        if (col.convert) sourceUnits.insert(col.name, col.sourceUnit);
        if (isDataRole(col.role)) columns.push_back({col.name, col.unit});
    }
    if (layout) {
        auto stream = longStream(data, origin, *header, ids, *layout);
        if (!stream) return stream.error();
        stream->info().name = kind->defaultName;
        if (!sourceUnits.isEmpty()) stream->info().attributes.insert(QStringLiteral("source_units"), sourceUnits);
        for (auto it = timeAttributes->begin(); it != timeAttributes->end(); ++it)
            stream->info().attributes.insert(it.key(), it.value());
        result.items.push_back({kind->defaultName, std::move(*stream)});
        return result;
    }

    StreamInfo info;
    info.kind = kindName;
    info.name = kind ? kind->defaultName : kindName;
    info.frame = kind ? kind->defaultFrame : QString();
    info.columns = std::move(columns);
    if (!sourceUnits.isEmpty()) info.attributes.insert(QStringLiteral("source_units"), sourceUnits);
    for (auto it = timeAttributes->begin(); it != timeAttributes->end(); ++it)
        info.attributes.insert(it.key(), it.value());
    if (kindName == QLatin1String("gnss") && info.columnIndex(QStringLiteral("lat")) < 0)
        info.frame = QStringLiteral("ENU");

    if (kindName == QLatin1String("imu")) {
        for (int c = 0; c < data.columns; ++c) {
            const Column& col = info.columns[c];
            if (!col.name.startsWith(QLatin1String("gyr_"))) continue;
            double peak = 0.0;
            for (size_t r = 0; r < data.rows(); ++r)
                if (const double a = std::abs(data.at(r, c)); a > peak)  // NaN compares false
                    peak = a;
            if (peak > kGyrPlausibleMax)
                result.warnings << QStringLiteral(
                                       "%1: column '%2' reaches %3 rad/s, implausible for rad/s; if the "
                                       "file is in deg/s, say so in the header: '%2 [deg/s]'")
                                       .arg(file, col.name, QString::number(peak, 'f', 1));
        }
    }
    result.items.push_back({info.name, Stream(std::move(info), std::move(data))});
    return result;
}

Expected<ImportResult> readTable(CsvReader& reader, const QString& file, const ImportOptions& options,
                                 const QString& kindName, const StreamKind* kind) {
    auto header = planHeader(reader, file, options, kindName, kind, true);
    if (!header) return header.error();
    Table table;
    table.kind = kindName;
    table.name = kind ? kind->defaultName : kindName;
    if (kind && !kind->defaultFrame.isEmpty()) table.attributes.insert(QStringLiteral("frame"), kind->defaultFrame);
    if (Status s = parseTableRecords(reader, file, *header, table); !s) return s.error();
    ImportResult result;
    result.items.push_back({table.name, std::move(table)});
    return result;
}

// Real exports name their time column "Time", "Timestamp", "Elapsed Time", ... and write clock
// times, ISO date-times or epochs in it. Without a 't' column and without --time-column, the first
// such column (by name, detectChannel) is the time column, in the unit of its header or else in
// the format its first value shows (guessTimeFormat). The returned note says what was chosen.
QString chooseTimeColumn(const MappedFile& mapped, const QString& file, ImportOptions& options) {
    if (!options.timeColumn.isEmpty()) return {};
    CsvReader reader(mapped.begin(), mapped.end());
    QStringList cells;
    if (!reader.readHeader(cells)) return {};
    int column = -1;
    QString source, unit;
    for (int i = 0; i < int(cells.size()); ++i) {
        QString name, headerUnit;
        splitNameAndUnit(cells[i], name, headerUnit);
        if (name == QLatin1String("t")) return {};  // the interchange layout
        const bool mapped = std::any_of(options.columns.begin(), options.columns.end(),
                                        [&](const ColumnMapping& m) { return m.source == name; });
        if (column >= 0 || mapped || name == options.labelColumn || detectChannel(name) != QLatin1String("t")) continue;
        column = i;
        source = name;
        unit = headerUnit;
    }
    if (column < 0) return {};
    options.timeColumn = source;
    if (!options.timeUnit.isEmpty() || !unit.isEmpty()) return {};
    QString first;
    if (reader.nextRecord()) {
        std::string cell;
        for (int i = 0; i <= column && reader.text(cell); ++i)
            if (i == column) first = QString::fromUtf8(cell.data(), qsizetype(cell.size()));
        reader.finishRecord();
    }
    options.timeUnit = guessTimeFormat(first);
    return QStringLiteral(
               "%1: column '%2' taken as the time column, %3 (from its first value '%4'); "
               "--time-column COL:FORMAT chooses another")
        .arg(QFileInfo(file).fileName(), source,
             options.timeUnit.isEmpty() ? QStringLiteral("in seconds") : QStringLiteral("format ") + options.timeUnit,
             first.trimmed().left(40));
}

}  // namespace

QString CsvImporter::description() const {
    return QStringLiteral("CSV interchange: header row, 't' in seconds, named columns with optional units");
}

bool CsvImporter::canRead(const QString& file, const QByteArray& head) const {
    return extensions().contains(QFileInfo(file).suffix().toLower()) && !head.contains('\0');
}

Expected<ImportResult> CsvImporter::read(const QString& file, const ImportOptions& options,
                                         const Progress& progress) const {
    static const QStringList repairs{"reject", "sort", "drop"};
    if (!repairs.contains(options.timeRepair))
        return makeError(QStringLiteral("unknown time repair '%1' (reject, sort or drop)").arg(options.timeRepair));
    MappedFile mapped;
    if (Status s = mapped.open(file); !s) return s.error();

    QString kindName = options.kind;
    const StreamKind* given = kindName.isEmpty() ? nullptr : lookupKind(kindName);
    ImportOptions chosen = options;
    const QString timeNote = given && given->table ? QString() : chooseTimeColumn(mapped, file, chosen);
    if (kindName.isEmpty()) {
        CsvReader peek(mapped.begin(), mapped.end());
        QStringList cells;
        if (!peek.readHeader(cells)) return makeError(QStringLiteral("%1: empty file (no header row)").arg(file));
        const QStringList names = mappedColumnNames(cells, chosen);
        kindName = inferCsvKind(names);
        if (kindName.isEmpty())
            return makeError(
                QStringLiteral("%1: cannot tell the kind of data from the columns (%2); give a kind (%3)")
                    .arg(file, names.join(QStringLiteral(", ")), streamKindNames().join(QStringLiteral(", "))));
    }
    const StreamKind* kind = lookupKind(kindName);
    if (kind) kindName = kind->kind;

    CsvReader reader(mapped.begin(), mapped.end());
    progress.report(0.0, QStringLiteral("Reading %1").arg(QFileInfo(file).fileName()));
    auto result = kind && kind->table ? readTable(reader, file, options, kindName, kind)
                                      : readStream(reader, mapped, file, chosen, kindName, kind, progress);
    if (!result) return result;
    if (!timeNote.isEmpty() && !(kind && kind->table)) result->warnings.prepend(timeNote);
    progress.report(1.0);
    return result;
}

}  // namespace athlos
