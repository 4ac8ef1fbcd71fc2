#include "core/io/CsvRecords.h"

#include <QFileInfo>
#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace athlos::csv {
namespace {

constexpr qint64 kProgressBytes = 4 << 20;

// Parses the data records of a time series into data; Id columns go through ids.
class StreamParser {
public:
    StreamParser(CsvReader& reader, const MappedFile& mapped, const QString& file, const Header& header,
                 const Progress& progress)
        : reader_(reader), mapped_(mapped), file_(file), header_(header), progress_(progress) {}

    Status run(StreamData& data, std::vector<long long>& lines, std::vector<std::string>& ids, ParsedTime& time,
               ParsedLabels* labels);

private:
    Error cellError(const ColumnPlan& col, const QString& what) const {
        return makeError(
            QStringLiteral("%1: %2").arg(where(file_, reader_.line(), reader_.fieldIndex(), col.source), what));
    }
    Error fieldCountError() const {
        const int found = reader_.fieldsOnLine();
        const int expected = int(header_.columns.size());
        const int column = std::min(found, expected) + 1;
        return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                             .arg(file_)
                             .arg(reader_.line())
                             .arg(column)
                             .arg(found)
                             .arg(expected));
    }

    CsvReader& reader_;
    const MappedFile& mapped_;
    const QString& file_;
    const Header& header_;
    const Progress& progress_;
};

Status StreamParser::run(StreamData& data, std::vector<long long>& lines, std::vector<std::string>& ids,
                         ParsedTime& time, ParsedLabels* labels) {
    const int columns = int(header_.columns.size());
    data.columns = int(std::count_if(header_.columns.begin(), header_.columns.end(),
                                     [](const ColumnPlan& col) { return isDataRole(col.role); }));
    const TimeFormat& format = header_.timeFormat;
    const bool absolute = format.absolute();
    const bool clock = format.kind == TimeKind::Clock;
    constexpr qint64 kHalfDay = kNsPerDay / 2;
    constexpr qint64 kExcelUnixEpoch = 25569;  // serial day of 1970-01-01
    qint64 recordNs = 0, recordDays = 0, previousTod = -1, dayOffset = 0, base = 0;
    bool haveBase = false;
    std::unordered_map<std::string, int> idIndex;
    std::string text;
    const qint64 dataStart = reader_.offset();
    qint64 nextReport = dataStart + kProgressBytes;
    long long records = 0;

    while (reader_.nextRecord()) {
        for (int c = 0; c < columns; ++c) {
            const ColumnPlan& col = header_.columns[c];
            if (col.role == Role::Skip) {
                if (!reader_.text(text)) return fieldCountError();
                continue;
            }
            if (col.role == Role::Label) {
                if (!reader_.text(text)) return fieldCountError();
                if (labels) labels->push_back(text);
                continue;
            }
            if (col.role == Role::Date) {
                if (!reader_.text(text)) return fieldCountError();
                if (!parseIsoDate(text, recordDays))
                    return cellError(col, QStringLiteral("%1 is not a date YYYY-MM-DD").arg(csv::quoted(text)));
                continue;
            }
            if (col.role == Role::Time && absolute) {
                if (!reader_.text(text)) return fieldCountError();
                if (text.empty()) return cellError(col, QStringLiteral("empty time"));
                bool ok = false, zone = true;
                switch (format.kind) {
                    case TimeKind::Unix:
                        ok = parseScaledInstant(text, format.scale * 1e9, recordNs);
                        break;
                    case TimeKind::Excel:
                        ok = parseScaledInstant(text, double(kNsPerDay), recordNs);
                        recordNs -= kExcelUnixEpoch * kNsPerDay;
                        break;
                    case TimeKind::Iso:
                        ok = parseIsoDateTime(text, recordNs, zone);
                        time.missingZone = time.missingZone || !zone;
                        break;
                    default:
                        ok = parseClockTime(text, recordNs);
                        break;
                }
                if (!ok) {
                    static const char* const kExpected[] = {"",
                                                            "",
                                                            "a number",
                                                            "an ISO 8601 date-time (2024-05-01T13:45:01.25Z)",
                                                            "a clock time hh:mm:ss[.fff]",
                                                            "a number"};
                    return cellError(
                        col, QStringLiteral("%1 is not %2 (time format '%3')")
                                 .arg(csv::quoted(text), QLatin1String(kExpected[int(format.kind)]), format.name));
                }
                continue;
            }
            if (col.role == Role::Id) {
                if (!reader_.text(text)) return fieldCountError();
                if (text.empty()) return cellError(col, QStringLiteral("empty id"));
                const auto [it, added] = idIndex.try_emplace(text, int(ids.size()));
                if (added) ids.push_back(text);
                data.values.push_back(it->second);
                continue;
            }
            double v;
            switch (reader_.number(v)) {
                case CsvReader::Field::Number:
                    if (!std::isfinite(v) && (col.role == Role::Time || !std::isnan(v)))
                        return cellError(col,
                                         QStringLiteral("%1 is not a finite number").arg(quoted(reader_.lastField())));
                    break;
                case CsvReader::Field::Empty:
                    if (col.role == Role::Time) return cellError(col, QStringLiteral("empty time"));
                    break;
                case CsvReader::Field::Invalid:
                    return cellError(col, QStringLiteral("%1 is not a number").arg(quoted(reader_.lastField())));
                case CsvReader::Field::Missing:
                    return fieldCountError();
            }
            if (col.convert) v = v * col.scale + col.offset;
            if (col.role == Role::Time)
                data.t.push_back(v);
            else
                data.values.push_back(v);
        }
        if (!reader_.finishRecord()) return fieldCountError();
        if (absolute) {
            qint64 ns = recordNs;
            if (clock) {
                if (header_.dateColumn >= 0) {
                    ns += recordDays * kNsPerDay;
                } else {
                    if (previousTod >= 0 && recordNs < previousTod - kHalfDay) ++dayOffset;  // past midnight
                    previousTod = recordNs;
                    ns += (dayOffset + (header_.haveDate ? header_.dateDays : 0)) * kNsPerDay;
                }
            }
            if (!haveBase) {
                base = ns;
                haveBase = true;
            }
            data.t.push_back(double(ns - base) * 1e-9);
        }
        lines.push_back(reader_.line());

        if (++records == 256) {  // reserve once the line length is known instead of growing by doubling
            const double perRecord = double(reader_.offset() - dataStart) / double(records);
            const auto estimate = size_t(double(mapped_.size() - dataStart) / perRecord * 1.05) + 1024;
            data.t.reserve(estimate);
            data.values.reserve(estimate * size_t(data.columns));
            lines.reserve(estimate);
        }
        if ((records & 1023) == 0 && reader_.offset() >= nextReport) {
            if (progress_.isCancelled()) return makeError(QStringLiteral("cancelled"));
            progress_.report(double(reader_.offset()) / double(mapped_.size()),
                             QStringLiteral("Reading %1").arg(QFileInfo(file_).fileName()));
            nextReport = reader_.offset() + kProgressBytes;
        }
    }
    if (records == 0)
        return makeError(QStringLiteral("%1: no data rows after the header (line %2)").arg(file_).arg(header_.line));
    if (absolute) {
        time.base.t0Ns = base;
        time.base.timeOfDayOnly = clock && header_.dateColumn < 0 && !header_.haveDate;
        time.base.known = !time.base.timeOfDayOnly;
    }
    return {};
}

}  // namespace

