// The importer registry, format detection, item naming and the all-or-nothing apply step.
//
// Naming: importers return items under their default names ("imu"; BROAD "imu" and "reference";
// gaitmap "left-foot" and "right-foot"; NMEA "gnss"). importFile() puts them under the target:
//   "rec"         → rec/<default name>
//   "rec/name"    → rec/name for a single item, rec/name-<default name> for each of several
//   "" (none)     → the recording is named after the file ("run1.csv" → run1/<default name>).
#include "core/io/AnnotationIo.h"
#include "core/io/BroadImporter.h"
#include "core/io/CsvImporter.h"
#include "core/io/GaitmapImporter.h"
#include "core/io/Importer.h"
#include "core/io/NmeaImporter.h"
#include "core/io/GpxImporter.h"
#include "core/io/MetricaImporter.h"
#include "core/io/RosImporter.h"
#include "core/io/VendorCsvImporter.h"
#include "core/util/Version.h"

#include <QDateTime>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QSet>
#include <algorithm>

namespace athlos {
namespace {

constexpr qint64 kHeadBytes = 4096;

struct Target {
    QString recording;
    QString item;
};

Expected<Target> parseTarget(const QString& target, const QString& file) {
    if (target.trimmed().isEmpty()) return Target{QFileInfo(file).completeBaseName(), {}};
    const QStringList parts = target.trimmed().split(QLatin1Char('/'));
    if (parts.size() > 2 || parts.front().isEmpty() || (parts.size() == 2 && parts.back().isEmpty()))
        return makeError(QStringLiteral("target '%1': expected <recording> or <recording>/<stream>").arg(target));
    return Target{parts.front(), parts.size() == 2 ? parts.back() : QString()};
}

Provenance importProvenance(const Importer& importer, const QString& file, const ImportOptions& options) {
    Provenance p;
    p.processorId = QStringLiteral("import:") + importer.format();
    p.processorVersion = appVersion();
    p.parameters = QJsonObject{{"format", importer.format()},
                               {"kind", options.kind},
                               {"time_repair", options.timeRepair},
                               {"frame", options.frame},
                               {"target", options.target}};
    if (!options.columns.empty()) {
        QJsonArray columns;
        for (const ColumnMapping& m : options.columns)
            columns.append(
                QJsonObject{{"source", m.source}, {"channel", m.channel}, {"unit", m.unit}, {"skip", m.skip}});
        p.parameters.insert(QStringLiteral("columns"), columns);
    }
    if (!options.timeColumn.isEmpty()) p.parameters.insert(QStringLiteral("time_column"), options.timeColumn);
    if (!options.timeUnit.isEmpty()) p.parameters.insert(QStringLiteral("time_unit"), options.timeUnit);
    if (options.dropUnmapped) p.parameters.insert(QStringLiteral("drop_unmapped"), true);
    if (options.origin) p.parameters.insert(QStringLiteral("origin"), options.origin->toJson());
    if (!options.date.isEmpty()) p.parameters.insert(QStringLiteral("date"), options.date);
    if (!options.start.isEmpty()) p.parameters.insert(QStringLiteral("start"), options.start);
    if (options.rate > 0.0) p.parameters.insert(QStringLiteral("rate"), options.rate);
    p.sourceFile = QFileInfo(file).absoluteFilePath();
    p.appVersion = appVersion();
    p.time = QDateTime::currentDateTimeUtc();
    return p;
}

}  // namespace

const std::vector<std::unique_ptr<Importer>>& importers() {
    // Order is the auto-detection order: specific signatures first, plain CSV last.
    static const auto list = [] {
        std::vector<std::unique_ptr<Importer>> v;
        v.push_back(std::make_unique<BroadImporter>());
        v.push_back(std::make_unique<AnnotationImporter>());
        v.push_back(std::make_unique<GaitmapImporter>());
        v.push_back(std::make_unique<NmeaImporter>());
        v.push_back(std::make_unique<RosImporter>());
        v.push_back(std::make_unique<MetricaImporter>());
        for (const VendorProfile& profile : VendorCsvImporter::profiles())
            v.push_back(std::make_unique<VendorCsvImporter>(profile));
        v.push_back(std::make_unique<GpxImporter>());
        v.push_back(std::make_unique<CsvImporter>());
        return v;
    }();
    return list;
}

Expected<const Importer*> chooseImporter(const QString& file, const QString& format) {
    auto known = [] {
        QStringList formats;
        for (const auto& candidate : importers()) formats << candidate->format();
        return formats.join(QStringLiteral(", "));
    };
    if (!format.isEmpty() && format != QLatin1String("auto")) {
        if (const Importer* importer = findImporter(format)) return importer;
        return makeError(QStringLiteral("unknown import format '%1' (known: auto, %2)").arg(format, known()));
    }
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly))
        return makeError(QStringLiteral("%1: cannot open: %2").arg(file, f.errorString()));
    const QByteArray head = f.read(kHeadBytes);
    for (const auto& candidate : importers())
        if (candidate->canRead(file, head)) return candidate.get();
    return makeError(QStringLiteral("%1: cannot tell the file format; give one of: %2").arg(file, known()));
}

