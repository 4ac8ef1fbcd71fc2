#include "plugins/events/GaitEventsProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/events/GaitEventDetector.h"
#include "plugins/events/MediolateralAxis.h"
#include "plugins/events/SwingSearch.h"
#include "plugins/events/VectorColumns.h"

#include <QJsonArray>
#include <cmath>

namespace athlos::events {

namespace {
constexpr Translator tr{"athlos::events", "GaitEventsProcessor"};

struct Plan {
    std::shared_ptr<const StreamData> data;
    int gyr = -1;
    QString axis;  // ml_axis: x, y, z or auto (resolved on the data in run())
    int sign = 0;  // 0: auto
    GaitEventDetector::Params params;
    QString foot, label;
};

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    const Stream* stream = c.stream(0);
    if (!stream) return makeError(QStringLiteral("input '%1' was not given").arg(c.inputRole(0)));
    const StreamInfo& info = stream->info();
    auto gyr = vectorColumns(c, 0, QStringLiteral("gyr_"), QStringLiteral("rad/s"), QStringLiteral("gait-events"));
    if (!gyr) return gyr.error();
    plan.gyr = *gyr;
    plan.axis = c.text(QStringLiteral("ml_axis"));
    plan.sign = swingSignOf(c.text(QStringLiteral("swing_sign")));
    auto& p = plan.params;
    auto swing = readSwingSearch(c);
    if (!swing) return swing.error();
    swing->applyTo(p);
    auto input = c.samples(0);
    if (!input) return input.error();
    plan.data = input->data;
    auto interval = input->samplingInterval();
    if (!interval) return interval.error();
    const double ts = *interval;
    if (4.0 * ts > p.icWindow)
        return makeError(QStringLiteral("ic_window: %1 s spans fewer than 4 samples of '%2' (interval %3 s)")
                             .arg(p.icWindow)
                             .arg(input->path)
                             .arg(ts));
    plan.foot = GaitEventsProcessor::footOf(info);
    plan.label = c.text(QStringLiteral("label"));
    if (plan.label.isEmpty())
        plan.label = plan.foot.isEmpty() ? QStringLiteral("stride") : QStringLiteral("stride ") + plan.foot;
    return plan;
}
}  // namespace

QString GaitEventsProcessor::footOf(const StreamInfo& info) {
    for (const QString& s : {info.name, info.attributes.value(QStringLiteral("sensor")).toString()}) {
        const QString l = s.toLower();
        if (l.contains(QLatin1String("left"))) return QStringLiteral("left");
        if (l.contains(QLatin1String("right"))) return QStringLiteral("right");
    }
    return {};
}

QString GaitEventsProcessor::name() const { return tr("Gait events (foot IMU)"); }

QString GaitEventsProcessor::description() const {
    return tr(
        "Initial contact, toe-off and mid-stance from the medio-lateral gyroscope of a foot-mounted IMU "
        "(negative peaks of the swing-positive signal after and before each mid-swing peak; minimum of the "
        "gyroscope norm in stance). Writes the strides (IC to next IC) as predicted annotations with a "
        "confidence, and a table of the events.");
}

ParameterSpecs GaitEventsProcessor::parameters() const {
    ParameterSpecs specs{mlAxisParameter(), swingSignParameter()};
    specs << swingSearchParameters(SwingSearch::of(GaitEventDetector::Params{}),
                                   tr("Longest stride; longer intervals between contacts are gaps."));
    specs << ParameterSpec::text(
        QStringLiteral("label"), QString(),
        tr("Annotation label of the strides; empty: \"stride left\" / \"stride right\" from the stream name."));
    return specs;
}

QList<InputSpec> GaitEventsProcessor::inputs() const {
    return {InputSpec{QStringLiteral("imu"),
                      {QStringLiteral("imu")},
                      false,
                      false,
                      tr("Foot-mounted IMU: gyr_x..z (rad/s) in the sensor frame.")}};
}

QList<OutputSpec> GaitEventsProcessor::outputs() const {
    return {
        OutputSpec{QStringLiteral("gait-events"), true, QString(), tr("Events: t (s), type (ic, tc, min_vel), foot.")},
        OutputSpec{QString(), false, QString(), tr("Strides (IC to next IC) as predicted annotations with confidence."),
                   true}};
}

Status GaitEventsProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> GaitEventsProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    const StreamData& d = *plan->data;
    const double* gyr = d.values.data() + plan->gyr;
    const auto stride = std::size_t(d.columns);
    const auto ml = mediolateralAxis(plan->axis, gyr, d.rows(), stride);
    if (!ml) return makeError(QStringLiteral("ml_axis: '%1' is not one of auto, x, y, z").arg(plan->axis));
    const int sign =
        plan->sign ? plan->sign : GaitEventDetector::swingSign(d.t.data(), gyr, d.rows(), stride, ml->axis);
    GaitEventDetector detector(plan->params, sign);
    const std::size_t chunk = 20000;
    for (std::size_t k = 0; k < d.rows(); ++k) {
        const Eigen::Map<const Eigen::Vector3d> g(gyr + k * stride);
        detector.update(d.t[k], ml->axis.dot(g), g.norm());
        if (k % chunk == chunk - 1) {
            if (context.isCancelled()) return cancelledError();
            context.report(0.95 * double(k) / double(d.rows()), QStringLiteral("detecting gait events"));
        }
    }
    detector.finish();
    // Nothing found is refused with the likely causes, not stored as an empty table (issue #13 item 8).
    if (detector.events().empty())
        return context.inputError(
            0, QStringLiteral("no gait event found in %1 s of data (ml_axis = %2 %3, swing_threshold "
                              "= %4 rad/s): is it a foot-mounted IMU during walking or running, "
                              "with the medio-lateral axis as ml_axis?")
                   .arg(d.rows() ? d.t.back() - d.t.front() : 0.0, 0, 'g', 4)
                   .arg(plan->axis, axisText(ml->axis))
                   .arg(plan->params.swingThreshold));

    Table table;
    table.kind = QStringLiteral("gait-events");
    table.attributes = QJsonObject{{QStringLiteral("swing_sign"), sign},
                                   {QStringLiteral("ml_axis"), QJsonArray{ml->axis.x(), ml->axis.y(), ml->axis.z()}},
                                   {QStringLiteral("foot"), plan->foot},
                                   {QStringLiteral("strides"), int(detector.strides().size())}};
    TableColumn t{QStringLiteral("t"), QStringLiteral("s"), false, {}, {}};
    TableColumn type{QStringLiteral("type"), QString(), true, {}, {}};
    TableColumn foot{QStringLiteral("foot"), QString(), true, {}, {}};
    for (const auto& e : detector.events()) {
        t.numbers.push_back(e.t);
        type.texts << QString::fromLatin1(gaitEventName(e.type));
        foot.texts << plan->foot;
    }
    table.columns = {std::move(t), std::move(type), std::move(foot)};

    Annotations annotations;
    for (const auto& s : detector.strides()) {
        Annotation a;
        a.label = plan->label;
        a.tStart = s.tStart;
        a.tEnd = s.tEnd;
        a.confidence = s.confidence;
        annotations.push_back(std::move(a));  // source and annotator are set by the runner
    }
    context.report(1.0);
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(table)});
    outputs.push_back({QString(), std::move(annotations)});
    return outputs;
}

}  // namespace athlos::events
