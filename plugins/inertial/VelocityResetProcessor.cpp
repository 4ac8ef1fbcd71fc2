#include "plugins/inertial/VelocityResetProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/ImuColumns.h"
#include "plugins/inertial/VelocityReset.h"

#include <cmath>
#include <limits>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "VelocityResetProcessor"};
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

ParameterSpec optionalNumber(const char* name, double min, double max, const char* unit, const QString& help) {
    ParameterSpec s = ParameterSpec::number(QLatin1String(name), kNaN, min, max, QLatin1String(unit), help);
    s.optional = true;
    return s;
}

Expected<VelocityReset::Params> makeParams(const RunContext& c) {
    const QString mode = c.has(QStringLiteral("mode")) ? c.text(QStringLiteral("mode")) : QStringLiteral("foot");
    VelocityReset::Params p =
        mode == QLatin1String("xc-ski") ? VelocityReset::crossCountrySki() : VelocityReset::foot();
    const auto num = [&](const char* name, double& value) {
        const QString n = QLatin1String(name);
        if (c.has(n) && !std::isnan(c.number(n))) value = c.number(n);
    };
    num("window", p.window);
    num("gyr_threshold", p.gyrThreshold);
    num("acc_threshold", p.accThreshold);
    num("acc_std_threshold", p.accStdThreshold);
    num("min_duration", p.minDuration);
    num("merge_gap", p.mergeGap);
    num("zero_speed", p.zeroSpeed);
    num("zero_acc", p.zeroAcc);
    num("anchor_share", p.anchorShare);
    num("gravity", p.gravity);
    if (c.has(QStringLiteral("inclination_reset"))) p.inclinationReset = c.flag(QStringLiteral("inclination_reset"));
    if (c.has(QStringLiteral("gyro_bridge"))) p.gyroBridge = c.flag(QStringLiteral("gyro_bridge"));
    if (c.has(QStringLiteral("refine"))) p.refine = c.flag(QStringLiteral("refine"));
    if (p.anchorShare <= 0.0 || p.anchorShare > 1.0)
        return makeError(
            QStringLiteral("velocity-reset: parameter 'anchor_share': %1 is not in (0, 1]").arg(p.anchorShare));
    return p;
}

}  // namespace

QString VelocityResetProcessor::name() const { return tr("Velocity resets (foot or ski sensor)"); }

QString VelocityResetProcessor::description() const {
    return tr(
        "Velocity and position of a foot- or ski-mounted sensor in the earth frame (Fasel 2017 ch. 2–4): "
        "zero-velocity phases found by gyroscope and accelerometer energy (the foot's stance; for cross-country "
        "skiing the thrust, where the ski stands still on the snow, refined by speed < 0.1 m/s and inertial "
        "acceleration < 1 m/s²), the inclination reset at each phase and spread by SLERP, gravity removed, the "
        "acceleration integrated, the velocity set to zero in each phase and the linear drift between phases "
        "removed. Inputs: orientation and IMU of the same sensor. Outputs: x, y, z, vx, vy, vz (NaN before the "
        "first and after the last phase) and the phases as a table (<output>-zero-velocity).");
}

