#include "core/io/MultiImport.h"

#include "core/io/CsvReader.h"
#include "core/io/TdoaLayout.h"
#include "core/io/TimeFormats.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QRegularExpression>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <numeric>

namespace athlos {
namespace {

constexpr double kSamePosition = 1e-3;  // m

struct Piece {
    QString file;
    ImportedItem item;
};

QString fileName(const QString& file) { return QFileInfo(file).fileName(); }

QString fileList(const std::vector<Piece>& pieces) {
    QStringList names;
    for (const Piece& p : pieces) names << fileName(p.file);
    return names.join(QStringLiteral(", "));
}

// The offsets (s) that put every piece on one axis (t = 0 at the earliest start), and that start.
Expected<std::vector<double>> alignStarts(const std::vector<Piece>& pieces, const QString& path, QStringList& warnings,
                                          TimeBase& base) {
    std::vector<qint64> starts;
    int known = 0;
    for (const Piece& p : pieces) {
        const QString t0 = std::get<Stream>(p.item.item).info().attributes.value(QStringLiteral("t0_utc")).toString();
        if (t0.isEmpty()) {
            starts.push_back(0);
            continue;
        }
        const auto ns = parseUtc(t0);
        if (!ns) return makeError(QStringLiteral("%1: t0_utc: %2").arg(fileName(p.file), ns.message()));
        starts.push_back(*ns);
        ++known;
    }
    std::vector<double> offsets(pieces.size(), 0.0);
    if (known == 0) {
        warnings << QStringLiteral(
                        "%1: the files (%2) do not say when they start; their times are taken to share one clock")
                        .arg(path, fileList(pieces));
        return offsets;
    }
    if (known != int(pieces.size())) {
        QStringList without;
        for (size_t i = 0; i < pieces.size(); ++i)
            if (std::get<Stream>(pieces[i].item.item)
                    .info()
                    .attributes.value(QStringLiteral("t0_utc"))
                    .toString()
                    .isEmpty())
                without << fileName(pieces[i].file);
        return makeError(
            QStringLiteral("%1: cannot put the files on one time axis: %2 do not say when they start (give the "
                           "time format of their time column, or --start)")
                .arg(path, without.join(QStringLiteral(", "))));
    }
    base.known = true;
    base.t0Ns = *std::min_element(starts.begin(), starts.end());
    for (size_t i = 0; i < pieces.size(); ++i) offsets[i] = double(starts[i] - base.t0Ns) * 1e-9;
    return offsets;
}

Expected<Stream> mergeLong(const std::vector<Piece>& pieces, const LongLayout& layout, const QString& path,
                           QStringList& warnings) {
    TimeBase base;
    const auto offsets = alignStarts(pieces, path, warnings, base);
    if (!offsets) return offsets.error();
    std::vector<TdoaSample> samples;
    for (size_t i = 0; i < pieces.size(); ++i) {
        const Stream& s = std::get<Stream>(pieces[i].item.item);
        const auto data = s.data();
        if (!data) return data.error();
        const long long file = (long long)(i);
        forEachLongSample(layout, s.info(), **data, [&](double t, const QString& beacon, double value) {
            samples.push_back({t + (*offsets)[i], beacon, value, file});
        });
    }
    std::stable_sort(samples.begin(), samples.end(),
                     [](const TdoaSample& a, const TdoaSample& b) { return a.t < b.t; });
    // The same beacon twice at one instant: name both files.
    std::map<QString, std::pair<double, long long>> last;  // beacon → (t, file)
    for (const TdoaSample& s : samples) {
        auto it = last.find(s.beacon);
        if (it != last.end() && it->second.first == s.t)
            return makeError(
                QStringLiteral("%1: beacon '%2' has two measurements at t = %3 s (in %4 and %5)")
                    .arg(path, s.beacon)
                    .arg(s.t, 0, 'g', 17)
                    .arg(fileName(pieces[size_t(it->second.second)].file), fileName(pieces[size_t(s.line)].file)));
        last[s.beacon] = {s.t, s.line};
    }
    for (TdoaSample& s : samples) s.line = 0;
    auto merged = longStreamFromSamples(samples, path, layout);
    if (!merged) return merged.error();
    const StreamInfo& first = std::get<Stream>(pieces.front().item.item).info();
    StreamInfo& info = merged->info();
    info.name = first.name;
    info.frame = first.frame;
    info.provenance = first.provenance;
    for (auto it = first.attributes.begin(); it != first.attributes.end(); ++it)
        if (!info.attributes.contains(it.key())) info.attributes.insert(it.key(), it.value());
    info.attributes.remove(QStringLiteral("t0_utc"));
    writeTimeAttributes(info.attributes, base, {});
    return merged;
}

// Pieces of one recording, one after another.
Expected<Stream> mergeSequential(const std::vector<Piece>& pieces, const QString& path, QStringList& warnings) {
    const StreamInfo& first = std::get<Stream>(pieces.front().item.item).info();
    for (const Piece& p : pieces) {
        const StreamInfo& info = std::get<Stream>(p.item.item).info();
        if (info.columns != first.columns) {
            QStringList a, b;
            for (const Column& c : first.columns) a << c.name;
            for (const Column& c : info.columns) b << c.name;
            return makeError(QStringLiteral("%1: %2 has the columns %3, %4 has %5; only files with the same columns "
                                            "make one stream")
                                 .arg(path, fileName(pieces.front().file), a.join(QLatin1Char(',')), fileName(p.file),
                                      b.join(QLatin1Char(','))));
        }
    }
    TimeBase base;
    const auto offsets = alignStarts(pieces, path, warnings, base);
    if (!offsets) return offsets.error();
    std::vector<size_t> order(pieces.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::vector<std::shared_ptr<const StreamData>> datas;
    for (const Piece& p : pieces) {
        const auto d = std::get<Stream>(p.item.item).data();
        if (!d) return d.error();
        datas.push_back(*d);
    }
    auto begin = [&](size_t i) { return datas[i]->t.front() + (*offsets)[i]; };
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return begin(a) < begin(b); });
    StreamData merged;
    merged.columns = first.columns.empty() ? datas.front()->columns : int(first.columns.size());
    size_t previous = pieces.size();
    for (size_t i : order) {
        const StreamData& d = *datas[i];
        if (!merged.t.empty() && begin(i) <= merged.t.back())
            return makeError(
                QStringLiteral("%1: %2 and %3 overlap in time (%4 s starts before %5 s ends); only pieces of "
                               "one recording that follow each other make one stream")
                    .arg(path, fileName(pieces[previous].file), fileName(pieces[i].file))
                    .arg(begin(i), 0, 'g', 12)
                    .arg(merged.t.back(), 0, 'g', 12));
        for (double t : d.t) merged.t.push_back(t + (*offsets)[i]);
        merged.values.insert(merged.values.end(), d.values.begin(), d.values.end());
        previous = i;
    }
    StreamInfo info = first;
    info.attributes.remove(QStringLiteral("t0_utc"));
    writeTimeAttributes(info.attributes, base, {});
    return Stream(std::move(info), std::move(merged));
}

Expected<Table> mergeTables(const std::vector<Piece>& pieces, const QString& path) {
    Table merged = std::get<Table>(pieces.front().item.item);
    const TableColumn* id = merged.column(QStringLiteral("id"));
    std::map<QString, std::pair<size_t, long long>> seen;  // id → (piece, row)
    if (id && id->isText)
        for (long long r = 0; r < merged.rows(); ++r) seen.emplace(id->texts.at(qsizetype(r)), std::pair{size_t(0), r});
    for (size_t i = 1; i < pieces.size(); ++i) {
        const Table& t = std::get<Table>(pieces[i].item.item);
        bool same = t.columns.size() == merged.columns.size();
        for (size_t c = 0; same && c < t.columns.size(); ++c)
            same = t.columns[c].name == merged.columns[c].name && t.columns[c].isText == merged.columns[c].isText;
        if (!same)
            return makeError(QStringLiteral("%1: %2 and %3 have different columns")
                                 .arg(path, fileName(pieces[0].file), fileName(pieces[i].file)));
        const TableColumn* tid = t.column(QStringLiteral("id"));
        for (long long r = 0; r < t.rows(); ++r) {
            if (tid && tid->isText) {
                const QString key = tid->texts.at(qsizetype(r));
                if (const auto it = seen.find(key); it != seen.end()) {
                    const Table& other = std::get<Table>(pieces[it->second.first].item.item);
                    for (size_t c = 0; c < t.columns.size(); ++c) {
                        if (t.columns[c].isText) continue;
                        const double a = other.columns[c].numbers[size_t(it->second.second)],
                                     b = t.columns[c].numbers[size_t(r)];
                        if (!(std::abs(a - b) <= kSamePosition) && !(std::isnan(a) && std::isnan(b)))
                            return makeError(QStringLiteral("%1: '%2' has %3 = %4 in %5 but %6 in %7")
                                                 .arg(path, key, t.columns[c].name)
                                                 .arg(a)
                                                 .arg(fileName(pieces[it->second.first].file))
                                                 .arg(b)
                                                 .arg(fileName(pieces[i].file)));
                    }
                    continue;  // the same row again
                }
                seen.emplace(key, std::pair{i, r});
            }
            for (size_t c = 0; c < t.columns.size(); ++c) {
                if (t.columns[c].isText)
                    merged.columns[c].texts << t.columns[c].texts.at(qsizetype(r));
                else
                    merged.columns[c].numbers.push_back(t.columns[c].numbers[size_t(r)]);
            }
        }
    }
    return merged;
}

QJsonArray absolutePaths(const std::vector<Piece>& pieces) {
    QJsonArray files;
    for (const Piece& p : pieces) files.append(QFileInfo(p.file).absoluteFilePath());
    return files;
}

// A stream name from a file name: letters, digits, '-', '_' and '.'; anything else becomes '-'.
QString streamNameOf(const QString& file) {
    QString name = QFileInfo(file).completeBaseName();
    static const QRegularExpression other(QStringLiteral("[^A-Za-z0-9_.\\-]+"));
    name.replace(other, QStringLiteral("-"));
    return name.isEmpty() ? QStringLiteral("stream") : name;
}

}  // namespace