const Importer* findImporter(const QString& format) {
    for (const auto& importer : importers())
        if (importer->format() == format) return importer.get();
    return nullptr;
}

Expected<ImportResult> importFile(const QString& file, const ImportOptions& options, const Progress& progress) {
    const QFileInfo info(file);
    if (!info.exists()) return makeError(QStringLiteral("%1: no such file").arg(file));
    if (!info.isFile()) return makeError(QStringLiteral("%1: not a file").arg(file));
    const auto target = parseTarget(options.target, file);
    if (!target) return target.error();

    const auto chosen = chooseImporter(file, options.format);
    if (!chosen) return chosen.error();
    const Importer* importer = *chosen;
    if (!options.columns.empty() || !options.timeColumn.isEmpty() || !options.timeUnit.isEmpty() ||
        options.dropUnmapped)
        if (!importer->mapsColumns())
            return makeError(QStringLiteral("%1: a column mapping applies to CSV files only (format '%2')")
                                 .arg(file, importer->format()));

    auto result = importer->read(file, options, progress);
    if (!result) return result;
    const Provenance provenance = importProvenance(*importer, file, options);
    if (!options.metadata.isEmpty()) result->recordingMetadata[target->recording] = options.metadata;
    result->origin = options.origin;
    if (auto it = result->annotations.find(QString()); it != result->annotations.end()) {
        Annotations own = std::move(it->second);
        result->annotations.erase(it);
        auto& list = result->annotations[target->recording];
        list.insert(list.end(), own.begin(), own.end());
    }
    const bool several = result->items.size() > 1;
    for (ImportedItem& item : result->items) {
        const QString defaultName = item.path;
        const QString name = target->item.isEmpty() ? defaultName
                             : several              ? target->item + QLatin1Char('-') + defaultName
                                                    : target->item;
        item.path = target->recording + QLatin1Char('/') + name;
        if (auto* stream = std::get_if<Stream>(&item.item)) {
            stream->info().name = name;
            stream->info().provenance = provenance;
            if (!options.frame.isEmpty()) stream->info().frame = options.frame;
        } else {
            auto& table = std::get<Table>(item.item);
            table.name = name;
            table.provenance = provenance;
            if (!options.frame.isEmpty()) table.attributes.insert(QStringLiteral("frame"), options.frame);
        }
    }
    return result;
}

Expected<std::map<QString, QString>> parseLabelNames(const QString& text) {
    std::map<QString, QString> names;
    for (const QString& pair : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const qsizetype eq = pair.indexOf(QLatin1Char('='));
        if (eq <= 0 || pair.left(eq).trimmed().isEmpty() || pair.mid(eq + 1).trimmed().isEmpty())
            return makeError(
                QStringLiteral("label names: '%1' is not VALUE=NAME (e.g. 0=rest,1=run)").arg(pair.trimmed()));
        names[pair.left(eq).trimmed()] = pair.mid(eq + 1).trimmed();
    }
    return names;
}