ParameterSpecs VelocityResetProcessor::parameters() const {
    const VelocityReset::Params f = VelocityReset::foot();
    return {
        ParameterSpec::choice(QStringLiteral("mode"), {QStringLiteral("foot"), QStringLiteral("xc-ski")},
                              QStringLiteral("foot"),
                              tr("foot: stance (mean |ω| < 2 rad/s and acceleration spread < 1 m/s² over 0.1 s, as "
                                 "measured on gaitmap's real walk); xc-ski: the thrust phase of the diagonal stride "
                                 "(|ω| < 0.2 rad/s, |‖a‖ − g| < 1 m/s² over 0.04 s for ≥ 0.08 s, then refined by "
                                 "speed and acceleration, Fasel 2017 ch. 3 Table 3.1). The parameters below "
                                 "override the mode's values.")),
        optionalNumber("window", 0.0, kInf, "s", tr("Centred moving mean of the detector signals (mode).")),
        optionalNumber("gyr_threshold", 0.0, kInf, "rad/s", tr("Zero velocity: mean gyroscope norm below (mode).")),
        optionalNumber("acc_threshold", 0.0, kInf, "m/s^2",
                       tr("Zero velocity: mean |‖a‖ − 9.81 m/s²| below, 0 = not used (mode).")),
        optionalNumber("acc_std_threshold", 0.0, kInf, "m/s^2",
                       tr("Zero velocity: spread of the acceleration vector over the window below, 0 = not used "
                          "(mode; the accelerometer term of Skog et al. 2010's SHOE detector).")),
        optionalNumber("min_duration", 0.0, kInf, "s", tr("Shortest zero-velocity phase (mode).")),
        optionalNumber("merge_gap", 0.0, kInf, "s",
                       tr("Phases closer than this are merged (mode: 0.1 s foot, 0 xc-ski).")),
        ParameterSpec::number(QStringLiteral("anchor_share"), f.anchorShare, 0.01, 1.0, QStringLiteral("1"),
                              tr("Central share of each phase whose mean integrated velocity is the drift (Fasel "
                                 "2017 ch. 4: the central 50 %).")),
        ParameterSpec::boolean(QStringLiteral("inclination_reset"), f.inclinationReset,
                               tr("Reset the inclination at each phase from the accelerometer and spread it by "
                                  "SLERP (Fasel 2017 Eq. 2.7) before removing gravity.")),
        ParameterSpec::boolean(QStringLiteral("gyro_bridge"), f.gyroBridge,
                               tr("Between phases, carry the input orientation of the previous phase by the "
                                  "gyroscope and spread the mismatch at the next (Fasel 2017 ch. 3: integration "
                                  "of the angular velocity between thrusts); an online filter's inclination is "
                                  "pulled by the accelerations in between.")),
        optionalNumber("gravity", 0.0, kInf, "m/s^2",
                       tr("Gravity removed; empty = the mean accelerometer norm at the zero-velocity phases.")),
        ParameterSpec::boolean(QStringLiteral("refine"), false,
                               tr("Grow each phase while the corrected speed and the inertial acceleration stay "
                                  "below zero_speed and zero_acc (Fasel 2017 ch. 3); on in xc-ski mode.")),
        ParameterSpec::number(QStringLiteral("zero_speed"), f.zeroSpeed, 0.0, kInf, QStringLiteral("m/s"),
                              tr("Refinement: speed of a still ski (0.1 m/s, Fasel 2017 ch. 3–4).")),
        ParameterSpec::number(QStringLiteral("zero_acc"), f.zeroAcc, 0.0, kInf, QStringLiteral("m/s^2"),
                              tr("Refinement: inertial acceleration of a still ski (Fasel 2017 Table 3.1).")),
    };
}

QList<InputSpec> VelocityResetProcessor::inputs() const {
    return {InputSpec{QStringLiteral("orientation"),
                      {QStringLiteral("orientation")},
                      false,
                      false,
                      tr("Orientation (qw..qz, sensor → earth) of the foot or ski sensor, on the IMU's time axis.")},
            InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("IMU stream (acc_x..z in m/s², gyr_x..z in rad/s) of the same sensor.")}};
}

QList<OutputSpec> VelocityResetProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("trajectory"), false, QString(),
                       tr("Position x, y, z (m) and velocity vx, vy, vz (m/s) in the orientation's earth frame, "
                          "origin at the first zero-velocity phase; zero_velocity 1 inside a phase.")},
            OutputSpec{QStringLiteral("zero-velocity"), true, QStringLiteral("zero-velocity"),
                       tr("One row per zero-velocity phase: start, end, duration (s), drift_x..z (m/s, the "
                          "integrated velocity removed there), tilt (rad, the inclination reset).")}};
}

Status VelocityResetProcessor::prepare(const RunContext& context) const { return statusOf(makeParams(context)); }