Expected<ImportResult> importFiles(const QStringList& files, const ImportOptions& options, const Progress& progress) {
    if (files.isEmpty()) return makeError(QStringLiteral("no files to import"));
    if (files.size() == 1) return importFile(files.front(), options, progress);
    ImportResult result;
    std::vector<std::pair<QString, std::vector<Piece>>> groups;  // by item path, in order of appearance
    const double n = double(files.size());
    for (qsizetype i = 0; i < files.size(); ++i) {
        auto one = importFile(files[i], options, progress.sub(double(i) / n, double(i + 1) / n));
        if (!one) return one.error();
        result.warnings << one->warnings;
        for (auto& [rec, metadata] : one->recordingMetadata)
            for (auto it = metadata.begin(); it != metadata.end(); ++it)
                result.recordingMetadata[rec].insert(it.key(), it.value());
        for (ImportedItem& item : one->items) {
            auto group =
                std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == item.path; });
            if (group == groups.end()) {
                groups.push_back({item.path, {}});
                group = groups.end() - 1;
            }
            group->second.push_back({files[i], std::move(item)});
        }
    }
    for (auto& [path, pieces] : groups) {
        if (pieces.size() == 1) {
            result.items.push_back(std::move(pieces.front().item));
            continue;
        }
        const bool tables = std::holds_alternative<Table>(pieces.front().item.item);
        for (const Piece& p : pieces)
            if (std::holds_alternative<Table>(p.item.item) != tables)
                return makeError(QStringLiteral("%1: %2 gives a table, %3 a stream")
                                     .arg(path, fileName(pieces.front().file), fileName(p.file)));
        if (tables) {
            auto merged = mergeTables(pieces, path);
            if (!merged) return merged.error();
            merged->provenance.parameters.insert(QStringLiteral("files"), absolutePaths(pieces));
            result.items.push_back({path, std::move(*merged)});
            continue;
        }
        const QString kind = std::get<Stream>(pieces.front().item.item).info().kind;
        for (const Piece& p : pieces)
            if (std::get<Stream>(p.item.item).info().kind != kind)
                return makeError(QStringLiteral("%1: %2 is of kind '%3', %4 of kind '%5'; one stream has one kind")
                                     .arg(path, fileName(pieces.front().file), kind, fileName(p.file),
                                          std::get<Stream>(p.item.item).info().kind));
        const LongLayout* layout = longLayoutOf(kind);
        auto merged =
            layout ? mergeLong(pieces, *layout, path, result.warnings) : mergeSequential(pieces, path, result.warnings);
        if (!merged) return merged.error();
        merged->info().provenance.parameters.insert(QStringLiteral("files"), absolutePaths(pieces));
        result.items.push_back({path, std::move(*merged)});
    }
    return result;
}

