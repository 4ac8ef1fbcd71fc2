#include "plugins/lps/LpsCalibration.h"

#include "plugins/lps/BeaconSelection.h"
#include "plugins/lps/FrameAlignment.h"
#include "plugins/lps/RobustStatistics.h"
#include "plugins/lps/TdoaSolver.h"

#include <ceres/ceres.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

namespace athlos::lps {

namespace {

// e = |m − b| − |r − b| − c·Δt − o  (Eqn. 3.1) with m = (x, y, h), scaled per fix (Eqn. 3.3's 1/B_n).
struct BundleResidual {
    double cdt;
    Vector3 reference;
    double scale;

    template <typename T>
    bool operator()(const T* beacon, const T* tag, const T* height, T* residual) const {
        const T mx = tag[0] - beacon[0], my = tag[1] - beacon[1], mz = height[0] - beacon[2];
        const T rx = T(reference.x()) - beacon[0], ry = T(reference.y()) - beacon[1], rz = T(reference.z()) - beacon[2];
        residual[0] =
            (sqrt(mx * mx + my * my + mz * mz) - sqrt(rx * rx + ry * ry + rz * rz) - T(cdt) - tag[2]) * T(scale);
        return true;
    }
};

// Weak Gaussian prior of a beacon towards its guessed position (fixes the rotation gauge).
struct GuessPrior {
    Vector3 guess;
    Vector3 inverseSigma;

    template <typename T>
    bool operator()(const T* beacon, T* residual) const {
        for (int k = 0; k < 3; ++k) residual[k] = (beacon[k] - T(guess[k])) * T(inverseSigma[k]);
        return true;
    }
};

struct HeightPrior {
    double prior, inverseSigma;
    template <typename T>
    bool operator()(const T* h, T* residual) const {
        residual[0] = (h[0] - T(prior)) * T(inverseSigma);
        return true;
    }
};

// Walk-on-the-track constraint (venue marks as constraints, thesis step 6): the tag's signed lateral
// offset from the track's reference line equals the walk's common offset d, within σ_track.
// Analytic Jacobian: ∂d_track/∂(x, y) is the unit vector to the right of the running direction.
class TrackLineResidual final : public ceres::SizedCostFunction<1, 3, 1> {
public:
    TrackLineResidual(const TrackGeometry* track, double inverseSigma) : track_(track), inverseSigma_(inverseSigma) {}
    bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
        const TrackQuery q = track_->query(Eigen::Vector2d(parameters[0][0], parameters[0][1]));
        residuals[0] = (q.d - parameters[1][0]) * inverseSigma_;
        if (jacobians) {
            if (jacobians[0]) {
                jacobians[0][0] = std::sin(q.heading) * inverseSigma_;
                jacobians[0][1] = -std::cos(q.heading) * inverseSigma_;
                jacobians[0][2] = 0.0;
            }
            if (jacobians[1]) jacobians[1][0] = -inverseSigma_;
        }
        return true;
    }

private:
    const TrackGeometry* track_;
    double inverseSigma_;
};

TdoaSolver planarSolver(double height) {
    TdoaSolver::Params p;
    p.geometry = TdoaSolver::Geometry::Planar;
    p.tagHeight = height;
    return TdoaSolver(p);
}

int usableReadings(const TdoaEpoch& e) { return int(e.readings.size()); }

}  // namespace

// One bundle adjustment from one starting layout.
struct LpsCalibration::Start {
    BeaconLayout beacons;
    double height = 0.0;
    std::vector<TdoaEpoch> epochs;  // outlier readings and fixes removed
    std::vector<Vector3> tags;      // x, y, o per epoch
    double lateral = 0.0;           // m, walk's offset from the track's reference line (track constraint)
    int mirrored = 0;               // beacons reflected in the walk plane by the mirror test
    double priorSigmaXy = 0.0;      // m, prior σ used (0 = the parameter's)
    int readingsRemoved = 0, fixesRemoved = 0, iterations = 0;
    bool converged = false;
    double nrmsr = std::numeric_limits<double>::infinity();
};

