#include "plugins/inertial/GnssImuProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/GnssImuFusion.h"
#include "plugins/inertial/ImuColumns.h"
#include "plugins/inertial/LocalTangentPlane.h"

#include <cmath>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "GnssImuProcessor"};
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Plan {
    InputSamples imu, gnss;
    ImuColumns columns;
    GnssSeries series;
    GnssImuEkf::Params params;
    double ts = 0.0;
    QJsonObject origin;
};

// GNSS samples in a local ENU frame: geodetic columns through the tangent plane at the first fix.
Expected<GnssSeries> gnssSeries(const StreamInfo& info, const StreamData& data, const QString& path, bool useVelocity,
                                QJsonObject& origin) {
    GnssSeries s;
    s.t = data.t;
    const int lat = info.columnIndex(QStringLiteral("lat")), lon = info.columnIndex(QStringLiteral("lon")),
              alt = info.columnIndex(QStringLiteral("alt"));
    const int x = info.columnIndex(QStringLiteral("x")), y = info.columnIndex(QStringLiteral("y")),
              z = info.columnIndex(QStringLiteral("z"));
    const int vn = info.columnIndex(QStringLiteral("vn")), ve = info.columnIndex(QStringLiteral("ve")),
              vd = info.columnIndex(QStringLiteral("vd"));
    const int vx = info.columnIndex(QStringLiteral("vx")), vy = info.columnIndex(QStringLiteral("vy")),
              vz = info.columnIndex(QStringLiteral("vz"));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto value = [&](std::size_t r, int c) { return c >= 0 ? data.at(r, c) : 0.0; };
    if (lat >= 0 && lon >= 0) {
        std::size_t first = 0;
        while (first < data.rows() && !(std::isfinite(data.at(first, lat)) && std::isfinite(data.at(first, lon))))
            ++first;
        if (first == data.rows()) return makeError(QStringLiteral("GNSS stream '%1' has no valid fix").arg(path));
        const LocalTangentPlane ltp(data.at(first, lat), data.at(first, lon), value(first, alt));
        origin = {{"lat", data.at(first, lat)}, {"lon", data.at(first, lon)}, {"alt", value(first, alt)}};
        for (std::size_t r = 0; r < data.rows(); ++r) {
            const bool ok = std::isfinite(data.at(r, lat)) && std::isfinite(data.at(r, lon));
            s.position.push_back(ok ? ltp.toEnu(data.at(r, lat), data.at(r, lon), value(r, alt)) : Vec3::Constant(nan));
        }
        if (useVelocity && vn >= 0 && ve >= 0)
            for (std::size_t r = 0; r < data.rows(); ++r) {
                // NMEA has no vertical speed (vd NaN): a runner's is ~0, so 0 keeps the horizontal update usable.
                const double down = vd >= 0 && std::isfinite(value(r, vd)) ? value(r, vd) : 0.0;
                s.velocity.push_back(LocalTangentPlane::nedToEnu(value(r, vn), value(r, ve), down));
            }
    } else if (x >= 0 && y >= 0) {
        for (std::size_t r = 0; r < data.rows(); ++r)
            s.position.push_back(Vec3(data.at(r, x), data.at(r, y), value(r, z)));
        if (useVelocity && vx >= 0 && vy >= 0)
            for (std::size_t r = 0; r < data.rows(); ++r)
                s.velocity.push_back(Vec3(value(r, vx), value(r, vy), value(r, vz)));
    } else {
        return makeError(QStringLiteral("GNSS stream '%1' needs lat, lon[, alt] or x, y[, z] columns (it has: %2)")
                             .arg(path, info.columnNames().join(QStringLiteral(", "))));
    }
    return s;
}

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    auto imu = c.samples(0);
    if (!imu) return imu.error();
    auto gnss = c.samples(1);
    if (!gnss) return gnss.error();
    plan.imu = *imu;
    plan.gnss = *gnss;
    auto columns = imuColumns(plan.imu, false);
    if (!columns) return columns.error();
    plan.columns = *columns;
    auto ts = plan.imu.samplingInterval();
    if (!ts) return ts.error();
    plan.ts = *ts;
    const auto num = [&](const char* name, double def) {
        const QString n = QLatin1String(name);
        return c.has(n) ? c.number(n) : def;
    };
    GnssImuEkf::Params& p = plan.params;
    const QString attitude =
        c.has(QStringLiteral("attitude")) ? c.text(QStringLiteral("attitude")) : QStringLiteral("ekf");
    if (attitude == QLatin1String("kalman"))
        p.attitude = AttitudeSource::Kalman;
    else if (attitude == QLatin1String("ekf"))
        p.attitude = AttitudeSource::Ekf;
    else if (attitude != QLatin1String("orientation"))
        return makeError(QStringLiteral("attitude: unknown '%1' (use orientation, kalman or ekf)").arg(attitude));
    p.accNoise = num("acc_noise", p.accNoise);
    p.gnssSigmaHorizontal = num("gnss_sigma", p.gnssSigmaHorizontal);
    p.gnssSigmaVertical = num("gnss_vertical_sigma", p.gnssSigmaVertical);
    p.gnssVelocitySigma = num("gnss_velocity_sigma", p.gnssVelocitySigma);
    p.gravity = num("gravity", p.gravity);
    const bool useVelocity = !c.has(QStringLiteral("use_velocity")) || c.flag(QStringLiteral("use_velocity"));
    auto series = gnssSeries(plan.gnss.stream->info(), *plan.gnss.data, c.inputPath(1), useVelocity, plan.origin);
    if (!series) return series.error();
    plan.series = std::move(*series);
    if (plan.series.t.empty() || plan.series.t.back() < plan.imu.data->t.front() ||
        plan.series.t.front() > plan.imu.data->t.back())
        return makeError(
            QStringLiteral("GNSS stream '%1' does not overlap the IMU stream '%2' in time (same clock expected)")
                .arg(c.inputPath(1), c.inputPath(0)));
    return plan;
}
}  // namespace