Expected<std::vector<RosterEntry>> readRoster(const QString& file) {
    MappedFile mapped;
    if (Status s = mapped.open(file); !s) return s.error();
    CsvReader reader(mapped.begin(), mapped.end());
    QStringList header;
    if (!reader.readHeader(header))
        return makeError(
            QStringLiteral("%1: empty roster (expected the header file,athlete,number,team,position,mass_kg)")
                .arg(file));
    const long long headerLine = reader.line();
    for (QString& h : header) h = h.trimmed().toLower();
    const qsizetype fileColumn = header.indexOf(QStringLiteral("file"));
    if (fileColumn < 0)
        return makeError(
            QStringLiteral("%1:%2: a roster needs a column 'file' (file,athlete,number,team,position,mass_kg); "
                           "columns: %3")
                .arg(file)
                .arg(headerLine)
                .arg(header.join(QStringLiteral(", "))));
    std::vector<RosterEntry> entries;
    std::string cell;
    while (reader.nextRecord()) {
        RosterEntry entry;
        for (qsizetype c = 0; c < header.size(); ++c) {
            if (!reader.text(cell))
                return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                     .arg(file)
                                     .arg(reader.line())
                                     .arg(c + 1)
                                     .arg(reader.fieldsOnLine())
                                     .arg(header.size()));
            const QString value = QString::fromUtf8(cell.data(), qsizetype(cell.size())).trimmed();
            const QString& key = header[c];
            if (c == fileColumn) {
                if (value.isEmpty())
                    return makeError(QStringLiteral("%1:%2:%3 (column 'file'): empty file name")
                                         .arg(file)
                                         .arg(reader.line())
                                         .arg(c + 1));
                entry.file = value;
            } else if (value.isEmpty()) {
                continue;
            } else if (key == QLatin1String("mass_kg") || key == QLatin1String("number")) {
                double v = 0.0;
                const auto [q, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
                if (ec != std::errc() || q != cell.data() + cell.size() || !std::isfinite(v))
                    return makeError(QStringLiteral("%1:%2:%3 (column '%4'): '%5' is not a number")
                                         .arg(file)
                                         .arg(reader.line())
                                         .arg(c + 1)
                                         .arg(key, value));
                entry.attributes.insert(key, v);
            } else if (!key.isEmpty()) {
                entry.attributes.insert(key, value);
                if (key == QLatin1String("athlete")) entry.attributes.insert(QStringLiteral("label"), value);
            }
        }
        if (!reader.finishRecord())
            return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %5")
                                 .arg(file)
                                 .arg(reader.line())
                                 .arg(header.size() + 1)
                                 .arg(reader.fieldsOnLine())
                                 .arg(header.size()));
        for (const RosterEntry& other : entries)
            if (other.file == entry.file)
                return makeError(QStringLiteral("%1:%2:%3 (column 'file'): '%4' is listed twice")
                                     .arg(file)
                                     .arg(reader.line())
                                     .arg(fileColumn + 1)
                                     .arg(entry.file));
        entries.push_back(std::move(entry));
    }
    return entries;
}

