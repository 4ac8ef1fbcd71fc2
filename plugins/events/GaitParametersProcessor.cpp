#include "plugins/events/GaitParametersProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/events/GaitEventsProcessor.h"
#include "plugins/events/ImuGaps.h"
#include "plugins/events/MediolateralAxis.h"
#include "plugins/events/StaticGyroBias.h"
#include "plugins/events/StrideIntegrator.h"
#include "plugins/events/SwingSearch.h"
#include "plugins/events/VectorColumns.h"
#include "plugins/events/ZuptKalmanSmoother.h"

#include <QJsonArray>
#include <cmath>
#include <limits>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "GaitParametersProcessor"};
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Plan {
    std::shared_ptr<const StreamData> data;
    int acc = -1, gyr = -1;
    StrideSegmentationParams segmentation;
    StrideIntegrationParams integration;
    bool smoother = false;  // method = rts
    ZuptStrideParams zupt;
    double staticThreshold = 0.0, staticDuration = 0.0;
    double maxGap = 0.0;   // s: longest run of missing samples bridged (ImuGaps.h)
    QString foot, mlAxis;  // mlAxis: the parameter (x, y, z or auto), resolved on the data in run()
};

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    const Stream* stream = c.stream(0);
    if (!stream) return makeError(QStringLiteral("input '%1' was not given").arg(c.inputRole(0)));
    const StreamInfo& info = stream->info();
    const QString id = QStringLiteral("gait-parameters");
    auto acc = vectorColumns(c, 0, QStringLiteral("acc_"), QStringLiteral("m/s^2"), id);
    if (!acc) return acc.error();
    auto gyr = vectorColumns(c, 0, QStringLiteral("gyr_"), QStringLiteral("rad/s"), id);
    if (!gyr) return gyr.error();
    plan.acc = *acc;
    plan.gyr = *gyr;
    auto& p = plan.segmentation;
    plan.mlAxis = c.text(QStringLiteral("ml_axis"));
    p.swingSign = swingSignOf(c.text(QStringLiteral("swing_sign")));
    auto swing = readSwingSearch(c);
    if (!swing) return swing.error();
    swing->applyTo(p);
    p.restWindow = c.number(QStringLiteral("rest_window"));
    p.restThreshold = c.number(QStringLiteral("rest_threshold"));
    p.stanceSearch = c.number(QStringLiteral("stance_search"));
    plan.integration.levelWindow = c.number(QStringLiteral("level_window"));
    plan.smoother = c.text(QStringLiteral("method")) == QLatin1String("rts");
    plan.zupt.levelWindow = plan.integration.levelWindow;
    plan.zupt.stanceWindow = c.number(QStringLiteral("zupt_window"));
    plan.zupt.stanceThreshold = c.number(QStringLiteral("zupt_threshold"));
    plan.zupt.filter.accNoise = c.number(QStringLiteral("acc_noise"));
    plan.zupt.filter.accNoiseDynamic = c.number(QStringLiteral("acc_noise_dynamic"));
    plan.zupt.filter.gyrNoise = c.number(QStringLiteral("gyr_noise"));
    plan.zupt.filter.gyrNoiseDynamic = c.number(QStringLiteral("gyr_noise_dynamic"));
    plan.zupt.filter.zuptNoise = c.number(QStringLiteral("zupt_noise"));
    plan.staticThreshold = p.staticThreshold = c.number(QStringLiteral("static_threshold"));
    p.standDuration = c.number(QStringLiteral("stand_duration"));
    plan.staticDuration = c.number(QStringLiteral("static_duration"));
    plan.maxGap = c.number(QStringLiteral("max_gap"));
    auto input = c.samples(0);
    if (!input) return input.error();
    plan.data = input->data;
    auto interval = input->samplingInterval();
    if (!interval) return interval.error();
    if (2.0 * *interval > p.stanceSearch)
        return makeError(QStringLiteral("stance_search: %1 s spans fewer than 2 samples of '%2' (interval %3 s)")
                             .arg(p.stanceSearch)
                             .arg(input->path)
                             .arg(*interval));
    plan.foot = GaitEventsProcessor::footOf(info);
    return plan;
}

