#include "plugins/lps/LpsCalibrationProcessor.h"

#include "core/processing/Translator.h"
#include "plugins/lps/BeaconTable.h"
#include "plugins/lps/LpsCalibration.h"
#include "plugins/lps/LpsInputs.h"

#include <cmath>

namespace athlos::lps {

namespace {
constexpr Translator tr{"athlos::lps", "LpsCalibrationProcessor"};

ParameterSpec optionalNumber(const QString& name, const QString& unit, const QString& help, double min = -1e9,
                             double max = 1e9) {
    ParameterSpec spec = ParameterSpec::number(name, 0.0, min, max, unit, help);
    spec.defaultValue = QVariant();
    spec.optional = true;
    return spec;
}
}  // namespace

QString LpsCalibrationProcessor::name() const { return tr("LPS beacon calibration"); }

QString LpsCalibrationProcessor::description() const {
    return tr(
        "Automatic calibration of a TDoA LPS from a walk at constant height and rough initial beacon positions: "
        "outlier removal, ~200 well-spread fixes, joint least squares over beacons, tag positions and offsets "
        "(minimising nRMSR), multi-start when residuals stay high. The rotation about the reference node's "
        "vertical axis is not observable from TDoA: it is taken from the running track when the walk follows it "
        "(gauge=auto|track, thesis step 6 \"rotate the frame to venue marks\") or from the initial guess.");
}

ParameterSpecs LpsCalibrationProcessor::parameters() const {
    return {
        optionalNumber(QStringLiteral("walk_height"), QStringLiteral("m"),
                       tr("Height of the tag during the walk in the LPS frame; absent = estimated (one unknown for the "
                          "whole walk)."),
                       -100, 1000),
        ParameterSpec::number(QStringLiteral("walk_height_prior"), 1.0, -100, 1000, QStringLiteral("m"),
                              tr("Prior mean of the estimated walk height (hand-held tag).")),
        ParameterSpec::number(QStringLiteral("walk_height_sigma"), 0.5, 1e-3, 100, QStringLiteral("m"),
                              tr("Prior standard deviation of the estimated walk height.")),
        ParameterSpec::integer(QStringLiteral("calibration_fixes"), 200, 0, 100000,
                               tr("Fixes spread over the area used for the calibration (thesis: 200); 0 = all.")),
        ParameterSpec::choice(QStringLiteral("outlier_test"), {QStringLiteral("grubbs"), QStringLiteral("mad")},
                              QStringLiteral("grubbs"), tr("Outlier test on the residuals.")),
        ParameterSpec::number(QStringLiteral("alpha"), 0.05, 1e-6, 0.5, QString(),
                              tr("Significance of the Grubbs test.")),
        ParameterSpec::number(QStringLiteral("prior_sigma_xy"), 2.0, 1e-3, 1000, QStringLiteral("m"),
                              tr("Horizontal uncertainty of the initial beacon positions (weak prior).")),
        ParameterSpec::number(QStringLiteral("prior_sigma_z"), 1.0, 1e-3, 1000, QStringLiteral("m"),
                              tr("Vertical uncertainty of the initial beacon positions (weak prior).")),
        ParameterSpec::number(
            QStringLiteral("tolerance"), 1e-4, 1e-12, 0.1, QString(),
            tr("Stop when nRMSR improves by less than this fraction per iteration (thesis: 0.01 %).")),
        ParameterSpec::integer(QStringLiteral("max_starts"), 5, 1, 100,
                               tr("Starts from re-perturbed initial positions while nRMSR stays above restart_nrmsr.")),
        ParameterSpec::number(QStringLiteral("restart_nrmsr"), 0.3, 0.0, 1000, QStringLiteral("m"),
                              tr("nRMSR above which the calibration restarts (about 3× the ranging noise).")),
        ParameterSpec::integer(QStringLiteral("seed"), 1, 0, std::numeric_limits<int>::max(),
                               tr("Seed of the restart perturbations (reproducible).")),
        ParameterSpec::choice(
            QStringLiteral("gauge"), {QStringLiteral("auto"), QStringLiteral("guess"), QStringLiteral("track")},
            QStringLiteral("auto"),
            tr("Rotation about the reference node's vertical axis. auto: fit the walk to a line parallel "
               "to the track and use that rotation if the fit is tight, covers the lap and agrees with "
               "the guess, else the guess; guess: from the initial beacon table only; track: always "
               "from the track fit.")),
        ParameterSpec::text(QStringLiteral("track"), QStringLiteral("iaaf-400m"),
                            tr("Track geometry the walk follows: a name under the project's /geometry or a built-in "
                               "(iaaf-400m, indoor-200m). Used by gauge=auto|track.")),
        optionalNumber(QStringLiteral("track_x"), QStringLiteral("m"),
                       tr("Track origin x in LPS coordinates (overrides the geometry's pose).")),
        optionalNumber(QStringLiteral("track_y"), QStringLiteral("m"), tr("Track origin y in LPS coordinates.")),
        optionalNumber(QStringLiteral("track_rotation"), QStringLiteral("rad"),
                       tr("Rotation of the track frame in LPS coordinates (counter-clockwise)."), -10.0, 10.0),
        ParameterSpec::number(QStringLiteral("gauge_max_rms"), 0.5, 1e-3, 100, QStringLiteral("m"),
                              tr("gauge=auto: largest RMS distance of the walk from its fitted track line.")),
        optionalNumber(QStringLiteral("gauge_guess_sigma"), QStringLiteral("m"),
                       tr("gauge=auto: horizontal error of the initial guess for the agreement test (the track "
                          "rotation must agree with the guess within 3σ); absent = prior_sigma_xy."),
                       1e-3, 1000),
        ParameterSpec::choice(QStringLiteral("geometry_check"), {QStringLiteral("refuse"), QStringLiteral("warn")},
                              QStringLiteral("refuse"),
                              tr("Beacons too few, clustered or collinear for the walk's area (horizontal spread "
                                 "below 1 m or below 1/50 of the area's extent): refuse the calibration, or only "
                                 "report it (report attributes geometry, geometry_reason).")),
        ParameterSpec::boolean(QStringLiteral("adapt_prior"), true,
                               tr("Widen the prior to the guess error the first start finds (σ̂ from the horizontal "
                                  "shifts) when it exceeds 1.5 × prior_sigma_xy, and restart around that solution; "
                                  "for guesses metres off (aerial image, GNSS).")),
        ParameterSpec::boolean(QStringLiteral("beacons_above_walk"), true,
                               tr("Height plausibility: beacons are mounted above the walking tag. A planar walk "
                                  "cannot tell a beacon from its reflection in the walk plane; reflections below "
                                  "are flipped back (else each reflection is tested on nRMSR).")),
        ParameterSpec::number(QStringLiteral("min_beacon_clearance"), 0.5, 0.0, 100, QStringLiteral("m"),
                              tr("beacons_above_walk: least height of a beacon above the walk plane.")),
        ParameterSpec::boolean(QStringLiteral("track_constraint"), true,
                               tr("gauge=auto|track: one extra start with the walk's tags on a line parallel to the "
                                  "track; it is taken when at least 80 % of its tags lie within 3 × track_sigma of "
                                  "the line (nRMSR alone does not see a wrong geometry).")),
        ParameterSpec::number(QStringLiteral("track_sigma"), 0.3, 1e-3, 100, QStringLiteral("m"),
                              tr("track_constraint: σ of the walk's lateral offset about its line.")),
        ParameterSpec::number(QStringLiteral("final_tolerance"), 1e-9, 1e-15, 0.1, QString(),
                              tr("Relative nRMSR change that stops the final least-squares pass (the beacon heights "
                                 "lie in a flat valley the 0.01 % rule stops in).")),
        ParameterSpec::number(QStringLiteral("gauge_min_coverage"), 0.5, 0.0, 1.0, QString(),
                              tr("gauge=auto: least share of the lap (10 m bins) the walk must visit; on an oval also "
                                 "both bends.")),
    };
}

QList<InputSpec> LpsCalibrationProcessor::inputs() const {
    return {InputSpec{QStringLiteral("tdoa"),
                      {QStringLiteral("lps-tdoa")},
                      false,
                      false,
                      tr("TDoA readings of the calibration walk (tag at constant height, whole area).")},
            InputSpec{QStringLiteral("beacons"),
                      {QStringLiteral("beacons")},
                      true,
                      false,
                      tr("Initial beacon positions (site plan, aerial image, GNSS), from any recording.")},
            InputSpec{QStringLiteral("reference"),
                      {QStringLiteral("beacons")},
                      true,
                      true,
                      tr("Optional surveyed beacon table: adds nRMSR_ref and η to the report.")}};
}

QList<OutputSpec> LpsCalibrationProcessor::outputs() const {
    return {
        OutputSpec{QStringLiteral("beacons"), true, QString(), tr("Calibrated beacon table id, x, y, z (m).")},
        OutputSpec{
            QStringLiteral("report"), true, QStringLiteral("report"),
            tr("Per beacon: rms_residual (m), readings, shift (m); attributes: nRMSR before/after, η, walk height.")}};
}

Expected<std::vector<ProcessorOutput>> LpsCalibrationProcessor::run(const RunContext& context) const {
    auto initial = loadBeacons(context, 1);
    if (!initial) return initial.error();
    std::optional<BeaconLayout> reference;
    if (context.inputCount() > 2 && context.table(2)) {
        auto ref = loadBeacons(context, 2);
        if (!ref) return ref.error();
        if (ref->ids != initial->ids)
            return makeError(QStringLiteral("reference table '%1' must list the same beacon ids as '%2'")
                                 .arg(context.inputPath(2), context.inputPath(1)));
        reference = std::move(*ref);
    }
    auto epochs = loadEpochs(context, 0, *initial);
    if (!epochs) return epochs.error();

    LpsCalibration::Params p;
    if (context.has(QStringLiteral("walk_height"))) p.walkHeight = context.number(QStringLiteral("walk_height"));
    p.walkHeightPrior = context.number(QStringLiteral("walk_height_prior"));
    p.walkHeightSigma = context.number(QStringLiteral("walk_height_sigma"));
    p.calibrationFixes = context.integer(QStringLiteral("calibration_fixes"));
    p.outlierTest = context.text(QStringLiteral("outlier_test")) == QLatin1String("mad")
                        ? LpsCalibration::OutlierTest::Mad
                        : LpsCalibration::OutlierTest::Grubbs;
    p.alpha = context.number(QStringLiteral("alpha"));
    p.priorSigmaXy = context.number(QStringLiteral("prior_sigma_xy"));
    p.priorSigmaZ = context.number(QStringLiteral("prior_sigma_z"));
    p.relativeTolerance = context.number(QStringLiteral("tolerance"));
    p.maxStarts = context.integer(QStringLiteral("max_starts"));
    p.restartNrmsr = context.number(QStringLiteral("restart_nrmsr"));
    p.seed = std::uint64_t(context.integer(QStringLiteral("seed")));
    const QString gauge = context.text(QStringLiteral("gauge"));
    p.gauge = gauge == QLatin1String("guess")   ? LpsCalibration::Gauge::Guess
              : gauge == QLatin1String("track") ? LpsCalibration::Gauge::Track
                                                : LpsCalibration::Gauge::Auto;
    if (p.gauge != LpsCalibration::Gauge::Guess) {
        auto track = loadTrack(context);
        if (!track) return track.error();
        TrackPose pose = track->pose();
        if (context.has(QStringLiteral("track_x"))) pose.x = context.number(QStringLiteral("track_x"));
        if (context.has(QStringLiteral("track_y"))) pose.y = context.number(QStringLiteral("track_y"));
        if (context.has(QStringLiteral("track_rotation")))
            pose.rotation = context.number(QStringLiteral("track_rotation"));
        track->setPose(pose);
        p.track = std::move(*track);
    }
    p.geometryCheck = context.text(QStringLiteral("geometry_check")) == QLatin1String("warn")
                          ? LpsCalibration::GeometryCheck::Warn
                          : LpsCalibration::GeometryCheck::Refuse;
    p.adaptPrior = context.flag(QStringLiteral("adapt_prior"));
    p.beaconsAboveWalk = context.flag(QStringLiteral("beacons_above_walk"));
    p.minBeaconClearance = context.number(QStringLiteral("min_beacon_clearance"));
    p.trackConstraint = context.flag(QStringLiteral("track_constraint"));
    p.trackSigma = context.number(QStringLiteral("track_sigma"));
    p.finalTolerance = context.number(QStringLiteral("final_tolerance"));
    p.gaugeMaxRms = context.number(QStringLiteral("gauge_max_rms"));
    p.gaugeMinCoverage = context.number(QStringLiteral("gauge_min_coverage"));
    if (context.has(QStringLiteral("gauge_guess_sigma")))
        p.gaugeGuessSigma = context.number(QStringLiteral("gauge_guess_sigma"));

    auto result =
        LpsCalibration(p).run(epochs->epochs, *initial, context.progress(), reference ? &*reference : nullptr);
    if (!result) return context.isCancelled() ? cancelledError() : result.error();
    const auto& report = result->report;

    Table beacons = tableFromLayout(result->beacons);
    QJsonObject summary{{"nrmsr_initial", report.nrmsrInitial},
                        {"nrmsr_calibrated", report.nrmsrCalibrated},
                        {"walk_height", report.walkHeight},
                        {"fixes_used", report.fixesUsed},
                        {"fixes_removed", report.fixesRemoved},
                        {"readings_removed", report.readingsRemoved},
                        {"starts", report.starts},
                        {"iterations", report.iterations},
                        {"converged", report.converged},
                        {"prior_sigma_xy_used", report.priorSigmaXy},
                        {"poor_guess", report.poorGuess},
                        {"mirrored_beacons", report.mirrored},
                        {"track_constrained", report.trackConstrained},
                        {"units", QStringLiteral("nRMSR, heights, offsets and RMS in m; rotations in rad")}};
    const auto& g = report.gauge;
    summary.insert(QStringLiteral("gauge_requested"), QString::fromLatin1(LpsCalibration::gaugeName(g.requested)));
    summary.insert(QStringLiteral("gauge"), QString::fromLatin1(LpsCalibration::gaugeName(g.used)));
    summary.insert(QStringLiteral("gauge_reason"), g.reason);
    summary.insert(QStringLiteral("gauge_rotation"), g.rotation);
    summary.insert(QStringLiteral("gauge_sigma_guess"), g.sigmaGuess);
    if (g.requested != LpsCalibration::Gauge::Guess) {
        summary.insert(QStringLiteral("gauge_track"), p.track.name());
        summary.insert(QStringLiteral("gauge_fit_valid"), g.fit.valid);
        summary.insert(QStringLiteral("gauge_fit_rotation"), g.fit.rotation);
        summary.insert(QStringLiteral("gauge_fit_sigma"), g.fit.sigmaRotation);
        summary.insert(QStringLiteral("gauge_fit_rms"), g.fit.rms);
        summary.insert(QStringLiteral("gauge_fit_inliers"), g.fit.inlierShare);
        summary.insert(QStringLiteral("gauge_fit_coverage"), g.fit.coverage);
        summary.insert(QStringLiteral("gauge_fit_both_bends"), g.fit.bothBends);
        summary.insert(QStringLiteral("gauge_lateral_offset"), g.fit.lateralOffset);
        summary.insert(QStringLiteral("gauge_fit_points"), g.fit.points);
    }
    const auto& geo = report.geometry;
    summary.insert(QStringLiteral("geometry"), report.geometryWarning.isEmpty() ? QStringLiteral("ok")
                                               : !geo.observable2d()            ? QStringLiteral("unobservable")
                                                                                : QStringLiteral("warning"));
    summary.insert(QStringLiteral("geometry_reason"), report.geometryWarning);
    summary.insert(QStringLiteral("geometry_spread_major"), geo.spreadMajor);
    summary.insert(QStringLiteral("geometry_spread_minor"), geo.spreadMinor);
    summary.insert(QStringLiteral("geometry_spread_vertical"), geo.spreadVertical);
    if (std::isfinite(geo.dilution)) summary.insert(QStringLiteral("geometry_dilution"), geo.dilution);
    if (std::isfinite(report.trackShare)) summary.insert(QStringLiteral("track_share"), report.trackShare);
    if (reference) {
        summary.insert(QStringLiteral("nrmsr_reference"), report.nrmsrReference);
        summary.insert(QStringLiteral("eta_initial"), report.etaInitial());
        summary.insert(QStringLiteral("eta_calibrated"), report.etaCalibrated());
    }
    beacons.attributes.insert(QStringLiteral("calibration"), summary);

    Table table;
    table.name = QStringLiteral("report");
    table.kind = QStringLiteral("report");
    table.attributes = summary;
    TableColumn id{QStringLiteral("id"), QString(), true, {}, result->beacons.ids};
    TableColumn rms{QStringLiteral("rms_residual"), QStringLiteral("m"), false, {}, {}};
    TableColumn readings{QStringLiteral("readings"), QStringLiteral("1"), false, {}, {}};
    TableColumn shift{QStringLiteral("shift"), QStringLiteral("m"), false, {}, {}};
    for (const auto& b : report.beacons) {
        rms.numbers.push_back(b.rmsResidual);
        readings.numbers.push_back(b.readings);
        shift.numbers.push_back(b.shift);
    }
    table.columns = {std::move(id), std::move(rms), std::move(readings), std::move(shift)};

    std::vector<ProcessorOutput> outputs;
    outputs.push_back({QString(), std::move(beacons)});
    outputs.push_back({QStringLiteral("report"), std::move(table)});
    return outputs;
}

}  // namespace athlos::lps
