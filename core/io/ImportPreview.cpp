#include "core/io/ImportPreview.h"

#include "core/io/CsvImporter.h"
#include "core/io/CsvReader.h"
#include "core/io/TimeFormats.h"
#include "core/model/StreamKinds.h"
#include "core/util/Units.h"

#include <QFileInfo>
#include <QHash>
#include <charconv>

namespace athlos {
namespace {

// Lower case without separators: "Gyro X" → "gyrox", "acc_x" → "accx".
QString normalized(const QString& name) {
    QString n;
    for (const QChar c : name)
        if (c.isLetterOrNumber()) n += c.toLower();
    return n;
}

bool isNumberCell(const QString& cell) {
    const QString c = cell.trimmed();
    if (c.isEmpty() || c.compare(QLatin1String("nan"), Qt::CaseInsensitive) == 0) return true;
    bool ok = false;
    c.toDouble(&ok);
    if (!ok) QString(c).replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&ok);
    return ok;
}

// Time columns whose name carries the unit ("time_ms", "timestamp_us").
QString timeUnitFromName(const QString& name) {
    const QString n = normalized(name);
    for (const char* unit : {"ms", "us", "ns"})
        for (const char* stem : {"time", "timestamp", "t"})
            if (n == QLatin1String(stem) + QLatin1String(unit)) return QLatin1String(unit);
    return {};
}

Expected<ImportPreview> previewCsv(const QString& file, int maxRows, const QString& forcedKind) {
    MappedFile mapped;
    if (Status s = mapped.open(file); !s) return s.error();
    CsvReader reader(mapped.begin(), mapped.end());
    QStringList cells;
    if (!reader.readHeader(cells)) return makeError(QStringLiteral("%1: empty file (no header row)").arg(file));
    ImportPreview preview;
    preview.file = file;
    preview.format = QStringLiteral("csv");
    preview.mappable = true;
    preview.headerLine = reader.line();
    std::string cell;
    while (int(preview.rows.size()) < maxRows && reader.nextRecord()) {
        QStringList row;
        while (reader.text(cell)) row << QString::fromUtf8(cell.data(), qsizetype(cell.size()));
        reader.finishRecord();
        preview.rows.push_back(row);
    }

    QStringList channels;
    bool haveTime = false;
    for (const QString& header : cells) {
        PreviewColumn col;
        col.header = header;
        splitNameAndUnit(header, col.source, col.unit);
        col.channel = detectChannel(col.source);
        if (col.channel == QLatin1String("t")) {
            if (haveTime)
                col.channel.clear();  // a second time-like column ("date", "time_utc") stays as it is
            else if (col.unit.isEmpty())
                col.unit = timeUnitFromName(col.source);
            haveTime = haveTime || !col.channel.isEmpty();
        }
        if (col.channel.isEmpty()) col.channel = col.source;
        col.time = col.channel == QLatin1String("t");
        channels << col.channel;
        preview.columns.push_back(col);
    }
    preview.kind = forcedKind.isEmpty() ? inferCsvKind(channels) : forcedKind;
    const StreamKind* kind = findStreamKind(preview.kind);
    for (PreviewColumn& col : preview.columns) {
        const QString rule = kind ? kind->unitFor(col.channel) : QString();
        // As the importer does: a header unit of a column the kind has no rule for is kept as it is
        // (a mapped unit is converted: storedUnitFor).
        col.storedUnit = col.time ? QStringLiteral("s") : !rule.isEmpty() ? rule : col.unit;
    }
    return preview;
}

// Formats whose importer decides the streams (HDF5, two header rows, NMEA): import in memory and
// describe the result.
Expected<ImportPreview> previewImported(const QString& file, const Importer& importer, int maxRows,
                                        const QString& kind) {
    ImportOptions options;
    options.format = importer.format();
    options.kind = kind;
    options.target = QStringLiteral("preview");
    auto result = importFile(file, options);
    if (!result) return result.error();
    ImportPreview preview;
    preview.file = file;
    preview.format = importer.format();
    std::vector<std::shared_ptr<const StreamData>> data;
    std::vector<const Stream*> streams;
    for (const ImportedItem& item : result->items) {
        const QString name = item.path.section(QLatin1Char('/'), 1);
        preview.items << name;
        if (const auto* stream = std::get_if<Stream>(&item.item)) {
            auto d = stream->data();
            if (!d) return d.error();
            data.push_back(*d);
            streams.push_back(stream);
            if (preview.kind.isEmpty()) preview.kind = stream->info().kind;
        }
    }
    if (streams.empty()) return preview;
    const bool prefix = streams.size() > 1;
    preview.columns.push_back({QStringLiteral("t"), QStringLiteral("t"), QStringLiteral("s"), QStringLiteral("t"),
                               QStringLiteral("s"), true});
    for (const Stream* stream : streams) {
        const QJsonObject sourceUnits = stream->info().attributes.value(QStringLiteral("source_units")).toObject();
        for (const Column& c : stream->info().columns) {
            const QString name = prefix ? stream->info().name + QLatin1Char('/') + c.name : c.name;
            preview.columns.push_back({name, name, sourceUnits.value(c.name).toString(c.unit), c.name, c.unit, false});
        }
    }
    const size_t rows = std::min(data.front()->rows(), size_t(std::max(0, maxRows)));
    for (size_t r = 0; r < rows; ++r) {
        QStringList row{QString::number(data.front()->t[r], 'g', 10)};
        for (const auto& d : data)
            for (int c = 0; c < d->columns; ++c)
                row << (r < d->rows() ? QString::number(d->at(r, c), 'g', 8) : QString());
        preview.rows.push_back(row);
    }
    return preview;
}

}  // namespace