Expected<ImportResult> importFolder(const QString& folder, const ImportOptions& options, const QString& roster,
                                    const Progress& progress) {
    const QFileInfo dir(folder);
    if (!dir.isDir()) return makeError(QStringLiteral("%1: not a folder").arg(folder));
    const QString target = options.target.trimmed().isEmpty() ? QDir(folder).dirName() : options.target.trimmed();
    if (target.contains(QLatin1Char('/')))
        return makeError(
            QStringLiteral("target '%1': a folder import names its streams after the files; give a recording "
                           "name only")
                .arg(target));
    std::vector<RosterEntry> entries;
    const QString rosterPath = roster.isEmpty() ? QString() : QFileInfo(roster).absoluteFilePath();
    if (!roster.isEmpty()) {
        auto read = readRoster(roster);
        if (!read) return read.error();
        entries = std::move(*read);
    }
    ImportResult result;
    QStringList files;
    for (const QFileInfo& f : QDir(folder).entryInfoList(QDir::Files | QDir::NoDotAndDotDot, QDir::Name)) {
        if (f.absoluteFilePath() == rosterPath) continue;
        if (const auto importer = chooseImporter(f.filePath(), options.format); !importer) {
            result.warnings << QStringLiteral("%1: skipped (%2)").arg(f.filePath(), importer.message());
            continue;
        }
        files << f.filePath();
    }
    if (files.isEmpty()) return makeError(QStringLiteral("%1: no file to import in the folder").arg(folder));
    std::vector<bool> used(entries.size(), false);
    const double n = double(files.size());
    for (qsizetype i = 0; i < files.size(); ++i) {
        const QFileInfo f(files[i]);
        ImportOptions one = options;
        one.target = target + QLatin1Char('/') + streamNameOf(files[i]);
        auto imported = importFile(files[i], one, progress.sub(double(i) / n, double(i + 1) / n));
        if (!imported) return imported.error();
        QJsonObject athlete{{QStringLiteral("athlete"), f.completeBaseName()},
                            {QStringLiteral("label"), f.completeBaseName()}};
        if (!entries.empty()) {
            const auto entry = std::find_if(entries.begin(), entries.end(), [&](const RosterEntry& e) {
                return e.file == f.fileName() || e.file == f.completeBaseName();
            });
            if (entry == entries.end()) {
                result.warnings << QStringLiteral("%1: not in the roster %2; the athlete is the file name")
                                       .arg(f.fileName(), QFileInfo(roster).fileName());
            } else {
                used[size_t(entry - entries.begin())] = true;
                for (auto it = entry->attributes.begin(); it != entry->attributes.end(); ++it)
                    athlete.insert(it.key(), it.value());
            }
        }
        result.warnings << imported->warnings;
        for (ImportedItem& item : imported->items) {
            if (auto* s = std::get_if<Stream>(&item.item))
                for (auto it = athlete.begin(); it != athlete.end(); ++it)
                    s->info().attributes.insert(it.key(), it.value());
            else
                for (auto it = athlete.begin(); it != athlete.end(); ++it)
                    std::get<Table>(item.item).attributes.insert(it.key(), it.value());
            result.items.push_back(std::move(item));
        }
        for (auto& [rec, metadata] : imported->recordingMetadata)
            for (auto it = metadata.begin(); it != metadata.end(); ++it)
                result.recordingMetadata[rec].insert(it.key(), it.value());
    }
    for (size_t i = 0; i < entries.size(); ++i)
        if (!used[i])
            result.warnings << QStringLiteral("%1: '%2' is in the roster but not in the folder")
                                   .arg(QFileInfo(roster).fileName(), entries[i].file);
    return result;
}

}  // namespace athlos