TableColumn numberColumn(const char* name, const char* unit) {
    return TableColumn{QString::fromLatin1(name), QString::fromLatin1(unit), false, {}, {}};
}

}  // namespace

QString GaitParametersProcessor::name() const { return tr("Gait parameters (foot IMU)"); }

QString GaitParametersProcessor::description() const {
    return tr(
        "Strides between consecutive mid-stance (minimum-velocity) instants of a foot-mounted IMU and "
        "zero-velocity-aided integration (method rts: a Kalman smoother over the whole recording with zero "
        "velocity on every stance sample; method instant: per stride, levelled from gravity at each mid-stance, "
        "inclination and velocity drift removed linearly): stride length (horizontal) and height, stride, "
        "stance and swing time, cadence, gait speed, toe clearance and turning angle; plus the foot "
        "trajectory.");
}

ParameterSpecs GaitParametersProcessor::parameters() const {
    const StrideSegmentationParams d;
    const StrideIntegrationParams di;
    const ZuptStrideParams dz;
    ParameterSpecs specs{
        ParameterSpec::choice(
            QStringLiteral("method"), {QStringLiteral("instant"), QStringLiteral("rts")}, QStringLiteral("rts"),
            tr("instant: per stride, zero velocity at the two mid-stance instants, drift removed linearly. rts: "
               "zero-velocity-aided error-state Kalman filter with Rauch-Tung-Striebel smoothing over the whole "
               "recording, zero velocity on every stance sample (Skog et al. 2010; gaitmap RtsKalman).")),
        mlAxisParameter(),
        swingSignParameter(),
    };
    specs << swingSearchParameters(SwingSearch::of(d), tr("Swings further apart have the foot standing between "
                                                          "them: the strides end and start next to the standing "
                                                          "phase."));
    specs << ParameterSpecs{
        ParameterSpec::number(QStringLiteral("rest_window"), d.restWindow, 0.0, kInf, QStringLiteral("s"),
                              tr("Moving average of the gyroscope norm whose minimum is the mid-stance "
                                 "(gaitmap NormZuptDetector: 0.15 s).")),
        ParameterSpec::number(
            QStringLiteral("rest_threshold"), d.restThreshold, 0.0, kInf, QStringLiteral("rad/s"),
            tr("Largest averaged gyroscope norm accepted as the mid-stance before the first swing or after "
               "the last one, where the data may start or end in motion. Between two swings the quietest "
               "instant is always the mid-stance (a running foot still rolls at 2–4 rad/s there). gaitmap's "
               "static threshold is 15 deg/s (0.26 rad/s), but the quietest 0.15 s of a stance reaches "
               "0.2–1.3 rad/s in gaitmap's own walk, so the default is 2 rad/s.")),
        ParameterSpec::number(QStringLiteral("static_threshold"), d.staticThreshold, 0.0, kInf, QStringLiteral("rad/s"),
                              tr("Standing: gyroscope norm averaged over rest_window below this (gaitmap "
                                 "NormZuptDetector: 15 deg/s); pauses end strides, and the mean rate while "
                                 "standing is the gyroscope bias, removed before integration.")),
        ParameterSpec::number(QStringLiteral("stand_duration"), d.standDuration, 0.0, kInf, QStringLiteral("s"),
                              tr("A pause between two swings (below static_threshold at least this long) ends "
                                 "the stride before where the foot comes to rest and starts the next where it "
                                 "leaves, so that no stride contains the pause. Shorter than a stride, longer "
                                 "than the foot-flat phase of slow walking.")),
        ParameterSpec::number(QStringLiteral("static_duration"), 1.0, 0.0, kInf, QStringLiteral("s"),
                              tr("Shortest standing phase used for the gyroscope bias; 0: no bias removal.")),
        ParameterSpec::number(QStringLiteral("max_gap"), 0.05, 0.0, kInf, QStringLiteral("s"),
                              tr("Longest run of missing samples (empty cells, NaN) bridged by linear interpolation "
                                 "(0.05 s: 5 % of a walking stride); a longer one is refused.")),
        ParameterSpec::number(QStringLiteral("stance_search"), d.stanceSearch, 0.0, kInf, QStringLiteral("s"),
                              tr("Next to a standing phase, the mid-stance is searched this long after the "
                                 "last swing and before the next one.")),
        ParameterSpec::number(QStringLiteral("level_window"), di.levelWindow, 0.0, kInf, QStringLiteral("s"),
                              tr("Accelerometer average at a mid-stance that gives the up direction.")),
        ParameterSpec::number(QStringLiteral("zupt_window"), dz.stanceWindow, 0.0, kInf, QStringLiteral("s"),
                              tr("rts: moving average of the gyroscope norm of the stance detector (gaitmap "
                                 "NormZuptDetector: 0.15 s). The samples within half of it around each "
                                 "mid-stance are stance while their average is at most zupt_threshold above "
                                 "the mid-stance's.")),
        ParameterSpec::number(QStringLiteral("zupt_threshold"), dz.stanceThreshold, 0.0, kInf, QStringLiteral("rad/s"),
                              tr("rts: a sample is stance (zero velocity) when the averaged gyroscope norm is at "
                                 "most this (gaitmap NormZuptDetector: 15 deg/s).")),
        ParameterSpec::number(QStringLiteral("acc_noise"), dz.filter.accNoise, 1e-6, kInf, QStringLiteral("m/s^2"),
                              tr("rts: accelerometer process noise per sample in quiet phases: sensor noise and "
                                 "vibration (OpenShoe: 0.01 m/s^2 for white noise alone); acc_noise_dynamic "
                                 "adds the errors that come with the motion.")),
        ParameterSpec::number(QStringLiteral("acc_noise_dynamic"), dz.filter.accNoiseDynamic, 0.0, kInf, QString(),
                              tr("rts: accelerometer process noise per m/s^2 of |acceleration norm - g|: scale, "
                                 "impact and shoe errors grow with the motion, so the smoother corrects the "
                                 "velocity at push-off and landing. 0: evenly over the swing (version 4).")),
        ParameterSpec::number(QStringLiteral("gyr_noise"), dz.filter.gyrNoise, 1e-6, kInf, QStringLiteral("rad/s"),
                              tr("rts: gyroscope process noise per sample.")),
        ParameterSpec::number(QStringLiteral("gyr_noise_dynamic"), dz.filter.gyrNoiseDynamic, 0.0, kInf, QString(),
                              tr("rts: gyroscope process noise per rad/s of rotation rate.")),
        ParameterSpec::number(QStringLiteral("zupt_noise"), dz.filter.zuptNoise, 1e-6, kInf, QStringLiteral("m/s"),
                              tr("rts: standard deviation of the zero-velocity pseudo-measurement (OpenShoe: "
                                 "0.01 m/s).")),
    };
    return specs;
}