Status parseStreamRecords(CsvReader& reader, const MappedFile& mapped, const QString& file, const Header& header,
                          const Progress& progress, StreamData& data, std::vector<long long>& lines,
                          std::vector<std::string>& ids, ParsedTime& time, ParsedLabels* labels) {
    return StreamParser(reader, mapped, file, header, progress).run(data, lines, ids, time, labels);
}

Status parseTableRecords(CsvReader& reader, const QString& file, const Header& header, Table& table) {
    std::vector<int> out(header.columns.size(), -1);  // table column of each file column
    for (size_t c = 0; c < header.columns.size(); ++c) {
        const auto& col = header.columns[c];
        if (col.role == Role::Skip) continue;
        out[c] = int(table.columns.size());
        table.columns.push_back({col.name, col.unit, col.role == Role::Text, {}, {}});
    }
    const int columns = int(header.columns.size());
    std::string text;
    long long rows = 0;
    while (reader.nextRecord()) {
        for (int c = 0; c < columns; ++c) {
            const ColumnPlan& col = header.columns[c];
            const auto at = [&] { return where(file, reader.line(), c + 1, col.source); };  // for messages only
            if (col.role == Role::Skip || col.role == Role::Date) {
                if (!reader.text(text))
                    return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                         .arg(file)
                                         .arg(reader.line())
                                         .arg(c + 1)
                                         .arg(reader.fieldsOnLine())
                                         .arg(columns));
                continue;
            }
            TableColumn& column = table.columns[size_t(out[c])];
            if (col.role == Role::Text) {
                if (!reader.text(text))
                    return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                         .arg(file)
                                         .arg(reader.line())
                                         .arg(c + 1)
                                         .arg(reader.fieldsOnLine())
                                         .arg(columns));
                column.texts << QString::fromUtf8(text.data(), qsizetype(text.size()));
                continue;
            }
            double v;
            const auto field = reader.number(v);
            if (field == CsvReader::Field::Missing)
                return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                     .arg(file)
                                     .arg(reader.line())
                                     .arg(c + 1)
                                     .arg(reader.fieldsOnLine())
                                     .arg(columns));
            if (field == CsvReader::Field::Invalid)
                return makeError(QStringLiteral("%1: %2 is not a number").arg(at(), quoted(reader.lastField())));
            if (std::isinf(v))
                return makeError(QStringLiteral("%1: %2 is not a finite number").arg(at(), quoted(reader.lastField())));
            column.numbers.push_back(col.convert ? v * col.scale + col.offset : v);
        }
        if (!reader.finishRecord())
            return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                 .arg(file)
                                 .arg(reader.line())
                                 .arg(columns + 1)
                                 .arg(reader.fieldsOnLine())
                                 .arg(columns));
        ++rows;
    }
    if (rows == 0)
        return makeError(QStringLiteral("%1: no data rows after the header (line %2)").arg(file).arg(header.line));
    return {};
}

}  // namespace athlos::csv
