#include "plugins/inertial/OrientationProcessor.h"

#include "core/math/Angles.h"
#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/ImuColumns.h"
#include "plugins/inertial/OrientationEstimation.h"

#include <limits>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "OrientationProcessor"};
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Plan {
    InputSamples input;
    ImuColumns columns;
    OrientationOptions options;
    double ts = 0.0;
};

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    auto input = c.samples(0);
    if (!input) return input.error();
    plan.input = *input;
    const QString mode = c.has(QStringLiteral("mode")) ? c.text(QStringLiteral("mode")) : QStringLiteral("auto");
    auto columns = imuColumns(plan.input, mode == QLatin1String("9d"));
    if (!columns) return columns.error();
    plan.columns = *columns;
    auto ts = plan.input.samplingInterval();
    if (!ts) return ts.error();
    plan.ts = *ts;
    auto algorithm = parseOrientationAlgorithm(c.has(QStringLiteral("algorithm")) ? c.text(QStringLiteral("algorithm"))
                                                                                  : QStringLiteral("vqf"));
    if (!algorithm) return algorithm.error();
    OrientationOptions& o = plan.options;
    o.algorithm = *algorithm;
    o.useMagnetometer = mode == QLatin1String("9d") || (mode == QLatin1String("auto") && plan.columns.mag >= 0);
    const auto num = [&](const char* name, double def) {
        const QString n = QLatin1String(name);
        return c.has(n) ? c.number(n) : def;
    };
    o.filter.tauAcc = num("tau_acc", o.filter.tauAcc);
    o.filter.tauMag = num("tau_mag", o.filter.tauMag);
    const bool bias = !c.has(QStringLiteral("bias_estimation")) || c.flag(QStringLiteral("bias_estimation"));
    o.filter.restBiasEstimation = o.filter.motionBiasEstimation = bias;
    o.filter.magDisturbanceRejection =
        !c.has(QStringLiteral("mag_rejection")) || c.flag(QStringLiteral("mag_rejection"));
    o.filter.rest.thGyr = num("rest_th_gyr", o.filter.rest.thGyr);
    o.filter.rest.thAcc = num("rest_th_acc", o.filter.rest.thAcc);
    o.filter.accRange = num("acc_range", 0.0);
    o.offline = c.has(QStringLiteral("offline")) && c.flag(QStringLiteral("offline"));
    if (o.offline && o.algorithm != OrientationAlgorithm::Vqf)
        return makeError(QStringLiteral("offline: only the vqf algorithm has an offline mode (algorithm is '%1')")
                             .arg(orientationAlgorithmName(o.algorithm)));
    o.madgwick.beta = num("beta", o.madgwick.beta);
    o.mahony.kp = num("kp", o.mahony.kp);
    o.mahony.ki = num("ki", o.mahony.ki);
    if (2.0 * plan.ts >= o.filter.tauAcc)
        return makeError(QStringLiteral("tau_acc: %1 s is too short for the sampling interval of '%2' (%3 s); use at "
                                        "least %4 s")
                             .arg(o.filter.tauAcc)
                             .arg(c.inputPath(0))
                             .arg(plan.ts)
                             .arg(2.0 * plan.ts));
    return plan;
}
}  // namespace

QString OrientationProcessor::name() const { return tr("Orientation (IMU)"); }

QString OrientationProcessor::description() const {
    return tr(
        "Sensor-to-earth orientation (ENU, scalar-first quaternions) from gyroscope + accelerometer (6D) or "
        "+ magnetometer (9D), one row per input sample, with gyroscope bias estimate and rest / magnetic "
        "disturbance flags. Default: a VQF-class filter (Laidig & Seel 2023) with bias estimation at rest and "
        "in motion, accelerometer correction in an almost inertial frame and heading-only magnetometer "
        "correction with disturbance rejection. Baselines: strapdown, madgwick, mahony, kalman (Kim et al. 2023).");
}