QList<InputSpec> GaitParametersProcessor::inputs() const {
    return {InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("Foot-mounted IMU: acc_x..z (m/s^2), gyr_x..z (rad/s), in any sensor frame (ml_axis = auto "
                         "finds the medio-lateral axis; give it when the recording is too short to tell).")}};
}

QList<OutputSpec> GaitParametersProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("gait-parameters"), true, QString(),
                       tr("One row per stride: start, end, stride_length, stride_height, stride_time, "
                          "stance_time, swing_time, cadence, gait_speed, max_toe_clearance, turning_angle.")},
            OutputSpec{QStringLiteral("trajectory"), false, QStringLiteral("trajectory"),
                       tr("Foot (sensor) positions x, y, z (m): z up, heading 0 at the first mid-stance.")}};
}

Status GaitParametersProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> GaitParametersProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    const StreamData& d = *plan->data;
    // acc_x..z, gyr_x..z per sample, missing samples bridged (ImuGaps.h).
    constexpr std::size_t stride = 6;
    std::vector<double> imu(stride * d.rows());
    for (std::size_t k = 0; k < d.rows(); ++k)
        for (int i = 0; i < 3; ++i) {
            imu[stride * k + std::size_t(i)] = d.at(k, plan->acc + i);
            imu[stride * k + 3 + std::size_t(i)] = d.at(k, plan->gyr + i);
        }
    const auto gaps = fillShortGaps(imu, stride, d.t, plan->maxGap);
    if (!gaps) return context.inputError(0, gaps.message());
    const double* acc = imu.data();
    // The gyroscope without its bias (from the standing phases), three columns per sample.
    const StaticGyroBias bias =
        estimateStaticGyroBias(d.t.data(), imu.data() + 3, d.rows(), stride, plan->segmentation.restWindow,
                               plan->staticThreshold, plan->staticDuration);
    std::vector<double> unbiased(3 * d.rows());
    for (std::size_t k = 0; k < d.rows(); ++k)
        for (int i = 0; i < 3; ++i)
            unbiased[3 * k + std::size_t(i)] = imu[stride * k + 3 + std::size_t(i)] - bias.bias[i];
    const double* gyr = unbiased.data();
    const auto ml = mediolateralAxis(plan->mlAxis, gyr, d.rows(), 3);
    if (!ml) return makeError(QStringLiteral("ml_axis: '%1' is not one of auto, x, y, z").arg(plan->mlAxis));
    plan->segmentation.mlAxis = ml->axis;
    context.report(0.1, QStringLiteral("finding strides"));
    const StrideSegmentation segmentation = segmentStrides(plan->segmentation, d.t.data(), gyr, d.rows(), 3);
    // Nothing found is refused with the likely causes, not stored as an empty table.
    if (segmentation.strides.empty()) {
        const QString why = segmentation.swings == 0
                                ? QStringLiteral("no swing above swing_threshold = %1 rad/s about ml_axis = %2 %3")
                                      .arg(plan->segmentation.swingThreshold)
                                      .arg(plan->mlAxis, axisText(ml->axis))
                                : QStringLiteral(
                                      "%1 swing(s), but the mid-stance before the first or after the last is above "
                                      "rest_threshold = %2 rad/s or cut off by the start or end of the data")
                                      .arg(segmentation.swings)
                                      .arg(plan->segmentation.restThreshold);
        return context.inputError(0, QStringLiteral("no stride found in %1 s of data (%2): is it a foot-mounted "
                                                    "IMU during walking or running?")
                                         .arg(d.rows() ? d.t.back() - d.t.front() : 0.0, 0, 'g', 4)
                                         .arg(why));
    }
    if (context.isCancelled()) return cancelledError();
    context.report(0.4, QStringLiteral("integrating strides"));
    std::size_t stanceSamples = 0;
    const auto smootherProgress = [&](double f) {
        context.report(0.4 + 0.55 * f, QStringLiteral("smoothing the foot trajectory"));
        return !context.isCancelled();
    };
    const FootTrajectory trajectory =
        plan->smoother
            ? smoothStrides(plan->zupt, segmentation.strides, d.t.data(), acc, stride, gyr, 3, d.rows(), &stanceSamples,
                            smootherProgress)
            : integrateStrides(plan->integration, segmentation.strides, d.t.data(), acc, stride, gyr, 3, d.rows());
    if (context.isCancelled()) return cancelledError();

    Table table;
    table.kind = QStringLiteral("gait-parameters");
    table.attributes =
        QJsonObject{{QStringLiteral("foot"), plan->foot},
                    {QStringLiteral("swing_sign"), segmentation.swingSign},
                    {QStringLiteral("ml_axis"), QJsonArray{ml->axis.x(), ml->axis.y(), ml->axis.z()}},
                    {QStringLiteral("gyr_bias"), QJsonArray{bias.bias.x(), bias.bias.y(), bias.bias.z()}},
                    {QStringLiteral("gyr_bias_static_time"), bias.staticTime},
                    {QStringLiteral("missing_samples_filled"), double(gaps->samples)},
                    {QStringLiteral("missing_runs_filled"), double(gaps->runs)},
                    {QStringLiteral("strides"), int(trajectory.strides.size())},
                    {QStringLiteral("stride_definition"), QStringLiteral("mid-stance to mid-stance")},
                    {QStringLiteral("method"), plan->smoother ? QStringLiteral("rts") : QStringLiteral("instant")},
                    {QStringLiteral("max_toe_clearance"),
                     QStringLiteral("sensor's max height above the higher of its two mid-stance "
                                    "heights")}};
    std::vector<TableColumn> c{numberColumn("start", "s"),          numberColumn("end", "s"),
                               numberColumn("stride_length", "m"),  numberColumn("stride_height", "m"),
                               numberColumn("stride_time", "s"),    numberColumn("stance_time", "s"),
                               numberColumn("swing_time", "s"),     numberColumn("cadence", "steps/min"),
                               numberColumn("gait_speed", "m/s"),   numberColumn("max_toe_clearance", "m"),
                               numberColumn("turning_angle", "rad")};
    for (std::size_t i = 0; i < trajectory.strides.size(); ++i) {
        const StrideEstimate& e = trajectory.strides[i];
        const StrideSegment& s = segmentation.strides[i];
        const double strideTime = e.tEnd - e.tStart;
        const double swing = d.t[s.ic] - d.t[s.tc];
        const double values[] = {e.tStart,
                                 e.tEnd,
                                 e.length,
                                 e.height,
                                 strideTime,
                                 strideTime - swing,
                                 swing,
                                 120.0 / strideTime,
                                 e.length / strideTime,
                                 e.maxClearance,
                                 e.turningAngle};
        for (std::size_t k = 0; k < c.size(); ++k) c[k].numbers.push_back(values[k]);
    }
    table.columns = std::move(c);
    if (plan->smoother) table.attributes.insert(QStringLiteral("zupt_samples"), double(stanceSamples));
    if (plan->mlAxis == QLatin1String("auto")) {
        table.attributes.insert(QStringLiteral("ml_axis_principal"),
                                QJsonArray{ml->principal.x(), ml->principal.y(), ml->principal.z()});
        table.attributes.insert(QStringLiteral("ml_axis_dominance"), ml->dominance);
    }

    StreamData positions(trajectory.position.size(), 3);
    for (std::size_t r = 0; r < trajectory.position.size(); ++r) {
        positions.t[r] = d.t[trajectory.first + r];
        for (int k = 0; k < 3; ++k) positions.at(r, k) = trajectory.position[r][k];
    }
    const QString frame = QStringLiteral("foot-world");
    QJsonObject attributes{
        {QStringLiteral("frame_definition"),
         QStringLiteral("z up; heading 0: the sensor's orientation at the first mid-stance turned level "
                        "about a horizontal axis (x forward for a sensor with x along the foot); origin at "
                        "the first mid-stance")},
        {QStringLiteral("foot"), plan->foot}};
    context.report(1.0);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(table)});
    outputs.push_back({QStringLiteral("trajectory"),
                       outputStream(QStringLiteral("trajectory"), frame, columnsOf({"x", "y", "z"}, {"m", "m", "m"}),
                                    std::move(positions), attributes)});
    return outputs;
}

}  // namespace athlos::events