Status applyImport(Project& project, ImportResult result, bool overwrite) {
    QSet<QString> seen;
    for (const ImportedItem& item : result.items) {
        const ItemPath path = ItemPath::parse(item.path);
        if (!path.isValid())
            return makeError(QStringLiteral("'%1' is not a valid item name (<recording>/<stream>)").arg(item.path));
        if (seen.contains(item.path))
            return makeError(QStringLiteral("the import has two items named '%1'").arg(item.path));
        seen.insert(item.path);
        if (!overwrite && (project.stream(item.path) || project.table(item.path)))
            return makeError(
                QStringLiteral("'%1' already exists in the project (overwrite to replace it)").arg(item.path));
    }
    // The project's geodetic origin, and every GNSS stream in its ENU frame (before anything changes).
    std::optional<GeodeticOrigin> origin = projectOrigin(project.meta());
    if (origin && result.origin && !(*origin == *result.origin))
        return makeError(QStringLiteral("the project's geodetic origin is %1, %2, %3 m; it cannot change (all GNSS "
                                        "streams share it)")
                             .arg(origin->lat, 0, 'g', 12)
                             .arg(origin->lon, 0, 'g', 12)
                             .arg(origin->height));
    bool newOrigin = false;
    if (!origin && result.origin) {
        origin = result.origin;
        newOrigin = true;
    }
    for (ImportedItem& item : result.items) {
        auto* stream = std::get_if<Stream>(&item.item);
        if (!stream || stream->kind() != QLatin1String("gnss")) continue;
        if (!origin) {
            origin = firstFix(*stream);
            newOrigin = origin.has_value();
        }
        if (!origin) continue;
        if (auto added = addLocalEnu(*stream, *origin); !added)
            return makeError(QStringLiteral("%1: %2").arg(item.path, added.message()));
    }
    for (const auto& [name, annotations] : result.annotations) {
        if (annotations.empty()) continue;
        if (!ItemPath::parse(name + QStringLiteral("/x")).isValid())
            return makeError(QStringLiteral("'%1' is not a valid recording name").arg(name));
        const Recording* rec = project.recording(name);
        if (!rec || overwrite) continue;
        for (const Annotation& a : rec->annotations)
            for (const Annotation& b : annotations)
                if (a.source == b.source && a.annotator == b.annotator)
                    return makeError(QStringLiteral("'%1' already has annotations from %2 (overwrite to replace them)")
                                         .arg(name, b.annotator));
    }
    for (ImportedItem& item : result.items) {
        if (project.stream(item.path) || project.table(item.path))
            project.removeItem(item.path);  // a table may replace a stream and vice versa
        if (auto* stream = std::get_if<Stream>(&item.item))
            project.putStream(item.path, std::move(*stream));
        else
            project.putTable(item.path, std::move(std::get<Table>(item.item)));
    }
    for (auto& [name, imported] : result.annotations) {
        // A plain reference: clang 14 cannot capture structured bindings in lambdas.
        const Annotations& annotations = imported;
        if (annotations.empty()) continue;
        Annotations& existing = project.ensureRecording(name).annotations;
        std::erase_if(existing, [&](const Annotation& a) {
            return std::any_of(annotations.begin(), annotations.end(),
                               [&](const Annotation& b) { return a.source == b.source && a.annotator == b.annotator; });
        });
        existing.insert(existing.end(), annotations.begin(), annotations.end());
    }
    if (newOrigin) {
        setProjectOrigin(project.meta(), *origin);
        project.setModified();
    }
    for (const auto& [name, metadata] : result.recordingMetadata) {
        QJsonObject& merged = project.ensureRecording(name).metadata;
        for (auto it = metadata.begin(); it != metadata.end(); ++it) merged.insert(it.key(), it.value());
    }
    return {};
}

}  // namespace athlos
