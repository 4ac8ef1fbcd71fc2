#include "plugins/positioning/PositionFilterProcessor.h"

#include "core/processing/ProcessorRunner.h"
#include "core/math/Angles.h"
#include "core/processing/Translator.h"
#include "plugins/lps/BeaconTable.h"
#include "plugins/lps/RangeStream.h"
#include "plugins/positioning/NoiseProfile.h"
#include "plugins/positioning/RangeFilter.h"

#include <QJsonArray>
#include <QJsonObject>
#include <cmath>
#include <limits>
#include <numbers>

namespace athlos::positioning {

namespace {
constexpr Translator tr{"athlos::positioning", "PositionFilterProcessor"};
const double kInf = std::numeric_limits<double>::infinity();

ParameterSpec optionalNumber(const QString& name, double min, double max, const QString& unit, const QString& help) {
    ParameterSpec spec = ParameterSpec::number(name, 0.0, min, max, unit, help);
    spec.defaultValue = QVariant();
    spec.optional = true;
    return spec;
}

// Noise profiles are estimated on position fixes; raw ranges have another measurement model.
Status refuseProfileForRanges(const RunContext& context) {
    if (!context.text(QStringLiteral("noise")).startsWith(QLatin1String("profile:"))) return {};
    return makeError(
        QStringLiteral("parameter 'noise': noise profiles hold the noise of position fixes; raw "
                       "ranges take noise=auto or manual (r_range)"));
}

bool rawRanges(const RunContext& context) {
    const Stream* stream = context.stream(0);
    return stream && stream->info().kind == QLatin1String("lps-range");
}

// Ranges against the beacon table of input 1, in time order.
Expected<RangeMeasurements> loadRanges(const RunContext& context) {
    if (!context.table(1))
        return context.inputError(
            0, QStringLiteral("raw ranges need the beacon table: --input %1,<rec>/beacons").arg(context.inputPath(0)));
    auto table = context.requireTable(1);
    if (!table) return table.error();
    auto layout = lps::layoutFromTable(**table, context.inputPath(1), 3, QStringLiteral("range filtering"));
    if (!layout) return layout.error();
    auto input = context.samples(0);
    if (!input) return input.error();
    auto set = lps::rangesFromStream(*input->stream, *input->data, *layout, input->path);
    if (!set) return set.error();
    RangeMeasurements m;
    m.beacons.assign(layout->positions.begin(), layout->positions.end());
    for (const auto& r : set->readings) {
        m.t.push_back(r.t);
        m.y.push_back({r.range, r.beacon});
    }
    if (m.size() < 10)
        return input->error(QStringLiteral("%1 valid ranges; position-filter needs at least 10").arg(m.size()));
    if (!RangeFilter::initialPosition(m, 0.0))
        return input->error(
            QStringLiteral("fewer than 3 beacons report a range in the first 10 s, so the start of the "
                           "track cannot be found"));
    return m;
}

QJsonObject noiseAttributes(const NoiseSettings& n, ModelKind model) {
    return QJsonObject{{QStringLiteral("q_position"), n.ctra.qPosition},
                       {QStringLiteral("q_speed"), n.ctra.qSpeed},
                       {QStringLiteral("q_accel"), model == ModelKind::ConstantVelocity ? n.qAccelCv : n.ctra.qAccel},
                       {QStringLiteral("q_heading"), n.ctra.qHeading},
                       {QStringLiteral("q_turn_rate"), n.ctra.qTurnRate},
                       {QStringLiteral("r_x"), n.ctra.rX},
                       {QStringLiteral("r_y"), n.ctra.rY},
                       {QStringLiteral("r_heading"), n.rHeading},
                       {QStringLiteral("r_turn_rate"), n.rTurnRate},
                       {QStringLiteral("r_accel"), n.rAccel},
                       {QStringLiteral("gate"), std::isfinite(n.gate) ? n.gate : 0.0}};
}

QJsonObject estimateAttributes(const PositionFilter::Estimate& estimate) {
    QJsonObject estimated;
    for (const auto& [name, value] : estimate.values) estimated.insert(QString::fromStdString(name), value);
    estimated.insert(QStringLiteral("objective"), estimate.objective);
    estimated.insert(QStringLiteral("evaluations"), estimate.evaluations);
    return estimated;
}

// The trajectory on the output grid (plus σ_x, σ_y for raw measurements) and the per-input flags.
std::vector<ProcessorOutput> trajectoryOutputs(const RunContext& context, const PositionFilterResult& r,
                                               const std::vector<double>& inT, const std::vector<Eigen::Vector2d>* sd,
                                               QJsonObject attributes) {
    const bool grid = context.has(QStringLiteral("output_rate"));
    const double rate = grid ? context.number(QStringLiteral("output_rate")) : 0.0;
    const int columns = sd ? 9 : 7;
    // Main output: kinematics on the grid, plus the outlier flag of the input samples nearest to each
    // output sample (interval [t − Δ/2, t + Δ/2)).
    StreamData out(r.t.size(), columns);
    out.t = r.t;
    std::size_t next = 0;
    for (std::size_t k = 0; k < r.t.size(); ++k) {
        const Kinematics& s = r.states[k];
        const bool reverse = s.speed < 0;  // a negative speed state is the same motion heading + π
        out.at(k, 0) = s.x;
        out.at(k, 1) = s.y;
        out.at(k, 2) = std::abs(s.speed);
        out.at(k, 3) = reverse ? math::wrapAngle(s.heading + std::numbers::pi) : s.heading;
        out.at(k, 4) = s.turnRate;
        out.at(k, 5) = s.accel;
        double flag = 0.0;
        if (grid) {
            const double hi = r.t[k] + 0.5 / rate, lo = r.t[k] - 0.5 / rate;
            while (next < inT.size() && inT[next] < lo) ++next;
            for (std::size_t i = next; i < inT.size() && inT[i] < hi; ++i) flag = std::max(flag, double(r.outlier[i]));
        } else {
            flag = r.outlier[k];
        }
        out.at(k, 6) = flag;
        if (sd) {
            out.at(k, 7) = (*sd)[k].x();
            out.at(k, 8) = (*sd)[k].y();
        }
    }
    StreamInfo info;
    info.kind = QStringLiteral("trajectory");
    const QString frame = context.stream(0)->info().frame;
    info.frame = frame.isEmpty() ? QStringLiteral("lps") : frame;
    info.columns = {{QStringLiteral("x"), QStringLiteral("m")},
                    {QStringLiteral("y"), QStringLiteral("m")},
                    {QStringLiteral("speed"), QStringLiteral("m/s")},
                    {QStringLiteral("heading"), QStringLiteral("rad")},
                    {QStringLiteral("turn_rate"), QStringLiteral("rad/s")},
                    {QStringLiteral("accel"), QStringLiteral("m/s^2")},
                    {QStringLiteral("outlier"), QStringLiteral("1")}};
    if (sd) {
        info.columns.push_back({QStringLiteral("sd_x"), QStringLiteral("m")});
        info.columns.push_back({QStringLiteral("sd_y"), QStringLiteral("m")});
    }
    if (grid) attributes.insert(QStringLiteral("sampling_rate"), rate);
    int outliers = 0;
    for (char o : r.outlier) outliers += o;
    attributes.insert(QStringLiteral("outliers"), outliers);
    info.attributes = attributes;

    StreamData flags(inT.size(), 2);
    flags.t = inT;
    for (std::size_t i = 0; i < inT.size(); ++i) {
        flags.at(i, 0) = r.outlier[i];
        flags.at(i, 1) = r.mahalanobis2[i];
    }
    StreamInfo flagInfo;
    flagInfo.kind = QStringLiteral("outliers");
    flagInfo.frame = info.frame;
    flagInfo.columns = {{QStringLiteral("outlier"), QStringLiteral("1")},
                        {QStringLiteral("mahalanobis"), QStringLiteral("1")}};

    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), Stream(std::move(info), std::move(out))});
    outputs.push_back({QStringLiteral("outliers"), Stream(std::move(flagInfo), std::move(flags))});
    return outputs;
}