QString GnssImuProcessor::name() const { return tr("GNSS/IMU fusion"); }

QString GnssImuProcessor::description() const {
    return tr(
        "Loosely-coupled GNSS/IMU extended Kalman filter (Kim et al., Sensors 2023): position, velocity and "
        "attitude in a local ENU frame from the first fix, driven by the IMU at its rate and corrected by GNSS "
        "position (and velocity) at theirs; output at the IMU rate with horizontal speed and distance.");
}

ParameterSpecs GnssImuProcessor::parameters() const {
    return {
        ParameterSpec::choice(
            QStringLiteral("attitude"),
            {QStringLiteral("orientation"), QStringLiteral("kalman"), QStringLiteral("ekf")}, QStringLiteral("ekf"),
            tr("Inclination source: ekf (the EKF's own quaternion, corrected through the GNSS velocity; "
               "best on sprints), orientation (the VQF-class filter) or kalman (the seed's quaternion "
               "Kalman filter). Heading always comes from the EKF.")),
        ParameterSpec::number(QStringLiteral("acc_noise"), 0.3, 1e-6, kInf, QStringLiteral("m/s^2"),
                              tr("Process noise of the specific force (includes attitude errors).")),
        ParameterSpec::number(QStringLiteral("gnss_sigma"), 1.8, 1e-6, kInf, QStringLiteral("m"),
                              tr("GNSS horizontal position noise per axis.")),
        ParameterSpec::number(QStringLiteral("gnss_vertical_sigma"), 4.0, 1e-6, kInf, QStringLiteral("m"),
                              tr("GNSS vertical position noise.")),
        ParameterSpec::number(QStringLiteral("gnss_velocity_sigma"), 0.1, 1e-6, kInf, QStringLiteral("m/s"),
                              tr("GNSS velocity noise per axis.")),
        ParameterSpec::boolean(QStringLiteral("use_velocity"), true, tr("Use GNSS velocity columns when present.")),
        ParameterSpec::number(QStringLiteral("gravity"), 9.81, 9.7, 9.9, QStringLiteral("m/s^2"), tr("Local gravity.")),
    };
}

QList<InputSpec> GnssImuProcessor::inputs() const {
    return {InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("IMU: acc_x..z (m/s^2), gyr_x..z (rad/s).")},
            InputSpec{QStringLiteral("gnss"),
                      {QStringLiteral("gnss")},
                      false,
                      false,
                      tr("GNSS: lat, lon, alt[, vn, ve, vd] or x, y, z[, vx, vy, vz] (ENU), same clock as the IMU.")}};
}

QList<OutputSpec> GnssImuProcessor::outputs() const {
    return {
        OutputSpec{QStringLiteral("trajectory"), false, QString(),
                   tr("x, y, z, vx, vy, vz (ENU from the first fix), qw..qz, speed (m/s, horizontal), distance (m).")}};
}

Status GnssImuProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> GnssImuProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    const StreamData& in = *plan->imu.data;
    const ImuBatch batch{in.values.data() + plan->columns.gyr, in.values.data() + plan->columns.acc, nullptr, in.rows(),
                         static_cast<std::size_t>(in.columns)};
    const FusedTrack track = fuseGnssImu(plan->params, plan->ts, in.t, batch, plan->series, [&](double f) {
        context.report(0.95 * f, QStringLiteral("fusing GNSS and IMU"));
        return !context.isCancelled();
    });
    if (track.cancelled || context.isCancelled()) return cancelledError();
    StreamData out(in.rows(), 12);
    out.t = in.t;
    for (std::size_t r = 0; r < in.rows(); ++r) {
        double* row = &out.values[r * 12];
        for (int i = 0; i < 3; ++i) {
            row[i] = track.position[r][i];
            row[3 + i] = track.velocity[r][i];
        }
        const Quat& q = track.orientation[r];
        row[6] = q.w();
        row[7] = q.x();
        row[8] = q.y();
        row[9] = q.z();
        row[10] = track.speed[r];
        row[11] = track.distance[r];
    }
    context.report(1.0);
    QJsonObject attributes{{"origin", plan->origin}, {"sampling_rate", 1.0 / plan->ts}};
    std::vector<ProcessorOutput> outputs;
    outputs.push_back(
        {QString(),
         outputStream(QStringLiteral("trajectory"), QStringLiteral("ENU"),
                      columnsOf({"x", "y", "z", "vx", "vy", "vz", "qw", "qx", "qy", "qz", "speed", "distance"},
                                {"m", "m", "m", "m/s", "m/s", "m/s", "1", "1", "1", "1", "m/s", "m"}),
                      std::move(out), attributes)});
    return outputs;
}

}  // namespace athlos::inertial