Expected<std::vector<ProcessorOutput>> VelocityResetProcessor::run(const RunContext& context) const {
    auto params = makeParams(context);
    if (!params) return params.error();
    auto o = context.samples(0);
    if (!o) return o.error();
    auto imu = context.samples(1);
    if (!imu) return imu.error();
    auto q = orientationQuaternions(*o);
    if (!q) return q.error();
    auto columns = imuColumns(*imu, false);
    if (!columns) return columns.error();
    const StreamData& d = *imu->data;
    if (d.t != o->data->t)
        return context.inputError(1, QStringLiteral("its time axis differs from '%1'; run orientation on this IMU "
                                                    "stream to get one with the same samples")
                                         .arg(context.inputPath(0)));
    auto interval = imu->samplingInterval();
    if (!interval) return interval.error();
    std::vector<math::Vec3> acc(d.rows()), gyr(d.rows());
    for (std::size_t k = 0; k < d.rows(); ++k) {
        for (int a = 0; a < 3; ++a) {
            acc[k][a] = d.at(k, columns->acc + a);
            gyr[k][a] = d.at(k, columns->gyr + a);
        }
        if (!acc[k].allFinite() || !gyr[k].allFinite())
            return context.inputError(1, QStringLiteral("row %1 is not finite").arg(k));
    }
    const VelocityReset reset(*params);
    const VelocityReset::Result r = reset.run(*q, acc, gyr, *interval, [&](double f) {
        context.report(0.9 * f, QStringLiteral("resetting velocity"));
        return !context.isCancelled();
    });
    if (context.isCancelled()) return cancelledError();
    // Fewer than two phases anchor nothing: refused, not stored as a stream of NaN.
    if (r.phases.size() < 2)
        return context.inputError(
            1,
            QStringLiteral(
                "%1 zero-velocity phase(s) found in %2 s (at least 2 needed): is it a %3 sensor? "
                "(gyr_threshold = %4 rad/s, acc_threshold or acc_std_threshold = %5 m/s^2, min_duration = %6 s)")
                .arg(r.phases.size())
                .arg(d.rows() ? d.t.back() - d.t.front() : 0.0, 0, 'g', 4)
                .arg(params->mode == VelocityReset::Params::Mode::Foot ? QStringLiteral("foot") : QStringLiteral("ski"))
                .arg(params->gyrThreshold)
                .arg(params->accThreshold > 0.0 ? params->accThreshold : params->accStdThreshold)
                .arg(params->minDuration));

    StreamData out = samplesOnTimeAxis(d, 7);
    for (std::size_t k = 0; k < d.rows(); ++k) {
        for (int a = 0; a < 3; ++a) {
            out.at(k, a) = r.position[k][a];
            out.at(k, 3 + a) = r.velocity[k][a];
        }
        out.at(k, 6) = r.zeroVelocity[k];
    }
    const QJsonObject attributes{
        {QStringLiteral("velocity_reset"),
         params->mode == VelocityReset::Params::Mode::Foot ? QStringLiteral("foot") : QStringLiteral("xc-ski")},
        {QStringLiteral("frame_definition"),
         QStringLiteral("the orientation's earth frame (z up), origin at the centre of the first zero-velocity phase; "
                        "NaN before it and after the centre of the last")},
        {QStringLiteral("gravity"), r.gravity},
        {QStringLiteral("zero_velocity_phases"), int(r.phases.size())}};
    Table table;
    table.kind = QStringLiteral("zero-velocity");
    std::vector<TableColumn> c;
    for (const auto& [name, unit] : std::initializer_list<std::pair<const char*, const char*>>{{"start", "s"},
                                                                                               {"end", "s"},
                                                                                               {"duration", "s"},
                                                                                               {"drift_x", "m/s"},
                                                                                               {"drift_y", "m/s"},
                                                                                               {"drift_z", "m/s"},
                                                                                               {"tilt", "rad"}})
        c.push_back(TableColumn{QString::fromLatin1(name), QString::fromLatin1(unit), false, {}, {}});
    for (const VelocityReset::Phase& p : r.phases) {
        const double start = d.t[p.begin], end = d.t[p.end - 1];
        const double values[] = {start, end, end - start, p.drift.x(), p.drift.y(), p.drift.z(), p.tilt};
        for (std::size_t i = 0; i < c.size(); ++i) c[i].numbers.push_back(values[i]);
    }
    table.columns = std::move(c);
    table.attributes = QJsonObject{{QStringLiteral("gravity"), r.gravity}};
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), outputStream(QStringLiteral("trajectory"), o->info().frame,
                                               columnsOf({"x", "y", "z", "vx", "vy", "vz", "zero_velocity"},
                                                         {"m", "m", "m", "m/s", "m/s", "m/s", "1"}),
                                               std::move(out), attributes)});
    outputs.push_back({QStringLiteral("zero-velocity"), std::move(table)});
    context.report(1.0);
    return outputs;
}

}  // namespace athlos::inertial