// Tightly coupled: every range updates the filter (RangeFilter.h).
Expected<std::vector<ProcessorOutput>> runRanges(const RunContext& context, const PositionFilter::Params& base) {
    if (auto refused = refuseProfileForRanges(context); !refused) return refused.error();
    auto rangesOr = loadRanges(context);
    if (!rangesOr) return rangesOr.error();
    const RangeMeasurements& in = *rangesOr;
    RangeFilter::Params params;
    params.model = base.model;
    params.track = base.track;
    params.noise = base.noise;
    params.rRange = context.number(QStringLiteral("r_range"));
    params.tagHeight = context.number(QStringLiteral("tag_height"));
    params.smoothing = base.smoothing;
    params.lag = base.lag;
    params.maxStep = base.maxStep;
    params.covariance = true;
    params.offsets = context.flag(QStringLiteral("range_offsets"));
    params.biasSigma = context.number(QStringLiteral("range_offset_sigma"));
    QJsonObject attributes;
    const bool autoNoise = context.text(QStringLiteral("noise")) == QLatin1String("auto");
    if (autoNoise) {
        const Progress sub = context.progress().sub(0.0, 0.8);
        const auto estimate = RangeFilter::estimateNoise(
            params,
            RangeFilter::noiseChunks(RangeFilter::thinned(in, context.number(QStringLiteral("noise_spacing"))),
                                     context.number(QStringLiteral("noise_chunk")),
                                     context.integer(QStringLiteral("noise_chunks"))),
            params.rRange, estimation::NoiseEstimator::Params{}, [&](double f) {
                sub.report(f, QStringLiteral("estimating noise"));
                return !context.isCancelled();
            });
        if (estimate.cancelled || context.isCancelled()) return cancelledError();
        params.noise = estimate.noise;
        attributes.insert(QStringLiteral("estimated_noise"), estimateAttributes(estimate));
    }
    QJsonObject noise = noiseAttributes(params.noise, params.model);
    noise.insert(QStringLiteral("r_range"), params.rRange);
    attributes.insert(QStringLiteral("noise"), noise);
    attributes.insert(QStringLiteral("measurements"), QStringLiteral("ranges"));
    attributes.insert(QStringLiteral("tag_height"), params.tagHeight);

    const bool grid = context.has(QStringLiteral("output_rate"));
    const std::vector<double> tOut =
        grid ? PositionFilter::outputGrid(in.t.front(), in.t.back(), context.number(QStringLiteral("output_rate")))
             : in.t;
    const Progress sub = context.progress().sub(autoNoise ? 0.8 : 0.0, 1.0);
    auto r = RangeFilter(params).run(in, tOut, [&](double f) {
        sub.report(f, QStringLiteral("filtering"));
        return !context.isCancelled();
    });
    if (!r) return context.inputError(0, r.message());
    if (r->filtered.cancelled || context.isCancelled()) return cancelledError();
    attributes.insert(QStringLiteral("start"), QJsonArray{r->start.x(), r->start.y()});
    if (!r->offsets.empty()) {
        QJsonArray offsets;
        for (double o : r->offsets) offsets.append(o);
        attributes.insert(QStringLiteral("range_offsets"), offsets);
    }
    return trajectoryOutputs(context, r->filtered, in.t, &r->sd, attributes);
}
}  // namespace