double LpsCalibration::nrmsr(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& beacons, double height,
                             int minBeacons) {
    TdoaSolver solver = planarSolver(height);
    const auto reference = referenceDistances(beacons);
    FixInput input;
    double sum = 0.0;
    int n = 0;
    for (const auto& epoch : epochs) {
        if (usableReadings(epoch) < minBeacons) continue;
        input.assign(epoch, beacons, reference);
        const TagFix fix = solver.solve(input);
        if (!fix.valid) continue;
        sum += fix.rmsResidual * fix.rmsResidual;  // |e_n|²/B_n
        ++n;
    }
    return n ? std::sqrt(sum / n) : std::numeric_limits<double>::quiet_NaN();
}

std::vector<int> LpsCalibration::spreadSelection(const std::vector<Vector3>& points, int count) {
    const int n = int(points.size());
    std::vector<int> chosen;
    if (count <= 0 || count >= n) {
        for (int i = 0; i < n; ++i) chosen.push_back(i);
        return chosen;
    }
    std::vector<double> distance(size_t(n), std::numeric_limits<double>::infinity());
    int next = 0;  // deterministic: start at the first fix of the walk
    for (int k = 0; k < count; ++k) {
        chosen.push_back(next);
        int best = -1;
        for (int i = 0; i < n; ++i) {
            distance[size_t(i)] =
                std::min(distance[size_t(i)], (points[size_t(i)] - points[size_t(next)]).head<2>().norm());
            if (best < 0 || distance[size_t(i)] > distance[size_t(best)]) best = i;
        }
        next = best;
    }
    std::sort(chosen.begin(), chosen.end());
    return chosen;
}

namespace {

struct BundleState {
    BeaconLayout* beacons;
    double* height;
    std::vector<Vector3>* tags;
    double* lateral = nullptr;  // non-null: tags constrained to a line parallel to the track
};

// Runs one bundle adjustment over the epochs; returns (iterations, converged).
std::pair<int, bool> solveBundle(const std::vector<TdoaEpoch>& epochs, BundleState state, const BeaconLayout& guess,
                                 const LpsCalibration::Params& params, ceres::LossFunction* loss, bool heightFree) {
    ceres::Problem::Options problemOptions;
    problemOptions.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problemOptions);
    double meanReadings = 0.0;
    for (const auto& e : epochs) meanReadings += double(e.readings.size());
    meanReadings /= double(std::max<std::size_t>(1, epochs.size()));
    auto& positions = state.beacons->positions;
    std::vector<bool> used(positions.size(), false);
    for (std::size_t n = 0; n < epochs.size(); ++n) {
        // Per-fix weight √(B̄/B_n): every fix counts equally (Eqn. 3.3), in units of the range noise.
        const double scale = std::sqrt(meanReadings / double(epochs[n].readings.size())) / params.rangeNoise;
        for (const auto& r : epochs[n].readings) {
            auto* cost = new ceres::AutoDiffCostFunction<BundleResidual, 1, 3, 3, 1>(
                new BundleResidual{kSpeedOfLight * r.dt, state.beacons->reference, scale});
            problem.AddResidualBlock(cost, loss, positions[size_t(r.beacon)].data(), (*state.tags)[n].data(),
                                     state.height);
            used[size_t(r.beacon)] = true;
        }
    }
    const Vector3 inverseSigma(1.0 / params.priorSigmaXy, 1.0 / params.priorSigmaXy, 1.0 / params.priorSigmaZ);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        if (!used[i]) continue;
        problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<GuessPrior, 3, 3>(new GuessPrior{guess.positions[i], inverseSigma}),
            nullptr, positions[i].data());
    }
    ceres::CauchyLoss trackLoss(params.trackSigmaOutlier / params.trackSigma);
    if (state.lateral)
        for (auto& tag : *state.tags)
            problem.AddResidualBlock(new TrackLineResidual(&params.track, 1.0 / params.trackSigma), &trackLoss,
                                     tag.data(), state.lateral);
    if (heightFree)
        problem.AddResidualBlock(new ceres::AutoDiffCostFunction<HeightPrior, 1, 1>(
                                     new HeightPrior{params.walkHeightPrior, 1.0 / params.walkHeightSigma}),
                                 nullptr, state.height);
    else
        problem.SetParameterBlockConstant(state.height);

    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_SCHUR;  // tags (x, y, o) eliminated: the inner per-fix solves
    auto* ordering = new ceres::ParameterBlockOrdering;
    for (auto& tag : *state.tags) ordering->AddElementToGroup(tag.data(), 0);
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (used[i]) ordering->AddElementToGroup(positions[i].data(), 1);
    ordering->AddElementToGroup(state.height, 1);
    if (state.lateral) ordering->AddElementToGroup(state.lateral, 1);
    options.linear_solver_ordering.reset(ordering);
    options.max_num_iterations = params.maxIterations;
    // Cost ∝ nRMSR²: a relative cost change of 2·tol is a relative nRMSR change of tol (0.01 %).
    options.function_tolerance = 2.0 * params.relativeTolerance;
    options.parameter_tolerance = 1e-10;
    options.logging_type = ceres::SILENT;
    options.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    return {int(summary.iterations.size()), summary.termination_type == ceres::CONVERGENCE};
}

}  // namespace