QString detectChannel(const QString& name) {
    const QString trimmed = name.trimmed();
    if (trimmed == QLatin1String("t") || trimmed == QLatin1String("beacon") || trimmed == QLatin1String("id"))
        return trimmed;
    for (const StreamKind& kind : streamKinds())  // interchange names are their own channel
        if (!kind.unitFor(trimmed).isEmpty()) return trimmed;

    static const QHash<QString, QString> exact{
        {"time", "t"},          {"timestamp", "t"},   {"times", "t"},         {"sec", "t"},
        {"seconds", "t"},       {"timesec", "t"},     {"timess", "t"},        {"elapsed", "t"},
        {"elapsedtime", "t"},   {"timems", "t"},      {"timestampms", "t"},   {"tms", "t"},
        {"timeus", "t"},        {"timestampus", "t"}, {"latitude", "lat"},    {"longitude", "lon"},
        {"lng", "lon"},         {"long", "lon"},      {"altitude", "alt"},    {"height", "alt"},
        {"elevation", "alt"},   {"quatw", "qw"},      {"quaternionw", "qw"},  {"quatx", "qx"},
        {"quaternionx", "qx"},  {"quaty", "qy"},      {"quaterniony", "qy"},  {"quatz", "qz"},
        {"quaternionz", "qz"},  {"posx", "x"},        {"posy", "y"},          {"posz", "z"},
        {"positionx", "x"},     {"positiony", "y"},   {"positionz", "z"},     {"temperature", "temp"},
        {"tdoa", "dt"},         {"anchor", "beacon"}, {"anchorid", "beacon"}, {"beaconid", "beacon"},
        {"satellites", "sats"}, {"numsats", "sats"},
    };
    const QString n = normalized(trimmed);
    if (const auto it = exact.constFind(n); it != exact.cend()) return *it;
    // Sensor axes: a stem and a final x, y or z ("AccX", "acc-y", "Gyroscope Z", "ax").
    if (n.size() >= 2) {
        const QChar axis = n.back();
        if (axis == QLatin1Char('x') || axis == QLatin1Char('y') || axis == QLatin1Char('z')) {
            const QString stem = n.left(n.size() - 1);
            static const QHash<QString, QString> stems{
                {"a", "acc_"},
                {"acc", "acc_"},
                {"accel", "acc_"},
                {"acceleration", "acc_"},
                {"accelerometer", "acc_"},
                {"g", "gyr_"},
                {"gyr", "gyr_"},
                {"gyro", "gyr_"},
                {"gyroscope", "gyr_"},
                {"angularvelocity", "gyr_"},
                {"w", "gyr_"},
                {"omega", "gyr_"},
                {"m", "mag_"},
                {"mag", "mag_"},
                {"magnetometer", "mag_"},
                {"magneticfield", "mag_"},
                {"magn", "mag_"},
                {"v", "v"},
                {"vel", "v"},
                {"velocity", "v"},
            };
            if (const auto it = stems.constFind(stem); it != stems.cend()) return *it + axis;
        }
    }
    return {};
}