Expected<PositionSamples> PositionFilterProcessor::positionSamples(const RunContext& context, int index) {
    const Stream* stream = context.stream(index);
    if (!stream) return makeError(QStringLiteral("input '%1' was not given").arg(context.inputRole(index)));
    const int cx = stream->info().columnIndex(QStringLiteral("x")),
              cy = stream->info().columnIndex(QStringLiteral("y"));
    if (cx < 0 || cy < 0) return context.inputError(index, QStringLiteral("needs columns x and y"));
    auto input = context.samples(index);
    if (!input) return input.error();
    PositionSamples samples;
    const StreamData& d = *input->data;
    for (std::size_t k = 0; k < d.rows(); ++k) {
        const double x = d.at(k, cx), y = d.at(k, cy);
        if (!std::isfinite(x) || !std::isfinite(y)) continue;  // missing fixes are gaps, not zeros
        samples.t.push_back(d.t[k]);
        samples.p.emplace_back(x, y);
    }
    if (samples.t.size() < 10)
        return input->error(QStringLiteral("%1 valid samples; the filter needs at least 10").arg(samples.t.size()));
    return samples;
}

Expected<std::optional<NoiseProfile>> PositionFilterProcessor::noiseProfile(const RunContext& context,
                                                                            ModelKind model) {
    const QString noise = context.text(QStringLiteral("noise"));
    const QString prefix = QStringLiteral("profile:");
    if (!noise.startsWith(prefix)) return std::optional<NoiseProfile>();
    const QString path = noise.mid(prefix.size()).trimmed();
    const Table* table = context.project().table(path);
    if (!table)
        return makeError(QStringLiteral("parameter 'noise': no table '%1' in the project (estimate a profile with "
                                        "the noise-profile processor and give its output path)")
                             .arg(path));
    // The profile table is an input of the run, though not a declared one: in the provenance, so that
    // athlos batch re-runs the filter when the profile is estimated again.
    context.recordRead(path, tableHash(*table));
    auto profile = noiseProfileFromTable(*table, path);
    if (!profile) return makeError(QStringLiteral("parameter 'noise': %1").arg(profile.message()));
    if (profile->model != model)
        return makeError(QStringLiteral("parameter 'noise': profile '%1' was estimated for model=%2, this run uses "
                                        "model=%3 (Q differs between models: set model=%2 or estimate a profile "
                                        "for %3)")
                             .arg(path, modelKindName(profile->model), modelKindName(model)));
    return std::optional<NoiseProfile>(*profile);
}