Expected<LpsCalibration::Start> LpsCalibration::adjust(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& start,
                                                       const BeaconLayout& guess, const Progress& progress,
                                                       bool onTrack) const {
    const bool heightFree = !std::isfinite(params_.walkHeight);
    Start s;
    s.beacons = start;
    s.height = heightFree ? params_.walkHeightPrior : params_.walkHeight;
    if (params_.beaconsAboveWalk)
        for (auto& b : s.beacons.positions)
            if (b.z() < s.height + params_.minBeaconClearance)
                b.z() = std::max(2.0 * s.height - b.z(), s.height + params_.minBeaconClearance);
    s.epochs = epochs;

    // Step 3: tag fixes with the starting beacons (IRLS keeps gross outliers out of the start).
    TdoaSolver solver = planarSolver(s.height);
    BeaconSelection irls;
    const auto reference = referenceDistances(s.beacons);
    FixInput input;
    s.tags.resize(s.epochs.size());
    for (std::size_t n = 0; n < s.epochs.size(); ++n) {
        input.assign(s.epochs[n], s.beacons, reference);
        const TagFix fix = irls.solve(input, solver, nullptr);
        s.tags[n] = fix.valid ? Vector3(fix.position.x(), fix.position.y(), fix.offset) : Vector3::Zero();
    }
    if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
    double* lateral = nullptr;
    if (onTrack) {
        // Start the tags on the track line (at the walk's median lateral offset) instead of where
        // the guessed beacons put them.
        std::vector<double> offsets;
        std::vector<TrackQuery> queries;
        for (const auto& tag : s.tags) {
            queries.push_back(params_.track.query(tag.head<2>()));
            offsets.push_back(queries.back().d);
        }
        s.lateral = std::clamp(math::median(offsets), -params_.trackMaxLateral, params_.trackMaxLateral);
        for (std::size_t n = 0; n < s.tags.size(); ++n)
            s.tags[n].head<2>() = params_.track.pointAt(queries[n].s, s.lateral).position;
        lateral = &s.lateral;
    }

    // Robust pass: readings with gross errors must not pull the beacons.
    ceres::HuberLoss huber(params_.huberScale / params_.rangeNoise);
    auto [it1, ok1] =
        solveBundle(s.epochs, {&s.beacons, &s.height, &s.tags, lateral}, guess, params_, &huber, heightFree);
    progress.report(0.4, QStringLiteral("outlier test"));
    if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));

    // Outlier test on every reading's residual (Grubbs [Grub 69] or MAD), then drop thin fixes.
    std::vector<double> residuals;
    for (std::size_t n = 0; n < s.epochs.size(); ++n) {
        const Vector3 m(s.tags[n].x(), s.tags[n].y(), s.height);
        for (const auto& r : s.epochs[n].readings) {
            const Vector3& b = s.beacons.positions[size_t(r.beacon)];
            residuals.push_back((m - b).norm() - (s.beacons.reference - b).norm() - kSpeedOfLight * r.dt -
                                s.tags[n].z());
        }
    }
    std::vector<bool> outlier;
    if (params_.outlierTest == OutlierTest::Grubbs) {
        outlier = grubbsOutliers(residuals, params_.alpha, int(residuals.size() / 5));
    } else {
        const double centre = math::median(residuals);
        const double cut = params_.madK * 1.4826 * medianAbsoluteDeviation(residuals);
        for (double e : residuals) outlier.push_back(std::abs(e - centre) > cut);
    }
    std::vector<TdoaEpoch> kept;
    std::vector<Vector3> keptTags;
    std::size_t k = 0;
    for (std::size_t n = 0; n < s.epochs.size(); ++n) {
        TdoaEpoch e{s.epochs[n].t, {}};
        for (const auto& r : s.epochs[n].readings) {
            if (outlier[k++])
                ++s.readingsRemoved;
            else
                e.readings.push_back(r);
        }
        if (int(e.readings.size()) < params_.minBeacons) {
            ++s.fixesRemoved;
            continue;
        }
        kept.push_back(std::move(e));
        keptTags.push_back(s.tags[n]);
    }
    s.epochs = std::move(kept);
    s.tags = std::move(keptTags);
    if (s.epochs.size() < 10)
        return makeError(QStringLiteral("calibration: only %1 fixes left after the outlier test; record a longer walk")
                             .arg(s.epochs.size()));

    // Least-squares pass to convergence (stopping rule: nRMSR improves by < 0.01 %).
    Params last = params_;
    last.relativeTolerance = std::min(params_.relativeTolerance, params_.finalTolerance);
    auto [it2, ok2] =
        solveBundle(s.epochs, {&s.beacons, &s.height, &s.tags, lateral}, guess, last, nullptr, heightFree);
    s.iterations = it1 + it2;
    s.converged = ok2;

    // Mirror test (see header): a planar walk cannot tell a beacon at height z from its reflection
    // 2h − z in the walk plane except through the one distance |r − b_i| to the reference node, so
    // the adjustment can stop in the reflected minimum when the guess is on the wrong side (σz ≥ the
    // beacon's height above the walk). Each beacon in turn is reflected and the adjustment re-run;
    // the reflection is kept when it lowers nRMSR (data only, the prior is not part of it).
    s.nrmsr = nrmsr(s.epochs, s.beacons, s.height, params_.minBeacons);
    if (params_.beaconsAboveWalk) {
        // Height plausibility: beacons are mounted above the walking tag; one found below the walk
        // plane sits in the reflected minimum and is reflected back, then the adjustment re-run.
        for (int round = 0; round < 3; ++round) {
            bool changed = false;
            for (auto& b : s.beacons.positions)
                if (b.z() < s.height + params_.minBeaconClearance) {
                    b.z() = std::max(2.0 * s.height - b.z(), s.height + params_.minBeaconClearance);
                    changed = true;
                    ++s.mirrored;
                }
            if (!changed) break;
            auto [it, ok] = solveBundle(s.epochs, {&s.beacons, &s.height, &s.tags, onTrack ? &s.lateral : nullptr},
                                        guess, last, nullptr, heightFree);
            s.iterations += it;
            s.converged = ok;
        }
        s.nrmsr = nrmsr(s.epochs, s.beacons, s.height, params_.minBeacons);
    } else if (params_.mirrorTest) {
        for (int round = 0; round < 2; ++round) {
            bool changed = false;
            for (int i = 0; i < s.beacons.size(); ++i) {
                if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
                Start c = s;
                Vector3& b = c.beacons.positions[size_t(i)];
                b.z() = 2.0 * c.height - b.z();
                auto [it, ok] = solveBundle(c.epochs, {&c.beacons, &c.height, &c.tags, onTrack ? &c.lateral : nullptr},
                                            guess, params_, nullptr, heightFree);
                c.iterations += it;
                c.converged = ok;
                c.nrmsr = nrmsr(c.epochs, c.beacons, c.height, params_.minBeacons);
                if (c.nrmsr < s.nrmsr * (1.0 - params_.mirrorMinGain)) {
                    s = std::move(c);
                    ++s.mirrored;
                    changed = true;
                }
            }
            if (!changed) break;
        }
    }

    // Gauge: rotate about r's vertical axis onto the guess (see header).
    const double yaw = fitYawAboutPivot(s.beacons.positions, guess.positions, s.beacons.reference);
    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(yaw, Vector3::UnitZ()).toRotationMatrix();
    for (auto& b : s.beacons.positions) b = s.beacons.reference + rotation * (b - s.beacons.reference);
    s.nrmsr = nrmsr(s.epochs, s.beacons, s.height, params_.minBeacons);
    progress.report(1.0);
    return s;
}

