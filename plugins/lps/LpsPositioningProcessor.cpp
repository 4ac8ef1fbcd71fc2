#include "plugins/lps/LpsPositioningProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/lps/BeaconGeometry.h"
#include "plugins/lps/BeaconTable.h"
#include "plugins/lps/LpsInputs.h"
#include "plugins/lps/RangeSolver.h"
#include "plugins/lps/RangeStream.h"

#include <QJsonArray>
#include <algorithm>
#include <cmath>

namespace athlos::lps {

namespace {
constexpr Translator tr{"athlos::lps", "LpsPositioningProcessor"};

// Why a run gave no fix at all (issue #13 item 8: a run that produces nothing fails with the reason,
// naming the stream and the numbers): too few beacons at every instant, or enough beacons but no
// converged, accepted solution.
Error noFixError(const RunContext& context, const std::vector<TdoaEpoch>& epochs, int minBeacons, bool spatial) {
    std::size_t most = 0, enough = 0;
    for (const auto& e : epochs) {
        most = std::max(most, e.readings.size());
        enough += e.readings.size() >= std::size_t(minBeacons);
    }
    const QString least = QStringLiteral("≥%1").arg(minBeacons);
    const QString why = QStringLiteral("min_beacons, %1").arg(spatial ? QStringLiteral("3d") : QStringLiteral("2d"));
    if (epochs.empty())
        return makeError(
            QStringLiteral("no fix: TDoA stream '%1' has no readings (every dt is NaN)").arg(context.inputPath(0)));
    if (enough == 0)
        return makeError(QStringLiteral("no fix: no instant of TDoA stream '%1' had enough beacons: need %2 (%3), the "
                                        "most was %4 (%5 instants, beacon table '%6')")
                             .arg(context.inputPath(0), least, why)
                             .arg(most)
                             .arg(epochs.size())
                             .arg(context.inputPath(1)));
    return makeError(QStringLiteral("no fix: %1 of %2 instants of TDoA stream '%3' had %4 beacons (%5) but none gave a "
                                    "converged, accepted solution (check the beacon table '%6' and the stream's frame)")
                         .arg(enough)
                         .arg(epochs.size())
                         .arg(context.inputPath(0), least, why, context.inputPath(1)));
}
}  // namespace

struct LpsPositioningProcessor::Plan {
    TdoaPositioning::Params params;
    BeaconLayout layout;
    TrackGeometry track;
    EpochSet epochs;  // TDoA instants, or merged range epochs (dt = range in m) when `ranges`
    bool ranges = false;
    RangeSolver::Params rangeSolver;
    std::shared_ptr<const StreamData> orientation;
    int orientationColumns[4] = {-1, -1, -1, -1};
};

QString LpsPositioningProcessor::name() const { return tr("LPS positioning (TDoA, ranges)"); }

QString LpsPositioningProcessor::description() const {
    return tr(
        "Tag positions and clock offsets from TDoA readings and a beacon table, one fix per instant "
        "(2D at tag_height or 3D), with beacon selection against NLOS: all, IRLS (bisquare, 2.5·MAD), "
        "largest-residual rejection or the field of view of the body-worn tag. Two-way ranges (lps-range): ToA fixes "
        "on epochs merged from the anchors' own report times, with all beacons or IRLS.");
}

ParameterSpecs LpsPositioningProcessor::parameters() const {
    const double inf = std::numeric_limits<double>::infinity();
    return {
        ParameterSpec::choice(
            QStringLiteral("dimension"), {QStringLiteral("auto"), QStringLiteral("2d"), QStringLiteral("3d")},
            QStringLiteral("auto"),
            tr("2d solves x, y at tag_height; 3d also z; auto = 3d only when the beacons' height span "
               "is at least 30 % of their horizontal extent (else z is ill-conditioned).")),
        ParameterSpec::number(QStringLiteral("tag_height"), 1.2, -100, 1000, QStringLiteral("m"),
                              tr("Tag height in the LPS frame for 2D fixes.")),
        ParameterSpec::choice(QStringLiteral("selection"),
                              {QStringLiteral("all"), QStringLiteral("irls"), QStringLiteral("largest-residual"),
                               QStringLiteral("field-of-view"), QStringLiteral("grubbs"), QStringLiteral("kalman-gate"),
                               QStringLiteral("all-subsets"), QStringLiteral("best-subset")},
                              QStringLiteral("irls"),
                              tr("Beacon selection method (thesis §3.2, Fig. 3.16): grubbs and kalman-gate drop "
                                 "readings whose TDoA changes abruptly (Grubbs test on each beacon's TDoA rate; "
                                 "a constant-velocity Kalman filter per beacon with a Mahalanobis gate) and solve "
                                 "with the rest; all-subsets weights readings by their residuals summed over NLOS "
                                 "hypotheses (Cong & Zhuang); best-subset keeps the best-fitting 5 readings.")),
        ParameterSpec::number(QStringLiteral("screen_gate"), TdoaScreening::Params().gate, 0.1, 1e6, QString(),
                              tr("kalman-gate: squared Mahalanobis distance above which a reading is dropped.")),
        ParameterSpec::number(QStringLiteral("grubbs_alpha"), 0.05, 1e-6, 0.5, QString(),
                              tr("grubbs: significance level of the test (thesis: 0.05).")),
        ParameterSpec::integer(QStringLiteral("subset_max_excluded"), 3, 0, 16,
                               tr("all-subsets: NLOS hypotheses with at most this many readings (0 = all 2^B; "
                                  "slow beyond 12 readings).")),
        ParameterSpec::choice(
            QStringLiteral("loss"), {QStringLiteral("none"), QStringLiteral("huber"), QStringLiteral("cauchy")},
            QStringLiteral("none"), tr("Robust loss of the fix (solved with a ceres::Problem; slower).")),
        ParameterSpec::number(QStringLiteral("loss_scale"), 0.5, 1e-3, 100, QStringLiteral("m"),
                              tr("Residual at which the robust loss leaves its quadratic part.")),
        ParameterSpec::integer(QStringLiteral("min_beacons"), 4, 3, 64,
                               tr("Fewest beacons per fix (thesis: 4; TDoA needs at least 4, 2D ranges 3).")),
        ParameterSpec::number(QStringLiteral("epoch"), 0.1, 1e-3, 60.0, QStringLiteral("s"),
                              tr("Ranges: one fix every this many seconds from each anchor's newest range.")),
        ParameterSpec::number(QStringLiteral("max_age"), 0.15, 0.0, 60.0, QStringLiteral("s"),
                              tr("Ranges: a range older than this at the epoch is left out (never extrapolated).")),
        ParameterSpec::number(QStringLiteral("irls_k"), 2.5, 0.5, 10, QString(),
                              tr("IRLS: bisquare cut-off in units of 1.4826·MAD of the residuals.")),
        ParameterSpec::number(QStringLiteral("rejection_threshold"), 0.25, 0.0, 100, QStringLiteral("m"),
                              tr("largest-residual: stop rejecting when the mean |residual| is below this.")),
        ParameterSpec::number(QStringLiteral("kappa"), 100.0, -inf, inf, QStringLiteral("dB"),
                              tr("field-of-view: κ of the rule G_t(φ) − L_fs + κ > 0 (Eqn. 3.8).")),
        ParameterSpec::text(QStringLiteral("gain_pattern"), QString(),
                            tr("field-of-view: body-worn tag pattern as 'angle_deg:linear_gain,…' (0° = forward; "
                               "0…180° is mirrored); empty = ((1+cos φ)/2)^6 with −30 dB behind.")),
        ParameterSpec::number(QStringLiteral("frequency"), 5.8e9, 1e6, 1e12, QStringLiteral("Hz"),
                              tr("field-of-view: carrier frequency for the free-space loss.")),
        ParameterSpec::boolean(QStringLiteral("fov_refine"), true,
                               tr("field-of-view: afterwards reject gross outliers among the beacons in view "
                                  "(leave-one-out), and re-solve a fix more than 4 m from the median of the "
                                  "last five fixes with IRLS over all beacons.")),
        ParameterSpec::choice(QStringLiteral("heading"),
                              {QStringLiteral("track"), QStringLiteral("orientation"), QStringLiteral("motion")},
                              QStringLiteral("track"),
                              tr("field-of-view: body heading from the track geometry and running direction, from the "
                                 "orientation input (sensor x axis = forward) or from the direction of travel.")),
        ParameterSpec::text(QStringLiteral("track"), QStringLiteral("iaaf-400m"),
                            tr("field-of-view, heading=track: project geometry name or built-in track; the LPS frame "
                               "must be the track's (see lps-align).")),
        ParameterSpec::choice(QStringLiteral("direction"), {QStringLiteral("ccw"), QStringLiteral("cw")},
                              QStringLiteral("ccw"),
                              tr("field-of-view, heading=track: running direction (athletics: counter-clockwise).")),
    };
}

QList<InputSpec> LpsPositioningProcessor::inputs() const {
    return {InputSpec{QStringLiteral("tdoa"),
                      {QStringLiteral("lps-tdoa"), QStringLiteral("lps-range")},
                      false,
                      false,
                      tr("TDoA readings t, beacon, dt (s), several rows per instant; or two-way ranges t, beacon, "
                         "range (m).")},
            InputSpec{QStringLiteral("beacons"),
                      {QStringLiteral("beacons")},
                      true,
                      false,
                      tr("Beacon table id, x, y, z (m), from any recording; a row 'ref' places the reference node.")},
            InputSpec{QStringLiteral("orientation"),
                      {QStringLiteral("orientation")},
                      false,
                      true,
                      tr("Optional orientation (qw, qx, qy, qz) for heading=orientation.")}};
}

QList<OutputSpec> LpsPositioningProcessor::outputs() const {
    return {OutputSpec{
        QStringLiteral("lps-position"), false, QString(),
        tr("t, x, y, z (m), offset (s), rms_residual (m), n_beacons, dop (dilution of precision) per fix.")}};
}

bool LpsPositioningProcessor::geometryAllows3d(const BeaconLayout& layout) {
    double zMin = INFINITY, zMax = -INFINITY, extent = 0.0;
    for (const auto& a : layout.positions) {
        zMin = std::min(zMin, a.z());
        zMax = std::max(zMax, a.z());
        for (const auto& b : layout.positions) extent = std::max(extent, (a - b).head<2>().norm());
    }
    return zMax - zMin >= 0.3 * extent;
}

Expected<LpsPositioningProcessor::Plan> LpsPositioningProcessor::makePlan(const RunContext& context) const {
    Plan plan;
    plan.ranges = context.stream(0) && context.stream(0)->info().kind == QLatin1String("lps-range");
    if (plan.ranges) return makeRangePlan(context);
    auto layout = loadBeacons(context, 1);
    if (!layout) return layout.error();
    plan.layout = std::move(*layout);

    auto& solver = plan.params.solver;
    const QString dimension = context.text(QStringLiteral("dimension"));
    const bool spatial =
        dimension == QLatin1String("3d") || (dimension == QLatin1String("auto") && geometryAllows3d(plan.layout));
    solver.geometry = spatial ? TdoaSolver::Geometry::Spatial : TdoaSolver::Geometry::Planar;
    solver.tagHeight = context.number(QStringLiteral("tag_height"));
    const QString loss = context.text(QStringLiteral("loss"));
    solver.loss = loss == QLatin1String("huber")    ? TdoaSolver::Loss::Huber
                  : loss == QLatin1String("cauchy") ? TdoaSolver::Loss::Cauchy
                                                    : TdoaSolver::Loss::None;
    solver.lossScale = context.number(QStringLiteral("loss_scale"));

    auto& sel = plan.params.selection;
    const QString method = context.text(QStringLiteral("selection"));
    const bool screen = method == QLatin1String("grubbs") || method == QLatin1String("kalman-gate");
    sel.method = method == QLatin1String("all") || screen      ? BeaconSelection::Method::All
                 : method == QLatin1String("largest-residual") ? BeaconSelection::Method::LargestResidual
                 : method == QLatin1String("field-of-view")    ? BeaconSelection::Method::FieldOfView
                 : method == QLatin1String("all-subsets")      ? BeaconSelection::Method::AllSubsets
                 : method == QLatin1String("best-subset")      ? BeaconSelection::Method::BestSubset
                                                               : BeaconSelection::Method::Irls;
    auto& scr = plan.params.screening;
    scr.method = method == QLatin1String("grubbs")        ? TdoaScreening::Method::GrubbsRate
                 : method == QLatin1String("kalman-gate") ? TdoaScreening::Method::KalmanGate
                                                          : TdoaScreening::Method::None;
    scr.gate = context.number(QStringLiteral("screen_gate"));
    scr.alpha = context.number(QStringLiteral("grubbs_alpha"));
    sel.subsetMaxExcluded = context.integer(QStringLiteral("subset_max_excluded"));
    sel.minBeacons = std::max(context.integer(QStringLiteral("min_beacons")), spatial ? 5 : 4);
    sel.irlsK = context.number(QStringLiteral("irls_k"));
    sel.rejectionThreshold = context.number(QStringLiteral("rejection_threshold"));
    sel.kappa = context.number(QStringLiteral("kappa"));
    sel.frequency = context.number(QStringLiteral("frequency"));
    sel.fovRefine = context.flag(QStringLiteral("fov_refine"));
    if (const QString pattern = context.text(QStringLiteral("gain_pattern")); !pattern.trimmed().isEmpty()) {
        auto gain = GainPattern::parse(pattern);
        if (!gain) return gain.error();
        sel.gain = *gain;
    }
    if (plan.layout.size() < sel.minBeacons)
        return makeError(QStringLiteral("min_beacons = %1 but the beacon table '%2' has only %3 beacons")
                             .arg(sel.minBeacons)
                             .arg(context.inputPath(1))
                             .arg(plan.layout.size()));

    const QString heading = context.text(QStringLiteral("heading"));
    plan.params.heading = heading == QLatin1String("orientation") ? TdoaPositioning::HeadingSource::Orientation
                          : heading == QLatin1String("motion")    ? TdoaPositioning::HeadingSource::Motion
                                                                  : TdoaPositioning::HeadingSource::Track;
    plan.params.clockwise = context.text(QStringLiteral("direction")) == QLatin1String("cw");
    if (sel.method == BeaconSelection::Method::FieldOfView) {
        if (plan.params.heading == TdoaPositioning::HeadingSource::Track) {
            auto track = loadTrack(context);
            if (!track) return track.error();
            plan.track = std::move(*track);
        }
        if (plan.params.heading == TdoaPositioning::HeadingSource::Orientation) {
            if (!context.stream(2))
                return makeError(QStringLiteral("heading=orientation needs the orientation input (a third --input)"));
            const char* names[] = {"qw", "qx", "qy", "qz"};
            for (int c = 0; c < 4; ++c) {
                plan.orientationColumns[c] = context.stream(2)->info().columnIndex(QString::fromLatin1(names[c]));
                if (plan.orientationColumns[c] < 0)
                    return context.inputError(2, QStringLiteral("no column %1").arg(QString::fromLatin1(names[c])));
            }
            auto orientation = context.samples(2);
            if (!orientation) return orientation.error();
            plan.orientation = orientation->data;
        }
    }
    auto epochs = loadEpochs(context, 0, plan.layout);
    if (!epochs) return epochs.error();
    plan.epochs = std::move(*epochs);
    return plan;
}

Expected<LpsPositioningProcessor::Plan> LpsPositioningProcessor::makeRangePlan(const RunContext& context) const {
    Plan plan;
    plan.ranges = true;
    auto table = context.requireTable(1);
    if (!table) return table.error();
    auto layout = layoutFromTable(**table, context.inputPath(1), 3, QStringLiteral("ranging"));
    if (!layout) return layout.error();
    plan.layout = std::move(*layout);
    RangeSolver::Params& solver = plan.rangeSolver;
    const QString dimension = context.text(QStringLiteral("dimension"));
    const bool spatial =
        dimension == QLatin1String("3d") || (dimension == QLatin1String("auto") && geometryAllows3d(plan.layout));
    solver.geometry = spatial ? RangeSolver::Geometry::Spatial : RangeSolver::Geometry::Planar;
    solver.tagHeight = context.number(QStringLiteral("tag_height"));
    const QString method = context.text(QStringLiteral("selection"));
    if (method != QLatin1String("all") && method != QLatin1String("irls"))
        return makeError(QStringLiteral("selection=%1 applies to TDoA; ranges use all or irls").arg(method));
    solver.selection = method == QLatin1String("all") ? RangeSolver::Selection::All : RangeSolver::Selection::Irls;
    solver.irlsK = context.number(QStringLiteral("irls_k"));
    if (context.text(QStringLiteral("loss")) != QLatin1String("none"))
        return makeError(QStringLiteral("loss applies to TDoA fixes; ranges use selection=irls"));
    plan.params.selection.minBeacons = std::max(context.integer(QStringLiteral("min_beacons")), spatial ? 4 : 3);
    if (plan.layout.size() < plan.params.selection.minBeacons)
        return makeError(QStringLiteral("min_beacons = %1 but the beacon table '%2' has only %3 beacons")
                             .arg(plan.params.selection.minBeacons)
                             .arg(context.inputPath(1))
                             .arg(plan.layout.size()));
    auto input = context.samples(0);
    if (!input) return input.error();
    auto set = rangesFromStream(*input->stream, *input->data, plan.layout, input->path);
    if (!set) return set.error();
    plan.epochs.readingsSkipped = set->readingsSkipped;
    plan.epochs.epochs = mergeRangeEpochs(set->readings, plan.layout.size(), context.number(QStringLiteral("epoch")),
                                          context.number(QStringLiteral("max_age")), plan.params.selection.minBeacons);
    if (plan.epochs.epochs.empty())
        return input->error(QStringLiteral("no epoch has %1 anchors with a range younger than max_age = %2 s")
                                .arg(plan.params.selection.minBeacons)
                                .arg(context.number(QStringLiteral("max_age"))));
    return plan;
}

std::optional<std::vector<TagFix>> LpsPositioningProcessor::solveRanges(const Plan& plan, const RunContext& context) {
    RangeSolver solver(plan.rangeSolver);
    std::vector<TagFix> fixes;
    fixes.reserve(plan.epochs.epochs.size());
    const TagFix* previous = nullptr;
    RangeFixInput input;
    for (std::size_t k = 0; k < plan.epochs.epochs.size(); ++k) {
        if ((k & 255) == 0) {
            if (context.isCancelled()) return std::nullopt;
            context.report(double(k) / double(plan.epochs.epochs.size()), QStringLiteral("ToA fixes"));
        }
        input.assign(plan.epochs.epochs[k], plan.layout);
        fixes.push_back(solver.solve(input, previous));
        previous = fixes.back().valid ? &fixes.back() : nullptr;
    }
    return fixes;
}

Status LpsPositioningProcessor::prepare(const RunContext& context) const { return statusOf(makePlan(context)); }

Expected<std::vector<ProcessorOutput>> LpsPositioningProcessor::run(const RunContext& context) const {
    auto plan = makePlan(context);
    if (!plan) return plan.error();
    TdoaPositioning::HeadingFunction orientationHeading;
    if (plan->orientation) {
        // Yaw of the sensor x axis rotated into the earth frame, at the nearest sample within 0.5 s.
        const StreamData* q = plan->orientation.get();
        const auto cols = plan->orientationColumns;
        orientationHeading = [q, cols](double t) -> std::optional<double> {
            auto it = std::lower_bound(q->t.begin(), q->t.end(), t);
            std::size_t k = std::size_t(it - q->t.begin());
            if (k == q->t.size() || (k > 0 && t - q->t[k - 1] < q->t[k] - t)) k = k ? k - 1 : 0;
            if (q->t.empty() || std::abs(q->t[k] - t) > 0.5) return std::nullopt;
            const double w = q->at(k, cols[0]), x = q->at(k, cols[1]), y = q->at(k, cols[2]), z = q->at(k, cols[3]);
            return std::atan2(2.0 * (x * y + w * z), 1.0 - 2.0 * (y * y + z * z));
        };
    }
    std::optional<std::vector<TagFix>> fixes;
    if (plan->ranges) {
        fixes = solveRanges(*plan, context);
    } else {
        TdoaPositioning positioning(plan->params, plan->layout, plan->track, orientationHeading);
        fixes = positioning.run(plan->epochs.epochs, context.progress());
    }
    if (!fixes) return cancelledError();

    StreamInfo info;
    info.name = QStringLiteral("lps");
    info.kind = QStringLiteral("lps-position");
    info.frame = QStringLiteral("lps");
    info.columns = {{QStringLiteral("x"), QStringLiteral("m")},
                    {QStringLiteral("y"), QStringLiteral("m")},
                    {QStringLiteral("z"), QStringLiteral("m")},
                    {QStringLiteral("offset"), QStringLiteral("s")},
                    {QStringLiteral("rms_residual"), QStringLiteral("m")},
                    {QStringLiteral("n_beacons"), QStringLiteral("1")},
                    {QStringLiteral("dop"), QStringLiteral("1")}};
    std::size_t valid = 0;
    for (const auto& f : *fixes) valid += f.valid;
    if (valid == 0 && plan->ranges)
        return makeError(QStringLiteral("no fix: none of %1 epochs of range stream '%2' gave a converged solution with "
                                        "an RMS residual below 2 m (check the beacon table '%3' and tag_height)")
                             .arg(plan->epochs.epochs.size())
                             .arg(context.inputPath(0), context.inputPath(1)));
    if (valid == 0)
        return noFixError(context, plan->epochs.epochs, plan->params.selection.minBeacons,
                          plan->params.solver.geometry == TdoaSolver::Geometry::Spatial);
    StreamData data(valid, 7);
    std::size_t r = 0;
    const bool planarFix = plan->ranges ? plan->rangeSolver.geometry == RangeSolver::Geometry::Planar
                                        : plan->params.solver.geometry == TdoaSolver::Geometry::Planar;
    std::vector<Vector3> reporting;
    for (std::size_t k = 0; k < fixes->size(); ++k) {
        const TagFix& f = (*fixes)[k];
        if (!f.valid) continue;
        // Dilution of precision of the fix over the beacons that reported at its instant (σ_pos ≈ DOP·σ_range).
        reporting.clear();
        if (fixes->size() == plan->epochs.epochs.size())
            for (const auto& reading : plan->epochs.epochs[k].readings)
                reporting.push_back(plan->layout.positions[std::size_t(reading.beacon)]);
        const double dop =
            plan->ranges ? toaDop(reporting, f.position, planarFix) : tdoaDop(reporting, f.position, planarFix);
        data.at(r, 6) = std::isfinite(dop) ? dop : std::numeric_limits<double>::quiet_NaN();
        data.t[r] = f.t;
        data.at(r, 0) = f.position.x();
        data.at(r, 1) = f.position.y();
        data.at(r, 2) = f.position.z();
        data.at(r, 3) = -f.offset / kSpeedOfLight;  // t_off of Eqn. 3.5
        data.at(r, 4) = f.rmsResidual;
        data.at(r, 5) = f.beaconsUsed;
        ++r;
    }
    info.attributes.insert(QStringLiteral("fixes_total"), qint64(fixes->size()));
    info.attributes.insert(QStringLiteral("geometry"), [&] {
        const QString reason = assessBeaconGeometry(plan->layout.positions).reason();
        return reason.isEmpty() ? QStringLiteral("ok") : reason;
    }());
    info.attributes.insert(QStringLiteral("fixes_dropped"), qint64(fixes->size() - valid));
    info.attributes.insert(QStringLiteral("readings_skipped"), qint64(plan->epochs.readingsSkipped));
    const bool planar = plan->ranges ? plan->rangeSolver.geometry == RangeSolver::Geometry::Planar
                                     : plan->params.solver.geometry == TdoaSolver::Geometry::Planar;
    info.attributes.insert(QStringLiteral("solver"), planar ? QStringLiteral("2d") : QStringLiteral("3d"));
    info.attributes.insert(QStringLiteral("measurements"),
                           plan->ranges ? QStringLiteral("ranges") : QStringLiteral("tdoa"));
    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), Stream(std::move(info), std::move(data))});
    return outputs;
}

}  // namespace athlos::lps