QString PositionFilterProcessor::name() const { return tr("Position filter"); }

QString PositionFilterProcessor::description() const {
    return tr(
        "Robust Kalman filtering of LPS positions (EKF, UKF or square-root UKF): outlier gating by the "
        "Mahalanobis distance, output on any time grid from non-uniform input, RTS or fixed-lag smoothing, "
        "noise parameters estimated from the data, and track constraints either in an augmented motion model "
        "or as pseudo-measurements.");
}

ParameterSpecs PositionFilterProcessor::parameters() const {
    const CtraNoise n;
    const NoiseSettings ns;
    return {
        ParameterSpec::choice(QStringLiteral("filter"),
                              {QStringLiteral("ekf"), QStringLiteral("ukf"), QStringLiteral("srukf")},
                              QStringLiteral("ekf"), tr("Kalman filter variant.")),
        ParameterSpec::choice(
            QStringLiteral("model"),
            {QStringLiteral("auto"), QStringLiteral("unconstrained"), QStringLiteral("pseudo"),
             QStringLiteral("augmented"), QStringLiteral("constant-velocity")},
            QStringLiteral("auto"),
            tr("Motion model: CTRA (unconstrained), CTRA with track pseudo-measurements, CTRA with the "
               "track-augmented prediction, or constant velocity. auto: augmented for position fixes (on the "
               "track), constant velocity for raw ranges (no track assumed).")),
        ParameterSpec::text(QStringLiteral("track"), QStringLiteral("iaaf-400m"),
                            tr("Track geometry: a name under the project's /geometry or a built-in (iaaf-400m, "
                               "indoor-200m). Used by model=pseudo|augmented.")),
        optionalNumber(QStringLiteral("track_x"), -kInf, kInf, QStringLiteral("m"),
                       tr("Track origin x in LPS coordinates (overrides the geometry's pose).")),
        optionalNumber(QStringLiteral("track_y"), -kInf, kInf, QStringLiteral("m"),
                       tr("Track origin y in LPS coordinates.")),
        optionalNumber(QStringLiteral("track_rotation"), -10.0, 10.0, QStringLiteral("rad"),
                       tr("Rotation of the track frame in LPS coordinates (counter-clockwise).")),
        ParameterSpec::choice(
            QStringLiteral("noise"), {QStringLiteral("auto"), QStringLiteral("manual"), QStringLiteral("profile:")},
            QStringLiteral("auto"),
            tr("auto: estimate Q, R and the gate from the input itself (innovation likelihood, no ground truth); "
               "manual: use the q_*, r_* and gate parameters; profile:PATH: the values of a noise-profile table "
               "estimated on training recordings (thesis §4.4 deployment), e.g. profile:training/noise.")),
        ParameterSpec::integer(QStringLiteral("noise_chunks"), 8, 0, 1000,
                               tr("noise=auto estimates on this many evenly spread chunks of noise_chunk seconds (a "
                                  "representative subsample; 0 or a shorter recording: all of it).")),
        ParameterSpec::number(QStringLiteral("noise_spacing"), 3.0, 0.0, 60.0, QStringLiteral("s"),
                              tr("Raw ranges, noise=auto: each beacon's ranges at least this far apart for the "
                                 "estimate (range errors are correlated over fractions of a second; the likelihood "
                                 "assumes white noise).")),
        ParameterSpec::number(QStringLiteral("noise_chunk"), 60.0, 5.0, kInf, QStringLiteral("s"),
                              tr("Length of one chunk of the noise estimate.")),
        ParameterSpec::number(QStringLiteral("q_position"), n.qPosition, 0.0, kInf, QStringLiteral("m^2/s"),
                              tr("Process noise density of the position (manual).")),
        ParameterSpec::number(QStringLiteral("q_speed"), n.qSpeed, 0.0, kInf, QStringLiteral("m^2/s^3"),
                              tr("Process noise density of the speed (manual).")),
        ParameterSpec::number(QStringLiteral("q_accel"), n.qAccel, 0.0, kInf, QStringLiteral("m^2/s^5"),
                              tr("Process noise density of the acceleration; for constant-velocity the white-noise "
                                 "acceleration density (m^2/s^3) (manual).")),
        ParameterSpec::number(QStringLiteral("q_heading"), n.qHeading, 0.0, kInf, QStringLiteral("rad^2/s"),
                              tr("Process noise density of the heading (manual).")),
        ParameterSpec::number(QStringLiteral("q_turn_rate"), n.qTurnRate, 0.0, kInf, QStringLiteral("rad^2/s^3"),
                              tr("Process noise density of the turn rate (manual).")),
        ParameterSpec::number(QStringLiteral("r_x"), n.rX, 1e-12, kInf, QStringLiteral("m^2"),
                              tr("Measurement noise variance in x (manual).")),
        ParameterSpec::number(QStringLiteral("r_y"), n.rY, 1e-12, kInf, QStringLiteral("m^2"),
                              tr("Measurement noise variance in y (manual).")),
        ParameterSpec::number(QStringLiteral("r_heading"), ns.rHeading, 1e-12, kInf, QStringLiteral("rad^2"),
                              tr("Pseudo-measurement variance of heading − track heading (model=pseudo, manual).")),
        ParameterSpec::number(QStringLiteral("r_turn_rate"), ns.rTurnRate, 1e-12, kInf, QStringLiteral("rad^2/s^2"),
                              tr("Pseudo-measurement variance of turn rate − v·curvature (model=pseudo, manual).")),
        ParameterSpec::number(
            QStringLiteral("r_accel"), ns.rAccel, 1e-12, kInf, QStringLiteral("m^2/s^4"),
            tr("Pseudo-measurement variance of the acceleration after the start (model=pseudo, manual).")),
        ParameterSpec::number(QStringLiteral("r_range"), 0.01, 1e-12, kInf, QStringLiteral("m^2"),
                              tr("Range measurement noise variance (raw ranges, manual).")),
        ParameterSpec::number(QStringLiteral("tag_height"), 1.0, -1000.0, 1000.0, QStringLiteral("m"),
                              tr("Raw ranges: height of the tag in the beacons' frame; the filter solves x, y at "
                                 "this height.")),
        ParameterSpec::boolean(QStringLiteral("range_offsets"), true,
                               tr("Raw ranges: estimate a constant range offset per beacon (antenna delay, survey "
                                  "error) with the track, for up to 8 beacons.")),
        ParameterSpec::number(QStringLiteral("range_offset_sigma"), 0.1, 1e-4, 100.0, QStringLiteral("m"),
                              tr("Raw ranges: prior standard deviation of each range offset.")),
        ParameterSpec::number(QStringLiteral("gate"), ns.gate, 0.0, kInf, QString(),
                              tr("Outlier gate α on the squared Mahalanobis distance of the innovation (manual); "
                                 "0 disables gating.")),
        ParameterSpec::choice(QStringLiteral("smoother"),
                              {QStringLiteral("none"), QStringLiteral("rts"), QStringLiteral("fixed-lag")},
                              QStringLiteral("rts"),
                              tr("none: causal filter output (real-time behaviour); rts: Rauch–Tung–Striebel smoothing "
                                 "over the whole recording; fixed-lag: smoothing with `lag` seconds of look-ahead.")),
        ParameterSpec::number(QStringLiteral("lag"), 0.5, 0.0, kInf, QStringLiteral("s"),
                              tr("Look-ahead of the fixed-lag smoother.")),
        ParameterSpec::number(QStringLiteral("bridge_gap"), 2.0, 0.0, kInf, QStringLiteral("s"),
                              tr("model=augmented with smoother=rts: outages at least this long are bridged along "
                                 "the track between the smoothed states at their ends (arc length by a monotone "
                                 "cubic matching both speeds); 0 = off.")),
        optionalNumber(
            QStringLiteral("output_rate"), 0.0, 1e4, QStringLiteral("Hz"),
            tr("Output on a uniform grid at this rate (multiples of 1/rate); absent: at the input time stamps.")),
        ParameterSpec::number(QStringLiteral("max_step"), 0.1, 1e-3, 10.0, QStringLiteral("s"),
                              tr("Longest prediction step; outages are crossed in steps of at most this length.")),
        ParameterSpec::boolean(QStringLiteral("cv_switch"), true,
                               tr("Track models: switch from constant acceleration to constant velocity after the "
                                  "start phase.")),
        ParameterSpec::number(QStringLiteral("accel_phase"), 6.0, 0.0, kInf, QStringLiteral("s"),
                              tr("Duration of the constant-acceleration phase after the detected start.")),
    };
}