Expected<ImportPreview> previewFile(const QString& file, const QString& format, int maxRows, const QString& kind) {
    if (!QFileInfo(file).isFile()) return makeError(QStringLiteral("%1: no such file").arg(file));
    const auto importer = chooseImporter(file, format);
    if (!importer) return importer.error();
    if ((*importer)->format() == QLatin1String("csv")) return previewCsv(file, maxRows, kind);
    return previewImported(file, **importer, maxRows, kind);
}

Expected<QString> storedUnitFor(const QString& kindName, const QString& channel, const QString& unit, bool time) {
    if (time) {  // any time format (ms, unix_ns, iso, hh:mm:ss, ...) is stored as t in s
        const auto format = parseTimeFormat(unit);
        if (!format) return format.error();
        return QStringLiteral("s");
    }
    const StreamKind* kind = findStreamKind(kindName);
    const QString target = kind ? kind->unitFor(channel) : QString();
    if (!target.isEmpty()) {
        const auto conversion = conversionTo(unit, target);
        if (!conversion) return conversion.error();
        return conversion->si;
    }
    if (unit.trimmed().isEmpty()) return QString();
    const QString si = siUnitOf(canonicalUnit(unit));
    if (si.isEmpty()) return makeError(QStringLiteral("unknown unit '%1'").arg(unit));
    return si;
}

ImportOptions suggestedOptions(const ImportPreview& preview) {
    ImportOptions options;
    options.format = preview.format;
    options.kind = preview.kind;
    if (!preview.mappable) return options;
    for (size_t c = 0; c < preview.columns.size(); ++c) {
        const PreviewColumn& col = preview.columns[c];
        // A text column (a date, a label) is skipped; a number column with a bad cell is not, so
        // the check reports the cell.
        bool anyNumber = false, anyText = false;
        for (const QStringList& row : preview.rows)
            if (qsizetype(c) < row.size()) (isNumberCell(row[qsizetype(c)]) ? anyNumber : anyText) = true;
        const bool numeric = anyNumber || !anyText;
        const bool idColumn = col.channel == QLatin1String("beacon") || col.channel == QLatin1String("id") ||
                              col.channel == QLatin1String("name") || col.channel == QLatin1String("label");
        if (col.time) {
            if (col.source != QLatin1String("t")) options.timeColumn = col.source;
            if (col.unit != QLatin1String("s") && !col.unit.isEmpty()) options.timeUnit = col.unit;
        } else if (!numeric && !idColumn) {
            options.columns.push_back({col.source, {}, {}, true});  // text such as a date: not a channel
        } else if (col.channel != col.source) {
            options.columns.push_back({col.source, col.channel, {}, false});
        }
    }
    return options;
}

ImportCheck checkImport(const QString& file, const ImportOptions& options, const Progress& progress) {
    ImportCheck check;
    check.file = file;
    auto result = importFile(file, options, progress);
    if (!result) {
        check.cancelled = progress.isCancelled();
        check.errors << result.message();
        return check;
    }
    check.warnings = result->warnings;
    for (const ImportedItem& item : result->items) {
        check.items << item.path;
        if (const auto* stream = std::get_if<Stream>(&item.item))
            check.samples += stream->info().rows;
        else
            check.samples += std::get<Table>(item.item).rows();
    }
    return check;
}

}  // namespace athlos