double LpsCalibration::trackLineShare(const std::vector<Vector3>& tags, double lateral) const {
    if (tags.empty()) return 0.0;
    int on = 0;
    for (const auto& tag : tags)
        on += std::abs(params_.track.query(tag.head<2>()).d - lateral) <= 3.0 * params_.trackSigma;
    return double(on) / double(tags.size());
}

double LpsCalibration::guessRotationSigma(const BeaconLayout& beacons, double sigmaXy) {
    double sum = 0.0;
    for (const auto& b : beacons.positions) sum += (b - beacons.reference).head<2>().squaredNorm();
    return sum > 0.0 ? sigmaXy / std::sqrt(sum) : std::numeric_limits<double>::infinity();
}

const char* LpsCalibration::gaugeName(Gauge gauge) {
    switch (gauge) {
        case Gauge::Auto:
            return "auto";
        case Gauge::Guess:
            return "guess";
        case Gauge::Track:
            return "track";
    }
    return "?";
}

// Track gauge (header, TrackGauge.h): the whole walk re-solved with the calibrated beacons (IRLS),
// fitted to a line parallel to the track; the beacons are rotated about r when the fit is accepted.
Expected<LpsCalibration::GaugeReport> LpsCalibration::applyGauge(const std::vector<TdoaEpoch>& epochs, double height,
                                                                 BeaconLayout& beacons, double guessSigmaXy) const {
    GaugeReport g;
    g.requested = params_.gauge;
    // The guess' σ: stated (gaugeGuessSigma), else the prior's as widened by adaptPrior.
    g.sigmaGuess = guessRotationSigma(beacons, std::isfinite(params_.gaugeGuessSigma)
                                                   ? params_.gaugeGuessSigma
                                                   : std::max(params_.priorSigmaXy, guessSigmaXy));
    if (params_.gauge == Gauge::Guess) {
        g.reason = QStringLiteral("gauge=guess: rotation from the initial beacon table");
        return g;
    }
    std::vector<Vector3> walk;
    {
        TdoaSolver solver = planarSolver(height);
        BeaconSelection irls;
        const auto refDist = referenceDistances(beacons);
        FixInput input;
        const TagFix* previous = nullptr;
        TagFix last;
        for (const auto& e : epochs) {
            if (usableReadings(e) < params_.minBeacons) continue;
            input.assign(e, beacons, refDist);
            const TagFix fix = irls.solve(input, solver, previous);
            if (!fix.valid) continue;
            walk.push_back(fix.position);
            last = fix;
            previous = &last;
        }
    }
    g.fit = fitTrackGauge(walk, beacons.reference, params_.track);
    const TrackGaugeFit& f = g.fit;
    QStringList failed;
    if (!f.valid) {
        failed << QStringLiteral("the track fit is undetermined (%1 fixes)").arg(f.points);
    } else {
        if (f.rms > params_.gaugeMaxRms)
            failed << QStringLiteral("fit RMS %1 m > %2 m").arg(f.rms, 0, 'f', 3).arg(params_.gaugeMaxRms);
        if (f.inlierShare < params_.gaugeMinInliers)
            failed << QStringLiteral("only %1 % of the walk on the track line").arg(100.0 * f.inlierShare, 0, 'f', 0);
        if (f.coverage < params_.gaugeMinCoverage)
            failed << QStringLiteral("walk covers %1 % of the lap < %2 %")
                          .arg(100.0 * f.coverage, 0, 'f', 0)
                          .arg(100.0 * params_.gaugeMinCoverage, 0, 'f', 0);
        if (!f.bothBends) failed << QStringLiteral("walk does not cover both bends");
        const double tolerance = params_.gaugeAgreementSigmas * std::hypot(g.sigmaGuess, f.sigmaRotation);
        if (std::abs(f.rotation) > tolerance)
            failed << QStringLiteral("track rotation %1 mrad disagrees with the guess (tolerance %2 mrad)")
                          .arg(1e3 * f.rotation, 0, 'f', 2)
                          .arg(1e3 * tolerance, 0, 'f', 2);
    }
    if (params_.gauge == Gauge::Track) {
        if (!f.valid)
            return makeError(QStringLiteral("gauge=track: %1; use gauge=auto or gauge=guess")
                                 .arg(failed.join(QStringLiteral("; "))));
        g.used = Gauge::Track;
        g.reason = failed.isEmpty()
                       ? QStringLiteral("gauge=track: rotation from the track fit")
                       : QStringLiteral("gauge=track (forced) although %1").arg(failed.join(QStringLiteral("; ")));
    } else if (failed.isEmpty()) {
        g.used = Gauge::Track;
        g.reason = QStringLiteral("auto: walk follows the track; rotation from the track fit");
    } else {
        g.used = Gauge::Guess;
        g.reason = QStringLiteral("auto: kept the guess-based rotation: %1").arg(failed.join(QStringLiteral("; ")));
    }
    if (g.used == Gauge::Track) {
        g.rotation = f.rotation;
        rotateLayout(beacons, f.rotation);
    }
    return g;
}