QList<InputSpec> PositionFilterProcessor::inputs() const {
    return {InputSpec{QStringLiteral("positions"),
                      {QStringLiteral("lps-position"), QStringLiteral("lps-range")},
                      false,
                      false,
                      tr("LPS fixes t, x, y (m), possibly non-uniform, with outliers and outages; or raw two-way "
                         "ranges (lps-range) filtered tightly coupled, with the beacon table.")},
            InputSpec{QStringLiteral("beacons"),
                      {QStringLiteral("beacons")},
                      true,
                      true,
                      tr("Beacon table id, x, y, z (m) for raw ranges.")}};
}

QList<OutputSpec> PositionFilterProcessor::outputs() const {
    return {OutputSpec{QStringLiteral("trajectory"), false, QString(),
                       tr("x, y (m), speed (m/s), heading (rad), turn_rate (rad/s), accel (m/s^2), outlier (1 if an "
                          "input sample in this output sample's interval was rejected); from raw ranges also "
                          "sd_x, sd_y (m), the filter's position standard deviations.")},
            OutputSpec{QStringLiteral("outliers"), false, QStringLiteral("outliers"),
                       tr("Per input sample: outlier (0/1) and mahalanobis (squared distance d^2).")}};
}

Expected<PositionFilter::Params> PositionFilterProcessor::readParams(const RunContext& c) const {
    PositionFilter::Params p;
    const QString filter = c.text(QStringLiteral("filter")), model = c.text(QStringLiteral("model"));
    p.filter = filter == QLatin1String("ukf")     ? FilterKind::Ukf
               : filter == QLatin1String("srukf") ? FilterKind::SrUkf
                                                  : FilterKind::Ekf;
    const bool ranges = c.stream(0) && c.stream(0)->info().kind == QLatin1String("lps-range");
    p.model = model == QLatin1String("unconstrained")       ? ModelKind::Unconstrained
              : model == QLatin1String("pseudo")            ? ModelKind::Pseudo
              : model == QLatin1String("constant-velocity") ? ModelKind::ConstantVelocity
              : model == QLatin1String("augmented")         ? ModelKind::Augmented
              : ranges                                      ? ModelKind::ConstantVelocity
                                                            : ModelKind::Augmented;
    if (ranges && p.model == ModelKind::Pseudo)
        return makeError(
            QStringLiteral("model=pseudo is not available for raw ranges (use auto, constant-velocity, "
                           "unconstrained or augmented)"));
    if (ranges && p.filter != FilterKind::Ekf)
        return makeError(
            QStringLiteral("filter=%1: raw ranges are filtered with the EKF only (filter=ekf)").arg(filter));
    if (!ranges && c.table(1))
        return makeError(QStringLiteral("a beacon table is only used with raw ranges (lps-range); '%1' is of kind '%2'")
                             .arg(c.inputPath(0), c.stream(0) ? c.stream(0)->info().kind : QString()));
    if (p.model == ModelKind::Pseudo || p.model == ModelKind::Augmented) {
        auto track = TrackGeometry::resolve(c.project().geometry(), c.text(QStringLiteral("track")));
        if (!track) return makeError(QStringLiteral("track: %1").arg(track.message()));
        TrackPose pose = track->pose();
        if (c.has(QStringLiteral("track_x"))) pose.x = c.number(QStringLiteral("track_x"));
        if (c.has(QStringLiteral("track_y"))) pose.y = c.number(QStringLiteral("track_y"));
        if (c.has(QStringLiteral("track_rotation"))) pose.rotation = c.number(QStringLiteral("track_rotation"));
        track->setPose(pose);
        p.track = std::make_shared<const TrackGeometry>(std::move(*track));
    }
    NoiseSettings& n = p.noise;
    n.ctra.qPosition = c.number(QStringLiteral("q_position"));
    n.ctra.qSpeed = c.number(QStringLiteral("q_speed"));
    n.ctra.qAccel = c.number(QStringLiteral("q_accel"));
    n.qAccelCv = n.ctra.qAccel;
    n.ctra.qHeading = c.number(QStringLiteral("q_heading"));
    n.ctra.qTurnRate = c.number(QStringLiteral("q_turn_rate"));
    n.ctra.rX = c.number(QStringLiteral("r_x"));
    n.ctra.rY = c.number(QStringLiteral("r_y"));
    n.rHeading = c.number(QStringLiteral("r_heading"));
    n.rTurnRate = c.number(QStringLiteral("r_turn_rate"));
    n.rAccel = c.number(QStringLiteral("r_accel"));
    n.gate = c.number(QStringLiteral("gate")) > 0 ? c.number(QStringLiteral("gate")) : kInf;
    const QString smoother = c.text(QStringLiteral("smoother"));
    p.smoothing = smoother == QLatin1String("rts")         ? estimation::Smoothing::Rts
                  : smoother == QLatin1String("fixed-lag") ? estimation::Smoothing::FixedLag
                                                           : estimation::Smoothing::None;
    p.lag = c.number(QStringLiteral("lag"));
    p.bridgeGap = c.number(QStringLiteral("bridge_gap"));
    if (p.smoothing == estimation::Smoothing::FixedLag && !(p.lag > 0))
        return makeError(QStringLiteral("lag must be > 0 s with smoother=fixed-lag"));
    if (c.has(QStringLiteral("output_rate")) && !(c.number(QStringLiteral("output_rate")) > 0))
        return makeError(QStringLiteral("output_rate must be > 0 Hz (leave it out to output at the input times)"));
    p.maxStep = c.number(QStringLiteral("max_step"));
    p.cvSwitch = c.flag(QStringLiteral("cv_switch"));
    p.accelPhase = c.number(QStringLiteral("accel_phase"));
    return p;
}

