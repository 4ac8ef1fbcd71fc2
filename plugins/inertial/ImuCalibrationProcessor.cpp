#include "plugins/inertial/ImuCalibrationProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "core/util/Units.h"
#include "plugins/inertial/CalibrationPlausibility.h"
#include "plugins/inertial/ImuCalibration.h"
#include "plugins/inertial/ImuColumns.h"

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "ImuCalibrationProcessor"};

struct Calibration {
    Vec3 gyrOffset = Vec3::Zero();
    AccCalibration acc;
    MagCalibration mag;
};

const QStringList kRows{"gyr_offset",      "acc_offset",      "acc_scale",      "mag_hard_iron",
                        "mag_soft_iron_0", "mag_soft_iron_1", "mag_soft_iron_2"};

Table toTable(const Calibration& c, QJsonObject attributes) {
    Table t;
    t.kind = QStringLiteral("calibration");
    t.attributes = std::move(attributes);
    TableColumn name{QStringLiteral("parameter"), QString(), true, {}, kRows};
    TableColumn x{QStringLiteral("x"), QString(), false, {}, {}}, y = x, z = x;
    y.name = QStringLiteral("y");
    z.name = QStringLiteral("z");
    const std::vector<Vec3> rows{c.gyrOffset,
                                 c.acc.offset,
                                 c.acc.scale,
                                 c.mag.hardIron,
                                 c.mag.softIron.row(0).transpose(),
                                 c.mag.softIron.row(1).transpose(),
                                 c.mag.softIron.row(2).transpose()};
    for (const Vec3& v : rows) {
        x.numbers.push_back(v.x());
        y.numbers.push_back(v.y());
        z.numbers.push_back(v.z());
    }
    t.columns = {name, x, y, z};
    return t;
}

Expected<Calibration> fromTable(const Table& t, const QString& path) {
    const TableColumn* name = t.column(QStringLiteral("parameter"));
    const TableColumn* x = t.column(QStringLiteral("x"));
    const TableColumn* y = t.column(QStringLiteral("y"));
    const TableColumn* z = t.column(QStringLiteral("z"));
    if (!name || !x || !y || !z || !name->isText)
        return makeError(QStringLiteral("calibration table '%1' needs columns parameter, x, y, z").arg(path));
    std::vector<Vec3> rows(kRows.size());
    for (int i = 0; i < kRows.size(); ++i) {
        const int r = static_cast<int>(name->texts.indexOf(kRows[i]));
        if (r < 0) return makeError(QStringLiteral("calibration table '%1' has no row '%2'").arg(path, kRows[i]));
        rows[i] = Vec3(x->numbers.at(r), y->numbers.at(r), z->numbers.at(r));
    }
    Calibration c;
    c.gyrOffset = rows[0];
    c.acc.offset = rows[1];
    c.acc.scale = rows[2];
    c.mag.hardIron = rows[3];
    c.mag.softIron << rows[4].transpose(), rows[5].transpose(), rows[6].transpose();
    return c;
}
}  // namespace

QString ImuCalibrationProcessor::name() const { return tr("IMU calibration"); }

QString ImuCalibrationProcessor::description() const {
    return tr(
        "Gyroscope offset from rest periods, accelerometer offset and scale from at least six static positions "
        "(each axis up and down), magnetometer hard/soft iron from an ellipsoid fit, and a saturation check. "
        "Writes the calibrated stream and the calibration table (<output>-calibration); given a calibration "
        "table as second input it applies that instead of estimating.");
}