ParameterSpecs OrientationProcessor::parameters() const {
    return {
        ParameterSpec::choice(
            QStringLiteral("mode"), {QStringLiteral("auto"), QStringLiteral("6d"), QStringLiteral("9d")},
            QStringLiteral("auto"),
            tr("6d: gyroscope + accelerometer (heading drifts freely); 9d: also magnetometer; auto: 9d "
               "when the stream has mag_x..z.")),
        ParameterSpec::choice(
            QStringLiteral("algorithm"), orientationAlgorithmNames(), QStringLiteral("vqf"),
            tr("vqf (default, recommended), or a baseline for comparison: strapdown, madgwick, mahony, "
               "kalman.")),
        ParameterSpec::number(QStringLiteral("tau_acc"), 3.0, 0.0, kInf, QStringLiteral("s"),
                              tr("vqf: time constant of the accelerometer (inclination) correction.")),
        ParameterSpec::number(QStringLiteral("tau_mag"), 9.0, 0.0, kInf, QStringLiteral("s"),
                              tr("vqf: time constant of the magnetometer (heading) correction.")),
        ParameterSpec::boolean(QStringLiteral("bias_estimation"), true,
                               tr("vqf: estimate the gyroscope bias (at rest and in motion).")),
        ParameterSpec::boolean(QStringLiteral("mag_rejection"), true,
                               tr("vqf: detect and ride out magnetic disturbances.")),
        ParameterSpec::number(QStringLiteral("rest_th_gyr"), 2.0 * math::kDeg, 0.0, kInf, QStringLiteral("rad/s"),
                              tr("vqf: rest detection threshold on the gyroscope deviation.")),
        ParameterSpec::number(QStringLiteral("rest_th_acc"), 0.5, 0.0, kInf, QStringLiteral("m/s^2"),
                              tr("vqf: rest detection threshold on the accelerometer deviation.")),
        ParameterSpec::number(QStringLiteral("acc_range"), 0.0, 0.0, kInf, QStringLiteral("m/s^2"),
                              tr("vqf: accelerometer measuring range; samples clipped at it do not correct the "
                                 "inclination (0 = unknown).")),
        ParameterSpec::boolean(QStringLiteral("offline"), false,
                               tr("vqf: estimate from the whole recording (forward-backward bias smoothing, "
                                  "zero-phase inclination, heading of both passes; offline VQF, Laidig & Seel "
                                  "2023) instead of sample by sample. Same outputs.")),
        ParameterSpec::number(QStringLiteral("beta"), 0.1, 0.0, kInf, QStringLiteral("rad/s"), tr("madgwick: gain.")),
        ParameterSpec::number(QStringLiteral("kp"), 0.74, 0.0, kInf, QStringLiteral("rad/s"),
                              tr("mahony: proportional gain.")),
        ParameterSpec::number(QStringLiteral("ki"), 0.0012, 0.0, kInf, QStringLiteral("rad/s^2"),
                              tr("mahony: integral gain.")),
    };
}

QList<InputSpec> OrientationProcessor::inputs() const {
    return {InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("IMU stream: acc_x..z (m/s^2), gyr_x..z (rad/s)[, mag_x..z (uT)] in the sensor frame.")}};
}

QList<OutputSpec> OrientationProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("orientation"), false, QString(),
                       tr("qw, qx, qy, qz (sensor to ENU), bias_x..z (rad/s), rest and mag_disturbed flags (0/1).")}};
}

Status OrientationProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> OrientationProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    const StreamData& in = *plan->input.data;
    const auto stride = static_cast<std::size_t>(in.columns);
    const ImuBatch batch{in.values.data() + plan->columns.gyr, in.values.data() + plan->columns.acc,
                         plan->columns.mag >= 0 ? in.values.data() + plan->columns.mag : nullptr, in.rows(), stride};
    const auto run = estimateOrientation(plan->options, batch, plan->ts, [&](double f) {
        context.report(0.95 * f, QStringLiteral("estimating orientation"));
        return !context.isCancelled();
    });
    if (run.cancelled || context.isCancelled()) return cancelledError();
    const OrientationTrack& tr = run.track;
    StreamData out(in.rows(), 9);
    out.t = in.t;
    for (std::size_t r = 0; r < in.rows(); ++r) {
        const math::Quat q = math::canonical(tr.q[r]);
        double* row = &out.values[r * 9];
        row[0] = q.w();
        row[1] = q.x();
        row[2] = q.y();
        row[3] = q.z();
        row[4] = tr.bias[r].x();
        row[5] = tr.bias[r].y();
        row[6] = tr.bias[r].z();
        row[7] = tr.rest[r];
        row[8] = tr.magDisturbed[r];
    }
    context.report(1.0);
    QJsonObject attributes{{"algorithm", orientationAlgorithmName(plan->options.algorithm)},
                           {"offline", plan->options.offline},
                           {"mode", plan->options.useMagnetometer ? QStringLiteral("9d") : QStringLiteral("6d")},
                           {"sampling_rate", 1.0 / plan->ts}};
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), outputStream(QStringLiteral("orientation"), QStringLiteral("ENU"),
                                               columnsOf({"qw", "qx", "qy", "qz", "bias_x", "bias_y", "bias_z", "rest",
                                                          "mag_disturbed"},
                                                         {"1", "1", "1", "1", "rad/s", "rad/s", "rad/s", "1", "1"}),
                                               std::move(out), attributes)});
    return outputs;
}

}  // namespace athlos::inertial
