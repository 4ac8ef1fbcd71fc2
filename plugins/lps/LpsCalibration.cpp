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
                                                       const BeaconLayout& guess, const Progress& progress) const {
    const bool heightFree = !std::isfinite(params_.walkHeight);
    Start s;
    s.beacons = start;
    s.height = heightFree ? params_.walkHeightPrior : params_.walkHeight;
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

    // Robust pass: readings with gross errors must not pull the beacons.
    ceres::HuberLoss huber(params_.huberScale / params_.rangeNoise);
    auto [it1, ok1] = solveBundle(s.epochs, {&s.beacons, &s.height, &s.tags}, guess, params_, &huber, heightFree);
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
    auto [it2, ok2] = solveBundle(s.epochs, {&s.beacons, &s.height, &s.tags}, guess, params_, nullptr, heightFree);
    s.iterations = it1 + it2;
    s.converged = ok2;

    // Gauge: rotate about r's vertical axis onto the guess (see header).
    const double yaw = fitYawAboutPivot(s.beacons.positions, guess.positions, s.beacons.reference);
    const Eigen::Matrix3d rotation = Eigen::AngleAxisd(yaw, Vector3::UnitZ()).toRotationMatrix();
    for (auto& b : s.beacons.positions) b = s.beacons.reference + rotation * (b - s.beacons.reference);
    s.nrmsr = nrmsr(s.epochs, s.beacons, s.height, params_.minBeacons);
    progress.report(1.0);
    return s;
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
                                                                 BeaconLayout& beacons) const {
    GaugeReport g;
    g.requested = params_.gauge;
    g.sigmaGuess = guessRotationSigma(
        beacons, std::isfinite(params_.gaugeGuessSigma) ? params_.gaugeGuessSigma : params_.priorSigmaXy);
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
    for (int s = 0; s < std::max(1, params_.maxStarts); ++s) {
        if (progress.isCancelled()) return makeError(QStringLiteral("cancelled"));
        BeaconLayout start = initial;
        if (s > 0)
            for (auto& p : start.positions)
                p += Vector3(params_.restartSigmaXy * normal(rng), params_.restartSigmaXy * normal(rng),
                             params_.restartSigmaZ * normal(rng));
        const double span = 1.0 / std::max(1, params_.maxStarts);
        auto result = adjust(selected, start, initial, progress.sub(s * span, (s + 1) * span));
        ++starts;
        if (!result) {
            if (result.message() == QLatin1String("cancelled")) return result.error();
            if (s == 0 && params_.maxStarts <= 1) return result.error();
            continue;
        }
        if (!best || result->nrmsr < best->nrmsr) best = std::move(*result);
        if (best->nrmsr <= params_.restartNrmsr) break;
    }
    if (!best)
        return makeError(QStringLiteral("calibration failed from every start; check the beacon table and the walk"));

    Result out;
    out.beacons = best->beacons;
    Report& report = out.report;
    if (auto gauge = applyGauge(epochs, best->height, out.beacons); gauge)
        report.gauge = std::move(*gauge);
    else
        return gauge.error();
    report.nrmsrCalibrated = best->nrmsr;
    report.nrmsrInitial = nrmsr(best->epochs, initial, h0, params_.minBeacons);
    if (reference) report.nrmsrReference = nrmsr(best->epochs, *reference, best->height, params_.minBeacons);
    report.epochs = int(epochs.size());
    report.fixesUsed = int(best->epochs.size());
    report.fixesRemoved = int(candidates.size() - clean.size()) + best->fixesRemoved;
    report.readingsRemoved = best->readingsRemoved;
    report.starts = starts;
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
