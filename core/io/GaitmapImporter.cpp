#include "core/io/GaitmapImporter.h"

#include "core/io/CsvImporter.h"
#include "core/io/CsvReader.h"
#include "core/io/ImuSamplingRate.h"
#include "core/model/StreamKinds.h"
#include "core/util/Units.h"

#include <QFileInfo>
#include <algorithm>
#include <cmath>
#include <map>

namespace athlos {
namespace {

const QStringList kAxisOrder{"acc_x", "acc_y", "acc_z", "gyr_x", "gyr_y", "gyr_z"};

// The side a sensor name says: gaitmap's left_sensor / right_sensor, and the forms of its datasets
// and of other exports (l_lateral, r_instep, left_foot, foot_l, LeftFoot, footRight, …): −1 left, +1
// right, 0 neither. The word may start or end the name; the single letter needs a separator.
int sideOf(const QString& sensor) {
    const QString s = sensor.toLower();
    const auto is = [&](const char* word, const char* letter) {
        const QString w = QLatin1String(word), l = QLatin1String(letter);
        return s.startsWith(w) || s.endsWith(w) || s.startsWith(l + u'_') || s.startsWith(l + u'-') ||
               s.endsWith(u'_' + l) || s.endsWith(u'-' + l);
    };
    return is("left", "l") ? -1 : is("right", "r") ? 1 : 0;
}

// Whether a sensor name says a body part other than the foot (l_wrist, LeftThigh, r_ankle, …): such a
// sensor is never one of the feet, whatever its side.
bool namesAnotherBodyPart(const QString& sensor) {
    static const char* const parts[] = {"wrist", "hand",  "arm",     "elbow", "shoulder", "thigh",  "shank",
                                        "shin",  "knee",  "ankle",   "leg",   "hip",      "pelvis", "sacrum",
                                        "trunk", "chest", "sternum", "head",  "waist"};
    const QString s = sensor.toLower();
    return std::any_of(std::begin(parts), std::end(parts), [&](const char* p) { return s.contains(QLatin1String(p)); });
}

// The stream of each sensor: left-foot and right-foot when the file has one foot sensor of each side
// (a side, and no other body part named; the names the gait processors and their documentation use),
// else the sensor's own name (l_ankle → l-ankle; left_sensor / right_sensor are always the feet).
QString streamNameFor(const QString& sensor, const QStringList& sensors) {
    if (sensor == QLatin1String("left_sensor")) return QStringLiteral("left-foot");
    if (sensor == QLatin1String("right_sensor")) return QStringLiteral("right-foot");
    const auto footSide = [](const QString& s) { return namesAnotherBodyPart(s) ? 0 : sideOf(s); };
    int left = 0, right = 0;
    for (const QString& s : sensors) {
        left += footSide(s) < 0;
        right += footSide(s) > 0;
    }
    if (left == 1 && right == 1 && footSide(sensor) != 0)
        return footSide(sensor) < 0 ? QStringLiteral("left-foot") : QStringLiteral("right-foot");
    QString name = sensor;
    if (name.endsWith(QLatin1String("_sensor"))) name.chop(7);
    return name.replace(QLatin1Char('_'), QLatin1Char('-'));
}

struct SensorColumn {
    int fileColumn;  // 0-based column in the file
    QString axis;
    QString unit;
    double scale = 1.0;
    double offset = 0.0;
    QString sourceUnit{};  // unit in the file, when converted
};

// Sample index (consecutive integers) or time in seconds: see the header.
bool isSampleIndex(const std::vector<double>& first) {
    for (size_t i = 0; i < first.size(); ++i)
        if (first[i] != std::round(first[i]) || (i > 0 && first[i] != first[i - 1] + 1.0)) return false;
    return true;
}

// The sampling rate of a file whose first column is a sample index: the caller's, or the one of
// kIndexRates whose gyroscope agrees best with the accelerometer (ImuSamplingRate), said in a warning.
Expected<double> indexRate(const QString& file, const StreamData& all,
                           const std::map<QString, std::vector<SensorColumn>>& bySensor, double given,
                           QStringList& warnings, QString& source) {
    source = QStringLiteral("given");
    if (given > 0.0) return given;
    std::vector<ImuSamplingRate::Imu> imus;
    for (const auto& entry : bySensor) {
        const std::vector<SensorColumn>& columns = entry.second;  // a plain reference: lambdas capture it
        int at[6] = {-1, -1, -1, -1, -1, -1};
        for (const SensorColumn& c : columns)
            if (const qsizetype i = kAxisOrder.indexOf(c.axis); i >= 0) at[i] = int(&c - columns.data());
        if (std::any_of(std::begin(at), std::end(at), [](int i) { return i < 0; })) continue;
        ImuSamplingRate::Imu imu;
        const auto value = [&](std::size_t r, int axis) {
            const SensorColumn& c = columns[std::size_t(at[axis])];
            return all.at(r, c.fileColumn) * c.scale + c.offset;
        };
        for (std::size_t r = 0; r < all.rows(); ++r) {
            imu.acc.emplace_back(value(r, 0), value(r, 1), value(r, 2));
            imu.gyr.emplace_back(value(r, 3), value(r, 4), value(r, 5));
        }
        imus.push_back(std::move(imu));
    }
    const std::vector<double> rates(std::begin(GaitmapImporter::kIndexRates), std::end(GaitmapImporter::kIndexRates));
    const ImuSamplingRate estimator;
    const std::vector<ImuSamplingRate::Candidate> scored = estimator.scores(imus, rates);
    auto best = estimator.best(scored);
    if (!best) {
        warnings << QStringLiteral("%1: the first column is a sample index and the rate cannot be told from the "
                                   "motion (%2); %3 Hz assumed: give the rate with --rate")
                        .arg(file, imus.empty() ? QStringLiteral("no sensor with acc_x…gyr_z") : best.message())
                        .arg(GaitmapImporter::kIndexRate);
        source = QStringLiteral("assumed");
        return GaitmapImporter::kIndexRate;
    }
    QStringList others;
    for (const auto& c : scored)
        if (c.rate != best->rate) others << QStringLiteral("%1 Hz %2").arg(c.rate).arg(c.score, 0, 'f', 3);
    warnings << QStringLiteral("%1: the first column is a sample index; sampling rate %2 Hz from the motion "
                               "(gyroscope/accelerometer disagreement %3 against %4); give --rate to set it")
                    .arg(file)
                    .arg(best->rate)
                    .arg(best->score, 0, 'f', 3)
                    .arg(others.join(QStringLiteral(", ")));
    source = QStringLiteral("motion");
    return best->rate;
}

// pandas writes the names of the column levels into the index column: "sensor" / "axis".
bool isLevelName(const QString& cell) { return cell.compare(QLatin1String("sensor"), Qt::CaseInsensitive) == 0; }

double medianInterval(const std::vector<double>& t) {
    if (t.size() < 2) return 0.0;
    std::vector<double> d(t.size() - 1);
    for (size_t i = 1; i < t.size(); ++i) d[i - 1] = t[i] - t[i - 1];
    std::nth_element(d.begin(), d.begin() + ptrdiff_t(d.size() / 2), d.end());
    return d[d.size() / 2];
}

}  // namespace

QString GaitmapImporter::description() const {
    return QStringLiteral("gaitmap foot IMU CSV (two header rows: sensor, axis; gyr in deg/s)");
}

bool GaitmapImporter::canRead(const QString& file, const QByteArray& head) const {
    if (QFileInfo(file).suffix().toLower() != QLatin1String("csv")) return false;
    const QList<QByteArray> lines = head.split('\n');
    if (lines.size() < 2 || !(lines[1].contains("acc_") || lines[1].contains("gyr_"))) return false;
    // gaitmap's sensor names, or any sensor row over pandas' axis row (its index cell empty or "axis").
    const QByteArray axisIndex = lines[1].left(lines[1].indexOf(',')).trimmed().toLower();
    return lines[0].contains("left_sensor") || lines[0].contains("right_sensor") ||
           (lines[1].contains(',') && (axisIndex.isEmpty() || axisIndex == "axis"));
}

Expected<ImportResult> GaitmapImporter::read(const QString& file, const ImportOptions& options,
                                             const Progress& progress) const {
    MappedFile mapped;
    if (Status s = mapped.open(file); !s) return s.error();
    CsvReader reader(mapped.begin(), mapped.end());
    QStringList sensors, axes;
    if (!reader.readHeader(sensors)) return makeError(QStringLiteral("%1: empty file (no header rows)").arg(file));
    if (!reader.readHeader(axes))
        return makeError(QStringLiteral("%1: the second header row (axes) is missing").arg(file));
    const long long axisLine = reader.line();
    // pandas writes the index name as a third header row ("sample,,,...") when the index has one.
    {
        CsvReader peek = reader;
        QStringList cells;
        bool ok = false;
        if (peek.readHeader(cells) && !cells.isEmpty() && !cells[0].trimmed().isEmpty()) {
            cells[0].trimmed().toDouble(&ok);
            const bool restEmpty =
                std::all_of(cells.begin() + 1, cells.end(), [](const QString& c) { return c.trimmed().isEmpty(); });
            if (!ok && restEmpty) reader = peek;
        }
    }
    if (axes.size() != sensors.size())
        return makeError(QStringLiteral("%1:%2: the axis row has %3 fields, the sensor row %4")
                             .arg(file)
                             .arg(axisLine)
                             .arg(axes.size())
                             .arg(sensors.size()));

    // Group columns by sensor, in order of first appearance; the column without a sensor is time.
    const StreamKind* imu = findStreamKind(QStringLiteral("imu"));
    int timeColumn = -1;
    QStringList order;
    std::map<QString, std::vector<SensorColumn>> bySensor;
    for (int i = 0; i < sensors.size(); ++i) {
        const QString sensor = sensors[i].trimmed();
        // The index column's sensor cell is empty, or the level name "sensor" when pandas wrote it.
        if (sensor.isEmpty() || (i == 0 && isLevelName(sensor))) {
            if (timeColumn >= 0)
                return makeError(
                    QStringLiteral("%1:1:%2: a second column without a sensor name (the first is column %3)")
                        .arg(file)
                        .arg(i + 1)
                        .arg(timeColumn + 1));
            timeColumn = i;
            continue;
        }
        SensorColumn col{i, {}, {}};
        QString unit;
        splitNameAndUnit(axes[i], col.axis, unit);
        const QString at =
            QStringLiteral("%1:%2:%3 (column '%4/%5')").arg(file).arg(axisLine).arg(i + 1).arg(sensor, col.axis);
        if (unit.isEmpty() && col.axis.startsWith(QLatin1String("gyr_")))
            unit = QStringLiteral("deg/s");  // gaitmap's convention
        col.unit = imu->unitFor(col.axis);
        if (col.unit.isEmpty()) {
            col.unit = unit;
        } else {
            const auto conversion = conversionTo(unit, col.unit);
            if (!conversion) return makeError(QStringLiteral("%1: %2").arg(at, conversion.message()));
            col.scale = conversion->scale;
            col.offset = conversion->offset;
            if (col.scale != 1.0 || col.offset != 0.0) col.sourceUnit = unit;
        }
        auto& columns = bySensor[sensor];
        if (std::any_of(columns.begin(), columns.end(), [&](const SensorColumn& c) { return c.axis == col.axis; }))
            return makeError(QStringLiteral("%1: duplicate column").arg(at));
        if (columns.empty()) order << sensor;
        columns.push_back(col);
    }
    if (timeColumn < 0)
        return makeError(QStringLiteral("%1:1: no index/time column (a column with an empty sensor name)").arg(file));
    if (order.isEmpty()) return makeError(QStringLiteral("%1:1: no sensor columns").arg(file));

    // All file columns into one block; time repair then applies to all sensors alike.
    const int width = int(sensors.size());
    StreamData all;
    all.columns = width;
    TimeOrigin origin{file, timeColumn + 1, QStringLiteral("(index/time)"), {}};
    std::vector<double> first;
    const qint64 total = std::max<qint64>(mapped.size(), 1);
    while (reader.nextRecord()) {
        for (int c = 0; c < width; ++c) {
            double v;
            const auto field = reader.number(v);
            const auto at = [&] {  // only built for a message: this loop is hot
                const QString name = c == timeColumn ? origin.columnName : sensors[c] + QLatin1Char('/') + axes[c];
                return QStringLiteral("%1:%2:%3 (column '%4')").arg(file).arg(reader.line()).arg(c + 1).arg(name);
            };
            if (field == CsvReader::Field::Missing)
                return makeError(QStringLiteral("%1: line has %2 fields, the header has %3")
                                     .arg(at())
                                     .arg(reader.fieldsOnLine())
                                     .arg(width));
            if (field == CsvReader::Field::Invalid) {
                const auto raw = reader.lastField();
                return makeError(QStringLiteral("%1: '%2' is not a number")
                                     .arg(at(), QString::fromUtf8(raw.data(), qsizetype(raw.size()))));
            }
            if (std::isinf(v) || (c == timeColumn && !std::isfinite(v)))
                return makeError(QStringLiteral("%1: not a finite number").arg(at()));
            if (c == timeColumn) first.push_back(v);
            all.values.push_back(v);
        }
        if (!reader.finishRecord())
            return makeError(QStringLiteral("%1:%2:%3: line has %4 fields, the header has %3")
                                 .arg(file)
                                 .arg(reader.line())
                                 .arg(width + 1)
                                 .arg(reader.fieldsOnLine())
                                 .arg(width));
        origin.lines.push_back(reader.line());
        if ((origin.lines.size() & 4095) == 0) {
            if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
            progress.report(double(reader.offset()) / double(total));
        }
    }
    if (first.empty()) return makeError(QStringLiteral("%1: no data rows after the header").arg(file));

    const bool index = isSampleIndex(first);
    ImportResult result;
    all.t = first;
    double rate = 0.0;
    QString rateSource = QStringLiteral("time column");
    if (index) {
        auto r = indexRate(file, all, bySensor, options.rate, result.warnings, rateSource);
        if (!r) return r.error();
        rate = *r;
    } else if (options.rate > 0.0) {
        result.warnings << QStringLiteral("%1: the first column is time in seconds; the sampling rate %2 Hz is not used")
                               .arg(file)
                               .arg(options.rate);
    }
    if (index)
        for (double& t : all.t) t /= rate;
    if (Status s = repairTimeOrder(all, origin, options.timeRepair, false, result.warnings); !s) return s.error();
    if (!index) rate = 1.0 / medianInterval(all.t);

    for (const QString& sensor : order) {
        auto columns = bySensor[sensor];
        std::stable_sort(columns.begin(), columns.end(), [](const SensorColumn& a, const SensorColumn& b) {
            const auto rank = [](const QString& axis) {
                const qsizetype i = kAxisOrder.indexOf(axis);
                return i < 0 ? kAxisOrder.size() : i;
            };
            return rank(a.axis) < rank(b.axis);
        });
        StreamInfo info;
        info.name = streamNameFor(sensor, order);
        info.kind = QStringLiteral("imu");
        info.frame = imu->defaultFrame;
        info.attributes.insert(QStringLiteral("sampling_rate"), rate);
        // Where the rate comes from: "time column", "given" (--rate), "motion" (ImuSamplingRate) or "assumed".
        info.attributes.insert(QStringLiteral("sampling_rate_source"), rateSource);
        info.attributes.insert(QStringLiteral("sensor"), sensor);
        info.attributes.insert(QStringLiteral("time_column"),
                               index ? QStringLiteral("sample index") : QStringLiteral("seconds"));
        StreamData data(all.rows(), int(columns.size()));
        data.t = all.t;
        for (size_t r = 0; r < all.rows(); ++r)
            for (size_t c = 0; c < columns.size(); ++c) {
                const SensorColumn& col = columns[c];
                data.at(r, int(c)) = all.at(r, col.fileColumn) * col.scale + col.offset;
            }
        QJsonObject sourceUnits;
        for (const SensorColumn& col : columns) {
            info.columns.push_back({col.axis, col.unit});
            if (!col.sourceUnit.isEmpty()) sourceUnits.insert(col.axis, col.sourceUnit);
        }
        if (!sourceUnits.isEmpty())  // as the CSV importer does: what the file said, for provenance
            info.attributes.insert(QStringLiteral("source_units"), sourceUnits);
        result.items.push_back({info.name, Stream(std::move(info), std::move(data))});
    }
    progress.report(1.0);
    return result;
}

}  // namespace athlos