Expected<LpsCalibration::Result> LpsCalibration::run(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& initial,
                                                     const Progress& progress, const BeaconLayout* reference) const {
    const double h0 = std::isfinite(params_.walkHeight) ? params_.walkHeight : params_.walkHeightPrior;
    // Steps 3–4: fixes with the initial beacons, Grubbs on their residuals, spread selection.
    std::vector<TdoaEpoch> candidates;
    std::vector<Vector3> positions;
    std::vector<double> rms;
    {
        TdoaSolver solver = planarSolver(h0);
        const auto refDist = referenceDistances(initial);
        FixInput input;
        for (const auto& e : epochs) {
            if (usableReadings(e) < params_.minBeacons) continue;
            input.assign(e, initial, refDist);
            const TagFix fix = solver.solve(input);
            if (!fix.valid) continue;
            candidates.push_back(e);
            positions.push_back(fix.position);
            rms.push_back(fix.rmsResidual);
        }
    }
    // Geometry of the guess (BeaconGeometry.h): e.g. 4 anchors inside a 2 m box cannot be calibrated
    // from a walk around a track (checked first: its fixes fail too, which would hide the reason).
    const BeaconGeometryReport guessGeometry = assessBeaconGeometry(initial.positions, positions, params_.geometry);
    if (!guessGeometry.observable2d() && params_.geometryCheck == GeometryCheck::Refuse)
        return makeError(QStringLiteral("calibration refused: the initial beacon table's geometry makes the walk's "
                                        "positions unobservable: %1 (geometry_check=warn to calibrate anyway)")
                             .arg(guessGeometry.reason()));
    if (candidates.size() < 20)
        return makeError(
            QStringLiteral("calibration needs at least 20 instants with %1 or more beacons; the walk has %2")
                .arg(params_.minBeacons)
                .arg(candidates.size()));
    const std::vector<bool> badFix = grubbsOutliers(rms, params_.alpha, int(rms.size() / 5));
    std::vector<TdoaEpoch> clean;
    std::vector<Vector3> cleanPositions;
    for (std::size_t n = 0; n < candidates.size(); ++n) {
        if (badFix[n]) continue;
        clean.push_back(candidates[n]);
        cleanPositions.push_back(positions[n]);
    }
    std::vector<TdoaEpoch> selected;
    for (int i : spreadSelection(cleanPositions, params_.calibrationFixes)) selected.push_back(clean[size_t(i)]);

    // Steps 5–8 with multi-start.
    std::mt19937_64 rng(params_.seed);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::optional<Start> best;
    int starts = 0;
    Params effective = params_;  // the prior is widened when the first start finds a poor guess
    bool poorGuess = false;
    bool onTrack = false;
    double trackShare = std::numeric_limits<double>::quiet_NaN();
    const bool useTrack = params_.trackConstraint && params_.gauge != Gauge::Guess;
    const int total = std::max(1, params_.maxStarts) + (useTrack ? 1 : 0);
    const double span = 1.0 / total;
    for (int s = 0; s < total; ++s) {
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        const Progress sub = progress.sub(s * span, (s + 1) * span);
        // Start 0: from the guess, free tags. Start 1 (trackConstraint): from the guess with the tags
        // on the track line. Further starts: re-perturbed (around the best solution once the guess
        // proved poor: a start re-perturbed from a guess metres off lands in another wrong minimum).
        const bool trackStart = useTrack && s == 1;
        BeaconLayout start = poorGuess && best && !trackStart ? best->beacons : initial;
        if (s > 0 && !trackStart)
            for (auto& p : start.positions)
                p += Vector3(params_.restartSigmaXy * normal(rng), params_.restartSigmaXy * normal(rng),
                             params_.restartSigmaZ * normal(rng));
        auto result = LpsCalibration(effective).adjust(selected, start, initial, sub, trackStart || onTrack);
        ++starts;
        if (s == 0 && result && params_.adaptPrior) {
            // Empirical prior (see header): the horizontal shifts from the guess measure the guess'
            // real error; a prior much tighter than that would pull the weakly observable heights
            // towards wrong guesses. Re-run the first start with the prior widened to it.
            double sum = 0.0;
            for (int i = 0; i < initial.size(); ++i)
                sum += (result->beacons.positions[size_t(i)] - initial.positions[size_t(i)]).head<2>().squaredNorm();
            const double sigma = std::sqrt(sum / (2.0 * std::max(1, initial.size())));
            if (sigma > params_.adaptPriorFactor * params_.priorSigmaXy) {
                poorGuess = true;
                effective.priorSigmaZ = params_.priorSigmaZ * sigma / params_.priorSigmaXy;
                effective.priorSigmaXy = sigma;
                if (auto again = LpsCalibration(effective).adjust(selected, start, initial, sub, false); again)
                    result = std::move(again);
            }
        }
        if (!result) {
            if (result.message() == QLatin1String("cancelled")) return result.error();
            if (s == 0 && total <= 1) return result.error();
            continue;
        }
        result->priorSigmaXy = effective.priorSigmaXy;
        if (trackStart) {
            // The track-constrained solution replaces the free one when its walk really lies on a
            // line parallel to the track (the free minimum's nRMSR can be as low while its geometry
            // is wrong); afterwards restarts keep the constraint.
            trackShare = trackLineShare(result->tags, result->lateral);
            if (trackShare >= params_.gaugeMinInliers) {
                onTrack = true;
                best = std::move(*result);
            }
            if (!poorGuess && best && best->nrmsr <= params_.restartNrmsr) break;
            continue;
        }
        if (!best || result->nrmsr < best->nrmsr) best = std::move(*result);
        if (!poorGuess && !(useTrack && s == 0) && best->nrmsr <= params_.restartNrmsr) break;
    }
    if (!best)
        return makeError(QStringLiteral("calibration failed from every start; check the beacon table and the walk"));

    Result out;
    out.beacons = best->beacons;
    Report& report = out.report;
    if (auto gauge = applyGauge(epochs, best->height, out.beacons, best->priorSigmaXy); gauge)
        report.gauge = std::move(*gauge);
    else
        return gauge.error();
    // Geometry of the result, with the walk re-solved as the area.
    {
        std::vector<Vector3> area;
        for (const auto& tag : best->tags) area.emplace_back(tag.x(), tag.y(), best->height);
        report.geometry = assessBeaconGeometry(out.beacons.positions, area, params_.geometry);
        if (!report.geometry.observable2d() && params_.geometryCheck == GeometryCheck::Refuse)
            return makeError(
                QStringLiteral("calibration refused: the calibrated beacons' geometry is not observable: %1 "
                               "(geometry_check=warn to keep it)")
                    .arg(report.geometry.reason()));
        QStringList warnings;
        if (!guessGeometry.observable2d()) warnings << QStringLiteral("initial table: %1").arg(guessGeometry.reason());
        if (!report.geometry.problems.isEmpty()) warnings << report.geometry.reason();
        report.geometryWarning = warnings.join(QStringLiteral("; "));
    }
    report.nrmsrCalibrated = best->nrmsr;
    report.nrmsrInitial = nrmsr(best->epochs, initial, h0, params_.minBeacons);
    if (reference) report.nrmsrReference = nrmsr(best->epochs, *reference, best->height, params_.minBeacons);
    report.epochs = int(epochs.size());
    report.fixesUsed = int(best->epochs.size());
    report.fixesRemoved = int(candidates.size() - clean.size()) + best->fixesRemoved;
    report.readingsRemoved = best->readingsRemoved;
    report.starts = starts;
    report.priorSigmaXy = best->priorSigmaXy;
    report.poorGuess = poorGuess;
    report.mirrored = best->mirrored;
    report.trackConstrained = onTrack;
    report.trackShare = trackShare;
    report.iterations = best->iterations;
    report.walkHeight = best->height;
    report.converged = best->converged;

    // Residual per beacon over the calibration fixes, re-solved with the calibrated beacons.
    report.beacons.assign(size_t(out.beacons.size()), {});
    std::vector<double> sumSq(size_t(out.beacons.size()), 0.0);
    TdoaSolver solver = planarSolver(best->height);
    const auto refDist = referenceDistances(out.beacons);
    FixInput input;
    std::vector<double> e;
    for (const auto& epoch : best->epochs) {
        input.assign(epoch, out.beacons, refDist);
        const TagFix fix = solver.solve(input);
        if (!fix.valid) continue;
        TdoaSolver::residuals(input, fix.position, fix.offset, e);
        for (int k = 0; k < input.size(); ++k) {
            sumSq[size_t(input.index[size_t(k)])] += e[size_t(k)] * e[size_t(k)];
            ++report.beacons[size_t(input.index[size_t(k)])].readings;
        }
    }
    for (int i = 0; i < out.beacons.size(); ++i) {
        auto& b = report.beacons[size_t(i)];
        b.rmsResidual =
            b.readings ? std::sqrt(sumSq[size_t(i)] / b.readings) : std::numeric_limits<double>::quiet_NaN();
        b.shift = (out.beacons.positions[size_t(i)] - initial.positions[size_t(i)]).norm();
    }
    return out;
}

}  // namespace athlos::lps
