#include "plugins/inertial/DriftReductionProcessor.h"

#include "core/processing/OutputStreams.h"
#include "core/processing/Translator.h"
#include "plugins/inertial/DriftReduction.h"
#include "plugins/inertial/ImuColumns.h"

#include <cmath>
#include <limits>

namespace athlos::inertial {

namespace {
constexpr Translator tr{"athlos::inertial", "DriftReductionProcessor"};
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Plan {
    QStringList segments;  // one per input pair
    DriftReduction::Params params;
    QString staticCorrection;  // auto, true, false (auto is decided in run(), from the inputs)
    std::vector<DriftReduction::Link> links;
};

ParameterSpec optionalNumber(const char* name, double min, double max, const char* unit, const QString& help) {
    ParameterSpec s = ParameterSpec::number(QLatin1String(name), kNaN, min, max, QLatin1String(unit), help);
    s.optional = true;
    return s;
}

Expected<Plan> makePlan(const RunContext& c) {
    Plan plan;
    // Inputs given (the optional ones at the end are absent).
    int given = 0;
    while (given < c.inputCount() && !c.inputPath(given).isEmpty()) ++given;
    const int pairs = given / 2;
    if (given % 2 != 0)
        return makeError(QStringLiteral("drift-reduction takes pairs of inputs (orientation, imu) per segment; got %1 "
                                        "input(s)")
                             .arg(given));
    const QString list = c.has(QStringLiteral("segments")) ? c.text(QStringLiteral("segments"))
                                                           : driftReductionSegments().join(QLatin1Char(','));
    QStringList names;
    for (const QString& s : list.split(QLatin1Char(','), Qt::SkipEmptyParts)) names << s.trimmed();
    for (const QString& s : names)
        if (!driftReductionSegments().contains(s))
            return makeError(QStringLiteral("segments: '%1' is not one of %2")
                                 .arg(s, driftReductionSegments().join(QStringLiteral(", "))));
    if (names.size() < pairs)
        return makeError(QStringLiteral("segments: %1 name(s) for %2 input pairs").arg(names.size()).arg(pairs));
    plan.segments = names.mid(0, pairs);
    if (plan.segments.removeDuplicates() > 0) return makeError(QStringLiteral("segments: a name is repeated"));
    if (!plan.segments.isEmpty() && plan.segments.front() != QLatin1String("sacrum"))
        return makeError(QStringLiteral("segments: the first input pair must be the sacrum (the root of the chain), "
                                        "not '%1'")
                             .arg(plan.segments.front()));
    for (int i = 1; i < plan.segments.size(); ++i) {
        const QString parent = driftReductionParent(plan.segments[i]);
        const int p = plan.segments.indexOf(parent);
        if (p < 0)
            return makeError(QStringLiteral("segments: '%1' is linked to '%2', which is not among the inputs")
                                 .arg(plan.segments[i], parent));
        plan.links.push_back({p, i});
    }
    DriftReduction::Params& p = plan.params;
    const QString preset =
        c.has(QStringLiteral("preset")) ? c.text(QStringLiteral("preset")) : QStringLiteral("on-snow");
    p = preset == QLatin1String("indoor") ? DriftReduction::indoor() : DriftReduction::onSnow();
    const auto num = [&](const char* name, double& value) {
        const QString n = QLatin1String(name);
        if (c.has(n) && !std::isnan(c.number(n))) value = c.number(n);
    };
    num("gyr_cutoff", p.gyrCutoff);
    num("omega_threshold", p.omegaThreshold);
    num("max_norm_difference", p.maxNormDifference);
    num("max_relative_difference", p.maxRelativeDifference);
    num("min_norm", p.minNorm);
    num("window", p.window);
    num("azimuth_min_norm", p.azimuthMinNorm);
    num("min_heading_coherence", p.minHeadingCoherence);
    num("estimation_rate", p.estimationRate);
    // Below this the ±1.25 s windows hold too few samples to estimate anything, and the run would
    // silently leave the orientations as they are (validated down to 50 Hz: ≤ 0.04°).
    constexpr double kMinEstimationRate = 20.0;
    if (p.estimationRate > 0.0 && p.estimationRate < kMinEstimationRate)
        return makeError(QStringLiteral("parameter 'estimation_rate': %1 Hz is too low; give 0 (every sample) or at "
                                        "least %2 Hz")
                             .arg(p.estimationRate)
                             .arg(kMinEstimationRate));
    num("rest_th_gyr", p.rest.thGyr);
    num("rest_th_acc", p.rest.thAcc);
    const auto flag = [&](const char* name, bool& value) {
        const QString n = QLatin1String(name);
        if (c.has(n)) value = c.flag(n);
    };
    if (c.has(QStringLiteral("estimator")))
        p.estimator = c.text(QStringLiteral("estimator")) == QLatin1String("markley")
                          ? DriftReduction::Params::Estimator::Markley
                          : DriftReduction::Params::Estimator::Wahba;
    plan.staticCorrection = c.has(QStringLiteral("static_correction")) ? c.text(QStringLiteral("static_correction"))
                                                                       : QStringLiteral("auto");
    p.staticCorrection = plan.staticCorrection != QLatin1String("false");
    flag("joint_correction", p.jointCorrection);
    flag("azimuth_pass", p.azimuthPass);
    flag("align_heading", p.alignHeading);
    return plan;
}

}  // namespace

QStringList driftReductionSegments() {
    return {QStringLiteral("sacrum"),      QStringLiteral("sternum"),    QStringLiteral("right-thigh"),
            QStringLiteral("right-shank"), QStringLiteral("right-foot"), QStringLiteral("left-thigh"),
            QStringLiteral("left-shank"),  QStringLiteral("left-foot")};
}

QString driftReductionParent(const QString& segment) {
    if (segment == QLatin1String("sternum") || segment.endsWith(QLatin1String("-thigh")))
        return QStringLiteral("sacrum");
    if (segment.endsWith(QLatin1String("-shank"))) return segment.left(segment.size() - 6) + QStringLiteral("-thigh");
    if (segment.endsWith(QLatin1String("-foot"))) return segment.left(segment.size() - 5) + QStringLiteral("-shank");
    return QString();
}

bool staticCorrectionSuits(const QString& orientationAlgorithm) {
    return orientationAlgorithm == QLatin1String("strapdown");
}

QString DriftReductionProcessor::name() const { return tr("Drift reduction (joints)"); }

QString DriftReductionProcessor::description() const {
    return tr(
        "Reduces the orientation drift of body-worn sensors after the recording (Fasel 2017 ch. 2, 5, 6): inclination "
        "at rest instants spread by SLERP between them, then joint drift reduction — two segments linked by a joint "
        "must see the same joint-centre acceleration; sensor-to-joint vectors by Nelder–Mead, the drift between the "
        "two virtual accelerations estimated over ±1.25 s windows, corrected from the sacrum to the thighs, "
        "shanks and feet and to the sternum, then a second pass on horizontal components for the azimuth. Inputs: "
        "(orientation, imu) per segment in the order of `segments`. Velocity resets for foot/ski sensors: "
        "velocity-reset, on any of the outputs.");
}

ParameterSpecs DriftReductionProcessor::parameters() const {
    const DriftReduction::Params d;
    return {
        ParameterSpec::text(QStringLiteral("segments"), driftReductionSegments().join(QLatin1Char(',')),
                            tr("Segment of each input pair, in order; the first must be sacrum. Links: sacrum → "
                               "sternum, sacrum → <side>-thigh → <side>-shank → <side>-foot.")),
        ParameterSpec::choice(QStringLiteral("preset"), {QStringLiteral("on-snow"), QStringLiteral("indoor")},
                              QStringLiteral("on-snow"),
                              tr("Valid-sample thresholds: on-snow (|ã| > 8 m/s², ||ã_d| − |ã_p|| < 2.5 m/s², "
                                 "Fasel 2017 Eqs. 5.6–5.8) or indoor (|ã| > 6 m/s², relative difference < 0.2, "
                                 "Eqs. 6.9–6.11). The parameters below override the preset.")),
        optionalNumber("min_norm", 0.0, kInf, "m/s^2", tr("Minimum |ã_d|, |ã_p| (Eqs. 5.7–5.8; preset).")),
        optionalNumber("max_norm_difference", 0.0, kInf, "m/s^2", tr("Maximum ||ã_d| − |ã_p|| (Eq. 5.6; preset).")),
        optionalNumber("max_relative_difference", 0.0, kInf, "1",
                       tr("Maximum ||ã_d| − |ã_p|| / mean norm, 0 = not used (Eq. 6.11; preset).")),
        ParameterSpec::number(QStringLiteral("gyr_cutoff"), d.gyrCutoff, 0.1, kInf, QStringLiteral("Hz"),
                              tr("Cut-off of the zero-phase 2nd-order Butterworth low-pass of ω (Eqs. 5.3–5.4).")),
        ParameterSpec::number(QStringLiteral("omega_threshold"), d.omegaThreshold, 0.0, kInf, QStringLiteral("rad/s"),
                              tr("Samples with |ω_proximal| above this fit the sensor-to-joint vectors (Eq. 5.5, "
                                 "40°/s).")),
        ParameterSpec::number(QStringLiteral("window"), d.window, 0.01, kInf, QStringLiteral("s"),
                              tr("Half width of the Markley mean of the drift (1.25 s, Fasel 2017 ch. 5).")),
        optionalNumber("estimation_rate", 0.0, kInf, "Hz",
                       tr("The drift estimates of the correction passes use every k-th sample, k the largest whole "
                          "number with rate / k ≥ this; the correction applies to every sample. 0 = every sample, "
                          "else at least 20 Hz. "
                          "Preset: on-snow 100 Hz (skiing at 500 Hz: joint angles within 0.01° of every sample), "
                          "indoor 0 (walking has few valid samples).")),
        ParameterSpec::choice(
            QStringLiteral("estimator"), {QStringLiteral("wahba"), QStringLiteral("markley")}, QStringLiteral("wahba"),
            tr("Drift of a window: wahba — the rotation that best maps all its valid ã_d onto ã_p (least squares); "
               "markley — per-sample smallest rotation (Fasel 2017 Eqs. 5.9–5.11) averaged with the Markley "
               "quaternion mean, as in the thesis (biased here: docs/validation/drift-reduction.md).")),
        ParameterSpec::boolean(QStringLiteral("azimuth_pass"), d.azimuthPass,
                               tr("Second pass on horizontal components (Eqs. 6.12–6.13).")),
        ParameterSpec::number(QStringLiteral("azimuth_min_norm"), d.azimuthMinNorm, 0.0, kInf, QStringLiteral("m/s^2"),
                              tr("Minimum horizontal norm in the azimuth pass (0.6 m/s²).")),
        ParameterSpec::boolean(QStringLiteral("align_heading"), d.alignHeading,
                               tr("Remove a constant heading offset per joint first (needed for 6D orientations, "
                                  "whose headings are independent).")),
        ParameterSpec::number(
            QStringLiteral("min_heading_coherence"), d.minHeadingCoherence, 0.0, 1.0, QStringLiteral("1"),
            tr("The joint heading is fitted on samples whose horizontal ã exceed azimuth_min_norm (Eqs. 6.12–6.13); "
               "below this weighted mean resultant length of their heading differences (circular statistics, "
               "Mardia & Jupp 2000; 0.5 ≈ 68° circular SD), or with fewer samples than a window needs, the "
               "heading is unobservable and the joint is left uncorrected (attribute heading_aligned=false: align "
               "it with joint-angles heading=align-start).")),
        ParameterSpec::choice(
            QStringLiteral("static_correction"),
            {QStringLiteral("auto"), QStringLiteral("true"), QStringLiteral("false")}, QStringLiteral("auto"),
            tr("Correct the inclination at rest instants, spread by SLERP between them (Fasel 2017 Eq. 2.7). Its "
               "model is an inclination error that grows between rests, as a gyroscope integration's: auto = only "
               "when every orientation input is a strap-down integration (attribute algorithm=strapdown). A filter "
               "that corrects its inclination with the accelerometer (vqf, madgwick, …) already uses the rests, and "
               "spreading its transient error at a rest back over the motion made the inclination worse "
               "(docs/validation/drift-reduction.md).")),
        ParameterSpec::boolean(QStringLiteral("joint_correction"), d.jointCorrection,
                               tr("Joint drift reduction (Fasel 2017 ch. 5–6).")),
        ParameterSpec::number(QStringLiteral("rest_th_gyr"), d.rest.thGyr, 0.0, kInf, QStringLiteral("rad/s"),
                              tr("Rest detection: gyroscope deviation threshold (as in orientation).")),
        ParameterSpec::number(QStringLiteral("rest_th_acc"), d.rest.thAcc, 0.0, kInf, QStringLiteral("m/s^2"),
                              tr("Rest detection: accelerometer deviation threshold.")),
    };
}

QList<InputSpec> DriftReductionProcessor::inputs() const {
    QList<InputSpec> in;
    const QStringList names = driftReductionSegments();
    for (int i = 0; i < names.size(); ++i) {
        in << InputSpec{names[i] + QStringLiteral("-orientation"),
                        {QStringLiteral("orientation")},
                        false,
                        i >= 2,
                        tr("Orientation (qw..qz) of the segment named at this place of `segments`.")}
           << InputSpec{names[i] + QStringLiteral("-imu"),
                        {QStringLiteral("imu")},
                        false,
                        i >= 2,
                        tr("IMU stream (acc_x..z, gyr_x..z) of the same sensor.")};
    }
    return in;
}

QList<OutputSpec> DriftReductionProcessor::outputs() const {
    QList<OutputSpec> out{OutputSpec{QStringLiteral("orientation"), false, QString(),
                                     tr("Corrected sacrum orientation, same columns as its input.")}};
    const QStringList names = driftReductionSegments();
    for (int i = 1; i < names.size(); ++i)
        out << OutputSpec{QStringLiteral("orientation"), false, names[i], tr("Corrected orientation of this segment.")};
    return out;
}

Status DriftReductionProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> DriftReductionProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    const int pairs = static_cast<int>(plan->segments.size());
    std::vector<DriftReduction::Segment> segments(static_cast<std::size_t>(pairs));
    std::vector<InputSamples> orientations;
    double ts = 0.0;
    for (int i = 0; i < pairs; ++i) {
        auto o = context.samples(2 * i);
        if (!o) return o.error();
        auto imu = context.samples(2 * i + 1);
        if (!imu) return imu.error();
        auto q = orientationQuaternions(*o);
        if (!q) return q.error();
        auto columns = imuColumns(*imu, false);
        if (!columns) return columns.error();
        const StreamData& d = *imu->data;
        if (d.t != o->data->t)
            return context.inputError(2 * i + 1, QStringLiteral("its time axis differs from '%1'; run orientation on "
                                                                "this IMU stream to get one with the same samples")
                                                     .arg(context.inputPath(2 * i)));
        if (i > 0 && d.t != orientations.front().data->t)
            return context.inputError(2 * i + 1, QStringLiteral("its time axis differs from '%1' (the sensors must "
                                                                "be synchronised and sampled together)")
                                                     .arg(context.inputPath(1)));
        auto interval = imu->samplingInterval();
        if (!interval) return interval.error();
        ts = *interval;
        DriftReduction::Segment& s = segments[static_cast<std::size_t>(i)];
        s.q = std::move(*q);
        s.acc.resize(d.rows());
        s.gyr.resize(d.rows());
        for (std::size_t k = 0; k < d.rows(); ++k)
            for (int a = 0; a < 3; ++a) {
                s.acc[k][a] = d.at(k, columns->acc + a);
                s.gyr[k][a] = d.at(k, columns->gyr + a);
            }
        if (!s.acc.empty() && !(s.acc.front().allFinite() && s.gyr.front().allFinite()))
            return context.inputError(2 * i + 1, QStringLiteral("the first sample is not finite"));
        orientations.push_back(*o);
    }
    // static_correction=auto: only when every input is a gyroscope integration; the first one that is
    // not is named in the outputs' attributes.
    QString staticReason = QStringLiteral("static_correction=%1").arg(plan->staticCorrection);
    if (plan->staticCorrection == QLatin1String("auto")) {
        for (int i = 0; i < pairs && plan->params.staticCorrection; ++i) {
            const QString algorithm = orientations[static_cast<std::size_t>(i)]
                                          .info()
                                          .attributes.value(QStringLiteral("algorithm"))
                                          .toString();
            if (staticCorrectionSuits(algorithm)) continue;
            plan->params.staticCorrection = false;
            staticReason = QStringLiteral("auto: '%1' is %2, not a gyroscope integration")
                               .arg(context.inputPath(2 * i),
                                    algorithm.isEmpty() ? QStringLiteral("of unknown origin (no algorithm attribute)")
                                                        : QStringLiteral("from %1").arg(algorithm));
        }
        if (plan->params.staticCorrection)
            staticReason = QStringLiteral("auto: every input is a gyroscope integration");
    }
    const DriftReduction reduction(plan->params);
    const DriftReduction::Result result = reduction.run(segments, plan->links, ts, [&](double f) {
        context.report(0.95 * f, QStringLiteral("reducing drift"));
        return !context.isCancelled();
    });
    if (result.q.empty() || context.isCancelled()) return cancelledError();
    for (std::size_t l = 0; l < result.links.size(); ++l)
        if (plan->params.jointCorrection && result.links[l].optimisationSamples < 10)
            return makeError(
                QStringLiteral("drift-reduction: joint %1 → %2 has fewer than 10 samples with |ω_proximal| above "
                               "omega_threshold; it cannot fit the sensor-to-joint vectors (too little motion?)")
                    .arg(plan->segments[plan->links[l].proximal], plan->segments[plan->links[l].distal]));
    std::vector<ProcessorOutput> out;
    for (int i = 0; i < pairs; ++i) {
        const InputSamples& o = orientations[static_cast<std::size_t>(i)];
        StreamData d = *o.data;
        const int cw = o.info().columnIndex(QStringLiteral("qw")), cx = o.info().columnIndex(QStringLiteral("qx")),
                  cy = o.info().columnIndex(QStringLiteral("qy")), cz = o.info().columnIndex(QStringLiteral("qz"));
        const std::vector<math::Quat>& q = result.q[static_cast<std::size_t>(i)];
        for (std::size_t k = 0; k < d.rows(); ++k) {
            const math::Quat c = math::canonical(q[k]);
            d.at(k, cw) = c.w();
            d.at(k, cx) = c.x();
            d.at(k, cy) = c.y();
            d.at(k, cz) = c.z();
        }
        Stream s = derivedStream(*o.stream, std::move(d));
        QJsonObject attributes = s.info().attributes;
        attributes.insert(QStringLiteral("drift_reduction"), true);
        attributes.insert(QStringLiteral("segment"), plan->segments[i]);
        attributes.insert(QStringLiteral("static_correction"), plan->params.staticCorrection);
        attributes.insert(QStringLiteral("static_correction_reason"), staticReason);
        attributes.insert(QStringLiteral("rest_intervals"), result.restIntervals[static_cast<std::size_t>(i)]);
        for (std::size_t l = 0; l < plan->links.size(); ++l) {
            if (plan->links[l].distal != i) continue;
            const DriftReduction::LinkResult& lr = result.links[l];
            attributes.insert(QStringLiteral("proximal"), plan->segments[plan->links[l].proximal]);
            attributes.insert(QStringLiteral("sensor_to_joint"), QStringLiteral("%1,%2,%3")
                                                                     .arg(lr.distalToJoint.x())
                                                                     .arg(lr.distalToJoint.y())
                                                                     .arg(lr.distalToJoint.z()));
            attributes.insert(QStringLiteral("proximal_sensor_to_joint"), QStringLiteral("%1,%2,%3")
                                                                              .arg(lr.proximalToJoint.x())
                                                                              .arg(lr.proximalToJoint.y())
                                                                              .arg(lr.proximalToJoint.z()));
            attributes.insert(QStringLiteral("heading_offset"), lr.headingOffset);
            attributes.insert(QStringLiteral("valid_share"), lr.validShare);
            attributes.insert(QStringLiteral("azimuth_valid_share"), lr.azimuthValidShare);
            attributes.insert(QStringLiteral("mean_correction"), lr.meanCorrection);
            attributes.insert(QStringLiteral("joint_fit_residual"), lr.optimisationCost);
            attributes.insert(QStringLiteral("heading_aligned"),
                              lr.heading == DriftReduction::HeadingStatus::Aligned ||
                                  lr.heading == DriftReduction::HeadingStatus::NotAligned);
            attributes.insert(QStringLiteral("heading_samples"), lr.headingSamples);
            attributes.insert(QStringLiteral("heading_coherence"), lr.headingCoherence);
            const QString joint = plan->segments[plan->links[l].proximal] + QStringLiteral(" → ") + plan->segments[i];
            if (lr.heading == DriftReduction::HeadingStatus::TooFewSamples)
                attributes.insert(QStringLiteral("heading_unobservable"),
                                  QStringLiteral("joint %1: only %2 samples with horizontal joint accelerations above "
                                                 "azimuth_min_norm; the joint is left uncorrected")
                                      .arg(joint)
                                      .arg(lr.headingSamples));
            else if (lr.heading == DriftReduction::HeadingStatus::Incoherent)
                attributes.insert(QStringLiteral("heading_unobservable"),
                                  QStringLiteral("joint %1: the heading differences of its %2 samples disagree "
                                                 "(coherence %3 < min_heading_coherence); the joint is left "
                                                 "uncorrected")
                                      .arg(joint)
                                      .arg(lr.headingSamples)
                                      .arg(lr.headingCoherence, 0, 'f', 2));
        }
        s.info().attributes = attributes;
        out.push_back({i == 0 ? QString() : plan->segments[i], std::move(s)});
    }
    context.report(1.0);
    return out;
}

}  // namespace athlos::inertial
