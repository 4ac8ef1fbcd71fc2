#include "core/io/CsvImporter.h"

#include "core/io/CsvReader.h"
#include "core/io/TdoaLayout.h"
#include "core/model/StreamKinds.h"
#include "core/util/Units.h"

#include <QFileInfo>
#include <QJsonArray>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace athlos {
namespace {

constexpr double kGyrPlausibleMax = 35.0;  // rad/s; human motion stays well below (35 rad/s ≈ 2000 deg/s)
constexpr qint64 kProgressBytes = 4 << 20;
constexpr char kPrefix[] = "%1:%2:%3 (column '%4')";

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

enum class Role { Time, Number, Id, Text, Skip };

struct ColumnPlan {
    QString name;
    QString source;        // name in the header (before mapping), for messages
    QString unit;          // unit stored with the column
    QString sourceUnit;    // unit in the header, if one was given
    Role role = Role::Number;
    bool convert = false;  // scale/offset differ from identity (kept apart so -0.0 survives)
    double scale = 1.0;
    double offset = 0.0;
};

const ColumnMapping* findMapping(const ImportOptions& options, const QString& source) {
    for (const ColumnMapping& m : options.columns)
        if (m.source == source)
            return &m;
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
                                 .arg(file).arg(line).arg(m.source, known));
        if (seen.contains(m.source))
            return makeError(QStringLiteral("column mapping: column '%1' is mapped twice").arg(m.source));
        seen << m.source;
        if (!m.skip && !m.unit.trimmed().isEmpty() && siUnitOf(canonicalUnit(m.unit)).isEmpty())
            return makeError(QStringLiteral("column mapping for '%1': unknown unit '%2'").arg(m.source, m.unit));
    }
    if (!options.timeColumn.isEmpty()) {
        if (!sources.contains(options.timeColumn))
            return makeError(QStringLiteral("%1:%2: time column '%3' is not in the file; columns: %4")
                                 .arg(file).arg(line).arg(options.timeColumn, known));
        if (const ColumnMapping* m = findMapping(options, options.timeColumn); m && m->skip)
            return makeError(QStringLiteral("time column '%1' is also marked to skip").arg(options.timeColumn));
    }
    if (!options.timeUnit.isEmpty()) {
        const auto c = conversionTo(options.timeUnit, QStringLiteral("s"));
        if (!c)
            return makeError(QStringLiteral("time unit: %1").arg(c.message()));
    }
    return {};
}

}  // namespace

QString siUnitOf(const QString& unit) {
    static const char* const kSi[] = {"s", "m", "m/s", "m/s^2", "rad/s", "rad", "uT", "1", "degC", "Hz", "dB", "dBm"};
    if (unit.trimmed().isEmpty())
        return {};
    for (const char* si : kSi)
        if (conversionTo(unit, QLatin1String(si)))
            return QLatin1String(si);
    return {};
}

QStringList mappedColumnNames(const QStringList& headerCells, const ImportOptions& options) {
    QStringList names;
    for (const QString& cell : headerCells) {
        QString name, unit;
        splitNameAndUnit(cell, name, unit);
        const ColumnMapping* m = findMapping(options, name);
        if (m && m->skip)
            continue;
        if (!options.timeColumn.isEmpty() && name == options.timeColumn)
            names << QStringLiteral("t");
        else
            names << (m && !m->channel.trimmed().isEmpty() ? m->channel.trimmed() : name);
    }
    return names;
}

QString inferCsvKind(const QStringList& names) {
    auto has = [&](const char* n) { return names.contains(QLatin1String(n)); };
    auto hasPrefix = [&](const char* p) {
        return std::any_of(names.begin(), names.end(), [p](const QString& n) { return n.startsWith(QLatin1String(p)); });
    };
    if (has("beacon") && has("dt"))
        return QStringLiteral("lps-tdoa");
    if (has("id") && has("x") && has("y") && !has("t"))
        return QStringLiteral("beacons");
    if (hasPrefix("acc_") || hasPrefix("gyr_") || hasPrefix("mag_"))
        return QStringLiteral("imu");
    if (has("qw") && has("qx") && has("qy") && has("qz"))
        return QStringLiteral("orientation");
    if (has("lat") && has("lon"))
        return QStringLiteral("gnss");
    if (has("x") && has("y"))
        return QStringLiteral("lps-position");
    return {};
}