Status PositionFilterProcessor::prepare(const RunContext& context) const {
    auto params = readParams(context);
    if (!params) return params.error();
    if (rawRanges(context)) {
        if (auto refused = refuseProfileForRanges(context); !refused) return refused;
        return statusOf(loadRanges(context));
    }
    if (auto profile = noiseProfile(context, params->model); !profile) return profile.error();
    auto samples = positionSamples(context, 0);
    if (!samples) return samples.error();
    return {};
}

Expected<std::vector<ProcessorOutput>> PositionFilterProcessor::run(const RunContext& context) const {
    auto paramsOr = readParams(context);
    if (!paramsOr) return paramsOr.error();
    PositionFilter::Params params = std::move(*paramsOr);
    if (rawRanges(context)) return runRanges(context, params);
    auto samplesOr = positionSamples(context, 0);
    if (!samplesOr) return samplesOr.error();
    const PositionSamples& in = *samplesOr;
    const bool autoNoise = context.text(QStringLiteral("noise")) == QLatin1String("auto");

    QJsonObject attributes;
    auto profile = noiseProfile(context, params.model);
    if (!profile) return profile.error();
    if (*profile) {
        params.noise = (*profile)->noise;
        attributes.insert(QStringLiteral("noise_profile"), context.text(QStringLiteral("noise")).mid(8));
    }
    if (autoNoise) {
        const Progress sub = context.progress().sub(0.0, 0.8);
        const auto estimate =
            PositionFilter::estimateNoise(params,
                                          PositionFilter::noiseChunks(in, context.number(QStringLiteral("noise_chunk")),
                                                                      context.integer(QStringLiteral("noise_chunks"))),
                                          estimation::NoiseEstimator::Params{}, [&](double f) {
                                              sub.report(f, QStringLiteral("estimating noise"));
                                              return !context.isCancelled();
                                          });
        if (estimate.cancelled || context.isCancelled()) return cancelledError();
        params.noise = estimate.noise;
        attributes.insert(QStringLiteral("estimated_noise"), estimateAttributes(estimate));
    }
    attributes.insert(QStringLiteral("noise"), noiseAttributes(params.noise, params.model));

    const bool grid = context.has(QStringLiteral("output_rate"));
    const std::vector<double> tOut =
        grid ? PositionFilter::outputGrid(in.t.front(), in.t.back(), context.number(QStringLiteral("output_rate")))
             : in.t;
    const Progress sub = context.progress().sub(autoNoise ? 0.8 : 0.0, 1.0);
    const PositionFilter filter(params);
    const PositionFilterResult r = filter.run(in, tOut, [&](double f) {
        sub.report(f, QStringLiteral("filtering"));
        return !context.isCancelled();
    });
    if (r.cancelled || context.isCancelled()) return cancelledError();
    return trajectoryOutputs(context, r, in.t, nullptr, attributes);
}

}  // namespace athlos::positioning