ParameterSpecs ImuCalibrationProcessor::parameters() const {
    const QStringList modes{QStringLiteral("auto"), QStringLiteral("on"), QStringLiteral("off")};
    return {
        ParameterSpec::choice(QStringLiteral("gyr_offset"), modes, QStringLiteral("auto"),
                              tr("Estimate the gyroscope offset from rest periods (auto: when there is rest).")),
        ParameterSpec::choice(
            QStringLiteral("acc_calibration"), modes, QStringLiteral("auto"),
            tr("Estimate accelerometer offset/scale (auto: when ≥ 6 static positions cover ±g on each axis).")),
        ParameterSpec::choice(
            QStringLiteral("mag_calibration"), modes, QStringLiteral("auto"),
            tr("Fit magnetometer hard/soft iron (auto: when mag columns exist and the fit succeeds).")),
        ParameterSpec::number(QStringLiteral("min_static"), 1.5, 0.1, 60.0, QStringLiteral("s"),
                              tr("Shortest static position.")),
        ParameterSpec::number(QStringLiteral("gravity"), 9.81, 9.7, 9.9, QStringLiteral("m/s^2"), tr("Local gravity.")),
        ParameterSpec::number(QStringLiteral("acc_range"), 0.0, 0.0, 10000.0, QStringLiteral("m/s^2"),
                              tr("Accelerometer range for the saturation check (0: detect clipping).")),
        ParameterSpec::number(QStringLiteral("gyr_range"), 0.0, 0.0, 1000.0, QStringLiteral("rad/s"),
                              tr("Gyroscope range for the saturation check (0: detect clipping).")),
        // Plausibility of the result; defaults and sources in CalibrationPlausibility.h.
        ParameterSpec::number(QStringLiteral("mag_field_min"), 22.0, 0.0, 1e4, QStringLiteral("uT"),
                              tr("Smallest plausible magnetic field after calibration (median |m|); default: the "
                                 "minimum geomagnetic total intensity at the Earth's surface (World Magnetic Model).")),
        ParameterSpec::number(QStringLiteral("mag_field_max"), 67.0, 0.0, 1e4, QStringLiteral("uT"),
                              tr("Largest plausible magnetic field after calibration; default: the maximum geomagnetic "
                                 "total intensity at the Earth's surface (World Magnetic Model).")),
        ParameterSpec::number(QStringLiteral("acc_norm_tolerance"), 0.03, 0.0, 1.0, QStringLiteral("1"),
                              tr("Largest plausible deviation of |a| at rest from gravity after calibration, as a "
                                 "fraction of gravity; default: the ±3 % factory tolerance of MEMS accelerometers.")),
        ParameterSpec::number(QStringLiteral("acc_scale_tolerance"), 0.10, 0.0, 10.0, QStringLiteral("1"),
                              tr("Largest plausible |scale − 1| of a fitted accelerometer axis (datasheet tolerances, "
                                 "rounded up).")),
        ParameterSpec::boolean(QStringLiteral("accept_implausible"), false,
                               tr("Store a calibration that fails the plausibility checks, flagged in the attribute "
                                  "'implausible' of both outputs, instead of refusing it.")),
    };
}

QList<InputSpec> ImuCalibrationProcessor::inputs() const {
    return {InputSpec{QStringLiteral("imu"), {QStringLiteral("imu")}, false, false, tr("IMU stream to calibrate.")},
            InputSpec{QStringLiteral("calibration"),
                      {QStringLiteral("calibration")},
                      true,
                      true,
                      tr("Optional calibration table to apply instead of estimating one.")}};
}

QList<OutputSpec> ImuCalibrationProcessor::outputs() const {
    return {
        OutputSpec{QStringLiteral("imu"), false, QString(), tr("Calibrated IMU stream.")},
        OutputSpec{
            QStringLiteral("calibration"), true, QStringLiteral("calibration"),
            tr("Calibration parameters: rows gyr_offset, acc_offset, acc_scale, mag_hard_iron, mag_soft_iron_0..2.")}};
}