namespace {

const StreamKind* lookupKind(const QString& kind) {
    if (const StreamKind* k = findStreamKind(kind))
        return k;
    for (const auto& k : streamKinds())  // "lps", "tdoa": the default names work as well
        if (k.defaultName == kind)
            return &k;
    return nullptr;
}

struct Header {
    std::vector<ColumnPlan> columns;
    long long line = 0;
    int timeColumn = -1;
};

Expected<Header> planHeader(CsvReader& reader, const QString& file, const ImportOptions& options,
                            const QString& kindName, const StreamKind* kind, bool table) {
    Header header;
    QStringList cells;
    if (!reader.readHeader(cells))
        return makeError(QStringLiteral("%1: empty file (no header row)").arg(file));
    header.line = reader.line();
    QStringList sources;
    for (const QString& cell : cells) {
        QString name, unit;
        splitNameAndUnit(cell, name, unit);
        sources << name;
    }
    if (Status s = checkMapping(options, sources, file, header.line); !s)
        return s.error();
    QStringList names;
    std::vector<int> nameColumn;  // file column (1-based) of each name, for messages
    for (int i = 0; i < cells.size(); ++i) {
        ColumnPlan col;
        QString unit;
        splitNameAndUnit(cells[i], col.name, unit);
        col.source = col.name;
        const QString at = where(file, header.line, i + 1, col.name);
        if (col.name.isEmpty())
            return makeError(QStringLiteral("%1:%2:%3: column %3 has no name").arg(file).arg(header.line).arg(i + 1));
        const ColumnMapping* mapping = findMapping(options, col.name);
        if (mapping && mapping->skip) {
            col.role = Role::Skip;
            header.columns.push_back(col);
            continue;
        }
        bool mappedUnit = false;
        if (mapping && !mapping->unit.trimmed().isEmpty()) {
            unit = canonicalUnit(mapping->unit);
            mappedUnit = true;
        }
        const bool isTime = !table && (options.timeColumn.isEmpty() ? col.name == QLatin1String("t")
                                                                    : col.name == options.timeColumn);
        if (mapping && !mapping->channel.trimmed().isEmpty())
            col.name = mapping->channel.trimmed();
        if (isTime) {
            col.name = QStringLiteral("t");
            if (!options.timeUnit.isEmpty())
                unit = canonicalUnit(options.timeUnit);
        } else if (!table && !options.timeColumn.isEmpty() && col.name == QLatin1String("t")) {
            return makeError(QStringLiteral("%1: the name 't' is taken by the time column '%2'").arg(at, options.timeColumn));
        }
        if (const qsizetype other = names.indexOf(col.name); other >= 0)
            return makeError(mapping ? QStringLiteral("%1: duplicate channel '%2' (also column %3)").arg(at, col.name).arg(nameColumn[size_t(other)])
                                     : QStringLiteral("%1: duplicate column name (also column %2)").arg(at).arg(nameColumn[size_t(other)]));
        names << col.name;
        nameColumn.push_back(i + 1);

        QString target;
        if (isTime) {
            col.role = Role::Time;
            header.timeColumn = i;
            target = QStringLiteral("s");
        } else if (!table && kindName == QLatin1String("lps-tdoa") && col.name == QLatin1String("beacon")) {
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
            const auto conversion = conversionTo(unit, target);
            if (!conversion)
                return makeError(QStringLiteral("%1: %2").arg(at, conversion.message()));
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

    const QString known = names.join(QStringLiteral(", "));
    if (!table && header.timeColumn < 0)
        return makeError(QStringLiteral("%1:%2: no 't' column (time in seconds); columns: %3").arg(file).arg(header.line).arg(known));
    if (kind) {
        for (const QString& required : kind->requiredColumns)
            if (!names.contains(required))
                return makeError(QStringLiteral("%1:%2: kind '%3' needs a column '%4'; columns: %5")
                                     .arg(file).arg(header.line).arg(kind->kind, required, known));
        if (kind->kind == QLatin1String("gnss") && !(names.contains("lat") && names.contains("lon")) &&
            !(names.contains("x") && names.contains("y")))
            return makeError(QStringLiteral("%1:%2: kind 'gnss' needs columns lat, lon (WGS84) or x, y (local ENU); columns: %3")
                                 .arg(file).arg(header.line).arg(known));
    }
    if (kindName == QLatin1String("lps-tdoa") && names.size() != 3)
        return makeError(QStringLiteral("%1:%2: kind 'lps-tdoa' has the columns t, beacon, dt (long format); columns: %3")
                             .arg(file).arg(header.line).arg(known));
    if (names.size() < (table ? 1 : 2))
        return makeError(QStringLiteral("%1:%2: no data columns; columns: %3").arg(file).arg(header.line).arg(known));
    return header;
}

// Parses the data records of a time series into data; Id columns go through ids.
class StreamParser {
public:
    StreamParser(CsvReader& reader, const MappedFile& mapped, const QString& file, const Header& header,
                 const Progress& progress)
        : reader_(reader), mapped_(mapped), file_(file), header_(header), progress_(progress) {}

    Status run(StreamData& data, std::vector<long long>& lines, std::vector<std::string>& ids);

private:
    Error cellError(const ColumnPlan& col, const QString& what) const {
        return makeError(QStringLiteral("%1: %2").arg(where(file_, reader_.line(), reader_.fieldIndex(), col.source), what));
    }
    Error fieldCountError() const {
        const int found = reader_.fieldsOnLine();
        const int expected = int(header_.columns.size());
        const int column = std::min(found, expected) + 1;
        return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                             .arg(file_).arg(reader_.line()).arg(column).arg(found).arg(expected));
    }

    CsvReader& reader_;
    const MappedFile& mapped_;
    const QString& file_;
    const Header& header_;
    const Progress& progress_;
};

Status StreamParser::run(StreamData& data, std::vector<long long>& lines, std::vector<std::string>& ids) {
    const int columns = int(header_.columns.size());
    data.columns = int(std::count_if(header_.columns.begin(), header_.columns.end(), [](const ColumnPlan& col) {
        return col.role != Role::Time && col.role != Role::Skip;
    }));
    std::unordered_map<std::string, int> idIndex;
    std::string text;
    const qint64 dataStart = reader_.offset();
    qint64 nextReport = dataStart + kProgressBytes;
    long long records = 0;

    while (reader_.nextRecord()) {
        for (int c = 0; c < columns; ++c) {
            const ColumnPlan& col = header_.columns[c];
            if (col.role == Role::Skip) {
                if (!reader_.text(text))
                    return fieldCountError();
                continue;
            }
            if (col.role == Role::Id) {
                if (!reader_.text(text))
                    return fieldCountError();
                if (text.empty())
                    return cellError(col, QStringLiteral("empty id"));
                const auto [it, added] = idIndex.try_emplace(text, int(ids.size()));
                if (added)
                    ids.push_back(text);
                data.values.push_back(it->second);
                continue;
            }
            double v;
            switch (reader_.number(v)) {
            case CsvReader::Field::Number:
                if (!std::isfinite(v) && (col.role == Role::Time || !std::isnan(v)))
                    return cellError(col, QStringLiteral("%1 is not a finite number").arg(quoted(reader_.lastField())));
                break;
            case CsvReader::Field::Empty:
                if (col.role == Role::Time)
                    return cellError(col, QStringLiteral("empty time"));
                break;
            case CsvReader::Field::Invalid:
                return cellError(col, QStringLiteral("%1 is not a number").arg(quoted(reader_.lastField())));
            case CsvReader::Field::Missing:
                return fieldCountError();
            }
            if (col.convert)
                v = v * col.scale + col.offset;
            if (col.role == Role::Time)
                data.t.push_back(v);
            else
                data.values.push_back(v);
        }
        if (!reader_.finishRecord())
            return fieldCountError();
        lines.push_back(reader_.line());

        if (++records == 256) {  // reserve once the line length is known instead of growing by doubling
            const double perRecord = double(reader_.offset() - dataStart) / double(records);
            const auto estimate = size_t(double(mapped_.size() - dataStart) / perRecord * 1.05) + 1024;
            data.t.reserve(estimate);
            data.values.reserve(estimate * size_t(data.columns));
            lines.reserve(estimate);
        }
        if ((records & 1023) == 0 && reader_.offset() >= nextReport) {
            if (progress_.isCancelled())
                return makeError(QStringLiteral("cancelled"));
            progress_.report(double(reader_.offset()) / double(mapped_.size()),
                             QStringLiteral("Reading %1").arg(QFileInfo(file_).fileName()));
            nextReport = reader_.offset() + kProgressBytes;
        }
    }
    if (records == 0)
        return makeError(QStringLiteral("%1: no data rows after the header (line %2)").arg(file_).arg(header_.line));
    return {};
}

// Long TDoA rows (t, beacon index, dt) → the wide stream of TdoaLayout.h.
Expected<Stream> tdoaStream(const StreamData& rows, const TimeOrigin& origin, const Header& header,
                            const std::vector<std::string>& ids) {
    int beacon = -1, dt = -1, dtFileColumn = 0, c = 0;
    for (size_t i = 0; i < header.columns.size(); ++i) {
        const auto& col = header.columns[i];
        if (col.role == Role::Time || col.role == Role::Skip)
            continue;
        if (col.name == QLatin1String("beacon"))
            beacon = c;
        else if (col.name == QLatin1String("dt"))
            dt = c, dtFileColumn = int(i) + 1;
        ++c;
    }
    std::vector<TdoaSample> samples(rows.rows());
    for (size_t r = 0; r < rows.rows(); ++r) {
        if (std::isnan(rows.at(r, dt)))
            return makeError(QStringLiteral("%1: empty dt").arg(where(origin.file, origin.lines[r], dtFileColumn, QStringLiteral("dt"))));
        const std::string& id = ids[size_t(rows.at(r, beacon))];
        samples[r] = {rows.t[r], QString::fromUtf8(id.data(), qsizetype(id.size())), rows.at(r, dt), origin.lines[r]};
    }
    return tdoaStreamFromSamples(samples, origin.file);
}

Expected<ImportResult> readStream(CsvReader& reader, const MappedFile& mapped, const QString& file,
                                  const ImportOptions& options, const QString& kindName, const StreamKind* kind,
                                  const Progress& progress) {
    auto header = planHeader(reader, file, options, kindName, kind, false);
    if (!header)
        return header.error();
    StreamData data;
    TimeOrigin origin{file, header->timeColumn + 1,
                      options.timeColumn.isEmpty() ? QStringLiteral("t") : options.timeColumn, {}};
    std::vector<std::string> ids;
    if (Status s = StreamParser(reader, mapped, file, *header, progress).run(data, origin.lines, ids); !s)
        return s.error();

    ImportResult result;
    const bool tdoa = kindName == QLatin1String("lps-tdoa");
    if (Status s = repairTimeOrder(data, origin, options.timeRepair, tdoa, result.warnings); !s)
        return s.error();

    QJsonObject sourceUnits;
    Columns columns;
    for (const auto& col : header->columns) {
        if (col.convert)
            sourceUnits.insert(col.name, col.sourceUnit);
        if (col.role != Role::Time && col.role != Role::Skip)
            columns.push_back({col.name, col.unit});
    }
    if (tdoa) {
        auto stream = tdoaStream(data, origin, *header, ids);
        if (!stream)
            return stream.error();
        stream->info().name = kind->defaultName;
        if (!sourceUnits.isEmpty())
            stream->info().attributes.insert(QStringLiteral("source_units"), sourceUnits);
        result.items.push_back({kind->defaultName, std::move(*stream)});
        return result;
    }

    StreamInfo info;
    info.kind = kindName;
    info.name = kind ? kind->defaultName : kindName;
    info.frame = kind ? kind->defaultFrame : QString();
    info.columns = std::move(columns);
    if (!sourceUnits.isEmpty())
        info.attributes.insert(QStringLiteral("source_units"), sourceUnits);
    if (kindName == QLatin1String("gnss") && info.columnIndex(QStringLiteral("lat")) < 0)
        info.frame = QStringLiteral("ENU");

    if (kindName == QLatin1String("imu")) {
        for (int c = 0; c < data.columns; ++c) {
            const Column& col = info.columns[c];
            if (!col.name.startsWith(QLatin1String("gyr_")))
                continue;
            double peak = 0.0;
            for (size_t r = 0; r < data.rows(); ++r)
                if (const double a = std::abs(data.at(r, c)); a > peak)  // NaN compares false
                    peak = a;
            if (peak > kGyrPlausibleMax)
                result.warnings << QStringLiteral("%1: column '%2' reaches %3 rad/s, implausible for rad/s; if the "
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
    if (!header)
        return header.error();
    Table table;
    table.kind = kindName;
    table.name = kind ? kind->defaultName : kindName;
    if (kind && !kind->defaultFrame.isEmpty())
        table.attributes.insert(QStringLiteral("frame"), kind->defaultFrame);
    std::vector<int> out(header->columns.size(), -1);  // table column of each file column
    for (size_t c = 0; c < header->columns.size(); ++c) {
        const auto& col = header->columns[c];
        if (col.role == Role::Skip)
            continue;
        out[c] = int(table.columns.size());
        table.columns.push_back({col.name, col.unit, col.role == Role::Text, {}, {}});
    }
    const int columns = int(header->columns.size());
    std::string text;
    long long rows = 0;
    while (reader.nextRecord()) {
        for (int c = 0; c < columns; ++c) {
            const ColumnPlan& col = header->columns[c];
            const auto at = [&] { return where(file, reader.line(), c + 1, col.source); };  // for messages only
            if (col.role == Role::Skip) {
                if (!reader.text(text))
                    return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                         .arg(file).arg(reader.line()).arg(c + 1).arg(reader.fieldsOnLine()).arg(columns));
                continue;
            }
            TableColumn& column = table.columns[size_t(out[c])];
            if (col.role == Role::Text) {
                if (!reader.text(text))
                    return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                         .arg(file).arg(reader.line()).arg(c + 1).arg(reader.fieldsOnLine()).arg(columns));
                column.texts << QString::fromUtf8(text.data(), qsizetype(text.size()));
                continue;
            }
            double v;
            const auto field = reader.number(v);
            if (field == CsvReader::Field::Missing)
                return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                     .arg(file).arg(reader.line()).arg(c + 1).arg(reader.fieldsOnLine()).arg(columns));
            if (field == CsvReader::Field::Invalid)
                return makeError(QStringLiteral("%1: %2 is not a number").arg(at(), quoted(reader.lastField())));
            if (std::isinf(v))
                return makeError(QStringLiteral("%1: %2 is not a finite number").arg(at(), quoted(reader.lastField())));
            column.numbers.push_back(col.convert ? v * col.scale + col.offset : v);
        }
        if (!reader.finishRecord())
            return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                 .arg(file).arg(reader.line()).arg(columns + 1).arg(reader.fieldsOnLine()).arg(columns));
        ++rows;
    }
    if (rows == 0)
        return makeError(QStringLiteral("%1: no data rows after the header (line %2)").arg(file).arg(header->line));
    ImportResult result;
    result.items.push_back({table.name, std::move(table)});
    return result;
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
    if (Status s = mapped.open(file); !s)
        return s.error();

    QString kindName = options.kind;
    if (kindName.isEmpty()) {
        CsvReader peek(mapped.begin(), mapped.end());
        QStringList cells;
        if (!peek.readHeader(cells))
            return makeError(QStringLiteral("%1: empty file (no header row)").arg(file));
        const QStringList names = mappedColumnNames(cells, options);
        kindName = inferCsvKind(names);
        if (kindName.isEmpty())
            return makeError(QStringLiteral("%1: cannot tell the kind of data from the columns (%2); give a kind (%3)")
                                 .arg(file, names.join(QStringLiteral(", ")), streamKindNames().join(QStringLiteral(", "))));
    }
    const StreamKind* kind = lookupKind(kindName);
    if (kind)
        kindName = kind->kind;

    CsvReader reader(mapped.begin(), mapped.end());
    progress.report(0.0, QStringLiteral("Reading %1").arg(QFileInfo(file).fileName()));
    auto result = kind && kind->table ? readTable(reader, file, options, kindName, kind)
                                      : readStream(reader, mapped, file, options, kindName, kind, progress);
    if (result)
        progress.report(1.0);
    return result;
}

// Time order --------------------------------------------------------------------------------------

namespace {

void keepRows(StreamData& data, std::vector<long long>& lines, const std::vector<size_t>& rows) {
    StreamData kept(rows.size(), data.columns);
    std::vector<long long> keptLines(rows.size());
    const size_t width = size_t(data.columns);
    for (size_t i = 0; i < rows.size(); ++i) {
        kept.t[i] = data.t[rows[i]];
        keptLines[i] = lines[rows[i]];
        std::copy_n(data.values.begin() + ptrdiff_t(rows[i] * width), width, kept.values.begin() + ptrdiff_t(i * width));
    }
    data = std::move(kept);
    lines = std::move(keptLines);
}

bool sameSample(const StreamData& data, size_t a, size_t b) {
    const size_t width = size_t(data.columns);
    return std::memcmp(&data.t[a], &data.t[b], sizeof(double)) == 0 &&
           std::memcmp(data.values.data() + a * width, data.values.data() + b * width, width * sizeof(double)) == 0;
}

}  // namespace

Status repairTimeOrder(StreamData& data, TimeOrigin& origin, const QString& mode, bool allowEqualTimes,
                       QStringList& warnings) {
    auto inOrder = [allowEqualTimes](double previous, double next) {
        return allowEqualTimes ? next >= previous : next > previous;
    };
    const size_t n = data.rows();
    if (origin.lines.size() != n)
        return makeError(QStringLiteral("%1: internal error: %2 line numbers for %3 samples").arg(origin.file).arg(origin.lines.size()).arg(n));
    size_t first = 1;
    while (first < n && inOrder(data.t[first - 1], data.t[first]))
        ++first;
    if (first >= n)
        return {};

    const QString at = where(origin.file, origin.lines[first], origin.column, origin.columnName);
    if (mode == QLatin1String("reject")) {
        return makeError(QStringLiteral("%1: time %2 is not after %3 on line %4 (times must increase; "
                                        "repair with time repair 'sort' or 'drop')")
                             .arg(at, shortest(data.t[first]), shortest(data.t[first - 1]))
                             .arg(origin.lines[first - 1]));
    }
    std::vector<size_t> rows;
    rows.reserve(n);
    if (mode == QLatin1String("drop")) {
        for (size_t i = 0; i < n; ++i)
            if (rows.empty() || inOrder(data.t[rows.back()], data.t[i]))
                rows.push_back(i);
        warnings << QStringLiteral("%1: dropped %2 samples whose time was not after the previous sample's (first on line %3)")
                        .arg(origin.file).arg(n - rows.size()).arg(origin.lines[first]);
        keepRows(data, origin.lines, rows);
        return {};
    }
    if (mode != QLatin1String("sort"))
        return makeError(QStringLiteral("unknown time repair '%1' (reject, sort or drop)").arg(mode));

    size_t outOfOrder = 0;
    for (size_t i = 1; i < n; ++i)
        outOfOrder += data.t[i] < data.t[i - 1];
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return data.t[a] < data.t[b]; });
    size_t duplicates = 0;
    size_t group = 0;  // first kept row (index into rows) with the current time
    for (size_t i : order) {
        if (rows.empty() || data.t[i] != data.t[rows.back()]) {
            group = rows.size();
            rows.push_back(i);
            continue;
        }
        bool duplicate = false;
        for (size_t k = group; k < rows.size() && !duplicate; ++k)
            duplicate = sameSample(data, rows[k], i);
        if (duplicate) {
            ++duplicates;
        } else if (allowEqualTimes) {
            rows.push_back(i);
        } else {
            return makeError(QStringLiteral("%1: lines %2 and %3 have the same time %4 but different values; "
                                            "time repair 'drop' keeps the first")
                                 .arg(origin.file).arg(origin.lines[rows.back()]).arg(origin.lines[i]).arg(shortest(data.t[i])));
        }
    }
    if (outOfOrder > 0)
        warnings << QStringLiteral("%1: sorted by time (%2 samples were out of order, the first on line %3)")
                        .arg(origin.file).arg(outOfOrder).arg(origin.lines[first]);
    if (duplicates > 0)
        warnings << QStringLiteral("%1: dropped %2 exact duplicate samples").arg(origin.file).arg(duplicates);
    keepRows(data, origin.lines, rows);
    return {};
}

}  // namespace athlos