Expected<std::vector<ProcessorOutput>> ImuCalibrationProcessor::run(const RunContext& c) const {
    auto input = c.samples(0);
    if (!input) return input.error();
    const StreamData& in = *input->data;
    auto columns = imuColumns(*input, false);
    if (!columns) return columns.error();
    auto ts = input->samplingInterval();
    if (!ts) return ts.error();
    const auto stride = static_cast<std::size_t>(in.columns);
    const ImuBatch batch{in.values.data() + columns->gyr, in.values.data() + columns->acc,
                         columns->mag >= 0 ? in.values.data() + columns->mag : nullptr, in.rows(), stride};
    const auto mode = [&](const char* n) {
        return c.has(QLatin1String(n)) ? c.text(QLatin1String(n)) : QStringLiteral("auto");
    };
    const double gravity = c.has(QStringLiteral("gravity")) ? c.number(QStringLiteral("gravity")) : 9.81;

    Calibration cal;
    QJsonObject attributes;
    QStringList estimated;
    std::vector<Vec3> staticMeans;  // raw accelerometer means of the rest segments
    if (c.inputCount() > 1 && c.table(1)) {
        auto given = fromTable(*c.table(1), c.inputPath(1));
        if (!given) return given.error();
        cal = *given;
        attributes.insert(QStringLiteral("applied_from"), c.inputPath(1));
        const double minStatic = c.has(QStringLiteral("min_static")) ? c.number(QStringLiteral("min_static")) : 1.5;
        for (const auto& s : findStaticSegments(batch, *ts, minStatic)) staticMeans.push_back(s.acc);
    } else {
        c.report(0.1, QStringLiteral("finding static periods"));
        const double minStatic = c.has(QStringLiteral("min_static")) ? c.number(QStringLiteral("min_static")) : 1.5;
        const auto segments = findStaticSegments(batch, *ts, minStatic);
        for (const auto& s : segments) staticMeans.push_back(s.acc);
        attributes.insert(QStringLiteral("static_segments"), static_cast<int>(segments.size()));
        if (c.isCancelled()) return cancelledError();
        if (mode("gyr_offset") != QLatin1String("off")) {
            if (segments.empty() && mode("gyr_offset") == QLatin1String("on"))
                return makeError(QStringLiteral("gyr_offset: no rest period of at least min_static found in '%1'")
                                     .arg(c.inputPath(0)));
            double n = 0;
            for (const auto& s : segments) {
                const double w = static_cast<double>(s.end - s.begin);
                cal.gyrOffset += w * s.gyr;
                n += w;
            }
            if (n > 0) {
                cal.gyrOffset /= n;
                estimated << QStringLiteral("gyr_offset");
            }
        }
        if (mode("acc_calibration") != QLatin1String("off")) {
            c.report(0.3, QStringLiteral("accelerometer calibration"));
            std::vector<Vec3> means;
            for (const auto& s : segments) means.push_back(s.acc);
            const auto acc = calibrateAccelerometer(means, gravity);
            if (acc) {
                cal.acc = *acc;
                estimated << QStringLiteral("acc");
                attributes.insert(QStringLiteral("acc_rms"), acc->rms);
            } else if (mode("acc_calibration") == QLatin1String("on")) {
                return makeError(QStringLiteral("acc_calibration: need at least 6 static positions of min_static with "
                                                "each axis pointing up and down; found %1 static periods")
                                     .arg(segments.size()));
            }
        }
        if (mode("mag_calibration") != QLatin1String("off") && columns->mag >= 0) {
            c.report(0.6, QStringLiteral("magnetometer ellipsoid fit"));
            std::vector<Vec3> samples;
            const std::size_t step = std::max<std::size_t>(1, in.rows() / 5000);  // the fit needs spread, not density
            for (std::size_t r = 0; r < in.rows(); r += step)
                samples.emplace_back(batch.mag[r * stride], batch.mag[r * stride + 1], batch.mag[r * stride + 2]);
            const auto mag = calibrateMagnetometer(samples);
            if (mag) {
                cal.mag = *mag;
                estimated << QStringLiteral("mag");
                attributes.insert(QStringLiteral("mag_rms"), mag->rms);
                attributes.insert(QStringLiteral("mag_radius"), mag->radius);
            } else if (mode("mag_calibration") == QLatin1String("on")) {
                return makeError(
                    QStringLiteral("mag_calibration: the ellipsoid fit failed (rotate the sensor through many "
                                   "directions away from magnetic disturbances)"));
            }
        } else if (mode("mag_calibration") == QLatin1String("on")) {
            return makeError(
                QStringLiteral("mag_calibration: stream '%1' has no mag_x..z columns").arg(c.inputPath(0)));
        }
    }
    attributes.insert(QStringLiteral("estimated"), estimated.join(QLatin1Char(',')));
    const Eigen::Vector3i satAcc = countSaturated(batch.acc, in.rows(), stride, c.number(QStringLiteral("acc_range")));
    const Eigen::Vector3i satGyr = countSaturated(batch.gyr, in.rows(), stride, c.number(QStringLiteral("gyr_range")));
    attributes.insert(QStringLiteral("saturated_acc"), satAcc.sum());
    attributes.insert(QStringLiteral("saturated_gyr"), satGyr.sum());
    if (c.isCancelled()) return cancelledError();

    c.report(0.8, QStringLiteral("applying"));
    StreamData out = in;
    for (std::size_t r = 0; r < out.rows(); ++r) {
        double* row = &out.values[r * stride];
        const Vec3 g = Vec3(row[columns->gyr], row[columns->gyr + 1], row[columns->gyr + 2]) - cal.gyrOffset;
        const Vec3 a = cal.acc.apply(Vec3(row[columns->acc], row[columns->acc + 1], row[columns->acc + 2]));
        for (int i = 0; i < 3; ++i) {
            row[columns->gyr + i] = g[i];
            row[columns->acc + i] = a[i];
        }
        if (columns->mag >= 0) {
            const Vec3 m = cal.mag.apply(Vec3(row[columns->mag], row[columns->mag + 1], row[columns->mag + 2]));
            for (int i = 0; i < 3; ++i) row[columns->mag + i] = m[i];
        }
    }
    // Plausibility of what was estimated or applied (CalibrationPlausibility.h).
    const auto limit = [&](const char* n, double fallback) {
        return c.has(QLatin1String(n)) ? c.number(QLatin1String(n)) : fallback;
    };
    const PlausibilityLimits limits{limit("mag_field_min", 22.0), limit("mag_field_max", 67.0),
                                    limit("acc_norm_tolerance", 0.03), limit("acc_scale_tolerance", 0.10)};
    const bool applied = attributes.contains(QStringLiteral("applied_from"));
    const bool accCalibrated = estimated.contains(QStringLiteral("acc")) ||
                               (applied && (cal.acc.offset != Vec3::Zero() || cal.acc.scale != Vec3::Ones()));
    const bool magCalibrated =
        columns->mag >= 0 && (estimated.contains(QStringLiteral("mag")) ||
                              (applied && (cal.mag.hardIron != Vec3::Zero() || cal.mag.softIron != Mat3::Identity())));
    QStringList implausible;
    if (accCalibrated) implausible << checkAccelerometer(cal.acc, staticMeans, gravity, limits);
    if (magCalibrated) {
        // Stored in µT by the importers (SI-ish convention of Column.h); another declared unit is converted.
        double toMicroTesla = 1.0;
        if (const QString unit = input->info().columns[std::size_t(columns->mag)].unit; !unit.isEmpty())
            if (auto conversion = conversionTo(unit, QStringLiteral("uT"))) toMicroTesla = conversion->scale;
        const double field = toMicroTesla * medianFieldNorm(out.values.data() + columns->mag, out.rows(), stride);
        attributes.insert(QStringLiteral("mag_field_median"), field);
        implausible << checkMagnetometer(field, limits);
    }
    if (!implausible.isEmpty()) {
        if (!c.flag(QStringLiteral("accept_implausible")))
            return makeError(
                QStringLiteral("implausible calibration of '%1': %2; nothing was stored (to store it anyway, "
                               "flagged, set accept_implausible=true)")
                    .arg(c.inputPath(0), implausible.join(QStringLiteral("; "))));
        attributes.insert(QStringLiteral("implausible"), implausible.join(QStringLiteral("; ")));
    }

    Stream calibrated = derivedStream(*input->stream, std::move(out));
    calibrated.info().attributes.insert(QStringLiteral("calibrated"), true);
    if (!implausible.isEmpty())
        calibrated.info().attributes.insert(QStringLiteral("implausible"), implausible.join(QStringLiteral("; ")));
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(calibrated)});
    outputs.push_back({QStringLiteral("calibration"), toTable(cal, attributes)});
    c.report(1.0);
    return outputs;
}

}  // namespace athlos::inertial
