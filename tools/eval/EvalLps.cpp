// athlos-eval-lps: simulation study in the spirit of thesis Figs. 3.6–3.9 (calibration) and 3.16
// (beacon selection under NLOS). Prints Markdown tables for docs/validation/lps.md.
//   athlos-eval-lps [--quick] [--runs N] [--nlos-runs N] [--seed S] [--grid kappa|gate|rejection=FROM:TO:STEP]
#include "plugins/lps/BeaconSelection.h"
#include "plugins/lps/FrameAlignment.h"
#include "plugins/lps/LpsCalibration.h"
#include "plugins/lps/RobustStatistics.h"
#include "plugins/lps/TdoaPositioning.h"
#include "plugins/lps/TdoaScreening.h"
#include "plugins/lps/TdoaSimulator.h"
#include "plugins/lps/TrackGauge.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

using namespace athlos;
using namespace athlos::lps;

namespace {

constexpr double kWalkHeight = 1.0, kRunHeight = 1.2;

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const double x = p / 100.0 * double(v.size() - 1);
    const auto lo = std::size_t(std::floor(x));
    const auto hi = std::min(v.size() - 1, lo + 1);
    return v[lo] + (x - double(lo)) * (v[hi] - v[lo]);
}

double mean(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x;
    return v.empty() ? NAN : s / double(v.size());
}

// Horizontal RMSE of the valid fixes against the truth samples of the same epochs.
double tagRmse(const std::vector<TagFix>& fixes, const std::vector<TrajectorySample>& truth) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t k = 0; k < fixes.size(); ++k) {
        if (!fixes[k].valid) continue;
        sum += (fixes[k].position - truth[k].position).head<2>().squaredNorm();
        ++n;
    }
    return n ? std::sqrt(sum / n) : NAN;
}

// A selection set-up of Fig. 3.16 and the parameter a grid search varies (--grid).
struct SelectionSetup {
    BeaconSelection::Method method = BeaconSelection::Method::All;
    TdoaScreening::Method screening = TdoaScreening::Method::None;
    double kappa = BeaconSelection::Params().kappa;
    double gate = TdoaScreening::Params().gate;
    double rejection = BeaconSelection::Params().rejectionThreshold;
};

std::vector<TagFix> position(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& beacons,
                             const SelectionSetup& setup, double height) {
    TdoaPositioning::Params p;
    p.solver.tagHeight = height;
    p.selection.method = setup.method;
    p.selection.kappa = setup.kappa;
    p.selection.rejectionThreshold = setup.rejection;
    p.screening.method = setup.screening;
    p.screening.gate = setup.gate;
    TdoaPositioning positioning(p, beacons);
    return *positioning.run(epochs);
}

std::vector<TagFix> position(const std::vector<TdoaEpoch>& epochs, const BeaconLayout& beacons,
                             BeaconSelection::Method method, double height) {
    SelectionSetup setup;
    setup.method = method;
    return position(epochs, beacons, setup, height);
}

struct CalibrationRun {
    double etaInitial, etaCalibrated, beaconRmse, tagRmseSurveyed, tagRmseCalibrated, seconds;
    double tagRmseGuessGauge;  // the same calibration with the guess-based gauge (gauge=guess)
    bool trackGauge;           // gauge=auto accepted the track rotation
    double gaugeError;         // rad, remaining rotation about the reference node vs. the truth
};

CalibrationRun calibrationRun(std::uint64_t seed, const Perturbation& level) {
    const TrackGeometry track = TrackGeometry::iaaf400m();
    TdoaSimulator sim(TdoaSimulator::Params(), seed);
    const BeaconLayout surveyed = sim.venue(VenueParams(), track);
    const BeaconLayout guess = sim.perturb(surveyed, level);
    const auto walk = sim.measure(TdoaSimulator::laps(track, 0.3, 1.4, 1.0, 1.0, kWalkHeight), surveyed);
    const double lane = track.laneOffset(1 + int(seed % 8));
    const auto testTrajectory = TdoaSimulator::laps(track, lane, 6.0, 10.0, 1.0, kRunHeight, 1000.0);
    const auto test = sim.measure(testTrajectory, surveyed);
    // η uses the same run without the 1 % gross outliers: they would dominate every nRMSR.
    TdoaSimulator::Params cleanParams;
    cleanParams.outlierRate = 0.0;
    const auto clean = TdoaSimulator(cleanParams, seed + 17).measure(testTrajectory, surveyed);

    const auto t0 = std::chrono::steady_clock::now();
    LpsCalibration::Params params;
    params.seed = seed;
    // The user states how good the guess is (the bundle prior stays at its 2 m default).
    params.gaugeGuessSigma = level.sigmaXy;
    auto result = LpsCalibration(params).run(walk.epochs, guess);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const BeaconLayout calibrated = result ? result->beacons : guess;
    // gauge=guess is the same bundle adjustment without the track rotation: undo it.
    BeaconLayout guessGauge = calibrated;
    if (result) rotateLayout(guessGauge, -result->report.gauge.rotation);

    // η on the test set (thesis: only test-set results are shown), all fixes at the run height.
    const double ref = LpsCalibration::nrmsr(clean.epochs, surveyed, kRunHeight);
    CalibrationRun run;
    run.etaInitial = LpsCalibration::nrmsr(clean.epochs, guess, kRunHeight) / ref;
    run.etaCalibrated = LpsCalibration::nrmsr(clean.epochs, calibrated, kRunHeight) / ref;
    run.beaconRmse = alignedRmse(calibrated.positions, surveyed.positions);
    run.tagRmseSurveyed =
        tagRmse(position(test.epochs, surveyed, BeaconSelection::Method::Irls, kRunHeight), test.truth);
    run.tagRmseCalibrated =
        tagRmse(position(test.epochs, calibrated, BeaconSelection::Method::Irls, kRunHeight), test.truth);
    run.tagRmseGuessGauge =
        tagRmse(position(test.epochs, guessGauge, BeaconSelection::Method::Irls, kRunHeight), test.truth);
    run.trackGauge = result && result->report.gauge.used == LpsCalibration::Gauge::Track;
    run.gaugeError = fitYawAboutPivot(calibrated.positions, surveyed.positions, surveyed.reference);
    run.seconds = seconds;
    if (std::getenv("LPS_EVAL_VERBOSE") && result)
        std::fprintf(stderr,
                     "seed %llu: surveyed %.3f auto %.3f guess %.3f | %s | theta %.2f mrad, residual yaw %.2f mrad, "
                     "rms %.3f, coverage %.2f, inliers %.2f\n",
                     static_cast<unsigned long long>(seed), run.tagRmseSurveyed, run.tagRmseCalibrated,
                     run.tagRmseGuessGauge, qPrintable(result->report.gauge.reason),
                     1e3 * result->report.gauge.fit.rotation, 1e3 * run.gaugeError, result->report.gauge.fit.rms,
                     result->report.gauge.fit.coverage, result->report.gauge.fit.inlierShare);
    return run;
}

void calibrationStudy(int runs, std::uint64_t seed, bool quick, const std::vector<int>& only) {
    std::printf("## Calibration (Figs. 3.6–3.9): %d runs per perturbation level\n\n", runs);
    std::printf(
        "| σxy / σz (m) | share η_calib < 1 | η_ini median | η_calib median | η_calib p90 | beacon RMSE median / p90 "
        "(m) "
        "| tag RMSE surveyed (m) | tag RMSE calibrated (m) | Δ median / max (m) | share Δ ≤ 0.10 m "
        "| gauge=guess: Δ median / max (m) | gauge=guess: share Δ ≤ 0.10 m | track gauge used | |yaw error| median / "
        "max (mrad) "
        "| s per calibration |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    const auto& levels = thesisPerturbations();
    const std::size_t count = quick ? 3 : levels.size();
    for (std::size_t l = 0; l < count; ++l) {
        if (!only.empty() && std::find(only.begin(), only.end(), int(l)) == only.end()) continue;
        std::vector<double> etaI, etaC, bRmse, tS, tC, delta, deltaGuess, yaw, secs;
        int below = 0, within = 0, withinGuess = 0, track = 0;
        for (int r = 0; r < runs; ++r) {
            const auto run = calibrationRun(seed + 1000 * l + std::uint64_t(r), levels[l]);
            etaI.push_back(run.etaInitial);
            etaC.push_back(run.etaCalibrated);
            below += run.etaCalibrated < 1.0;
            bRmse.push_back(run.beaconRmse);
            tS.push_back(run.tagRmseSurveyed);
            tC.push_back(run.tagRmseCalibrated);
            delta.push_back(run.tagRmseCalibrated - run.tagRmseSurveyed);
            within += delta.back() <= 0.10;
            deltaGuess.push_back(run.tagRmseGuessGauge - run.tagRmseSurveyed);
            withinGuess += deltaGuess.back() <= 0.10;
            track += run.trackGauge;
            yaw.push_back(1e3 * std::abs(run.gaugeError));
            secs.push_back(run.seconds);
        }
        std::printf(
            "| %g / %g | %.0f %% | %.2f | %.3f | %.3f | %.3f / %.3f | %.3f | %.3f | %+.3f / %+.3f | %.0f %% "
            "| %+.3f / %+.3f | %.0f %% | %d / %d | %.2f / %.2f | %.2f |\n",
            levels[l].sigmaXy, levels[l].sigmaZ, 100.0 * below / runs, percentile(etaI, 50), percentile(etaC, 50),
            percentile(etaC, 90), percentile(bRmse, 50), percentile(bRmse, 90), percentile(tS, 50), percentile(tC, 50),
            percentile(delta, 50), *std::max_element(delta.begin(), delta.end()), 100.0 * within / runs,
            percentile(deltaGuess, 50), *std::max_element(deltaGuess.begin(), deltaGuess.end()),
            100.0 * withinGuess / runs, track, runs, percentile(yaw, 50), *std::max_element(yaw.begin(), yaw.end()),
            mean(secs));
        std::fflush(stdout);
    }
    std::printf("\n");
}

// One simulated run of the selection study (body-shadowing NLOS, thesis Fig. 3.16 set-up).
struct NlosRun {
    BeaconLayout beacons;
    TdoaSimulator::Recording run;
};

NlosRun nlosRun(int r, std::uint64_t seed, bool grossOutliers) {
    const TrackGeometry track = TrackGeometry::iaaf400m();
    TdoaSimulator::Params simParams;
    simParams.bodyShadowing = true;
    simParams.outlierRate = grossOutliers ? 0.01 : 0.0;
    TdoaSimulator sim(simParams, seed + std::uint64_t(r));
    NlosRun out;
    out.beacons = sim.venue(VenueParams(), track);
    const double lane = track.laneOffset(1 + r % 8);
    const double speed = 5.0 + 2.0 * (r % 3) / 2.0;
    out.run = sim.measure(TdoaSimulator::laps(track, lane, speed, 10.0, r % 2 ? 2.0 : 1.0, kRunHeight), out.beacons);
    return out;
}

void selectionStudy(int runs, std::uint64_t seed, bool grossOutliers) {
    std::printf("## Beacon selection under body-shadowing NLOS (Fig. 3.16): %d runs, %s\n\n", runs,
                grossOutliers ? "plus 1 % gross outliers of 20 m" : "NLOS and 0.1 m noise only");
    struct Method {
        const char* name;
        SelectionSetup setup;
    };
    using M = BeaconSelection::Method;
    using S = TdoaScreening::Method;
    const std::vector<Method> methods = {{"(1) all beacons", {M::All}},
                                         {"(2) Grubbs test on the TDoA rate", {M::All, S::GrubbsRate}},
                                         {"(3) Kalman-gated TDoA", {M::All, S::KalmanGate}},
                                         {"(4) all-subset weighting (Cong & Zhuang, ≤ 3 NLOS)", {M::AllSubsets}},
                                         {"(5) best 5-subset", {M::BestSubset}},
                                         {"(6) IRLS bisquare (2.5·MAD)", {M::Irls}},
                                         {"(8) largest-residual rejection", {M::LargestResidual}},
                                         {"(9) field of view (proposed)", {M::FieldOfView}}};
    std::vector<std::vector<double>> rmse(methods.size() + 1);
    std::vector<double> seconds(methods.size(), 0.0);
    for (int r = 0; r < runs; ++r) {
        const NlosRun sim = nlosRun(r, seed, grossOutliers);
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const auto t0 = std::chrono::steady_clock::now();
            rmse[m].push_back(
                tagRmse(position(sim.run.epochs, sim.beacons, methods[m].setup, kRunHeight), sim.run.truth));
            seconds[m] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        }
        // Oracle (method 10's spirit): the simulator's NLOS flags decide.
        TdoaSolver solver;
        const auto refDist = referenceDistances(sim.beacons);
        FixInput input;
        std::vector<TagFix> fixes;
        for (std::size_t k = 0; k < sim.run.epochs.size(); ++k) {
            input.assign(sim.run.epochs[k], sim.beacons, refDist);
            for (int i = 0; i < input.size(); ++i) input.weights[size_t(i)] = sim.run.nlos[k][size_t(i)] ? 0.0 : 1.0;
            if (input.activeCount() < 4) input.setAllWeights(1.0);
            fixes.push_back(solver.solve(input, fixes.empty() ? nullptr : &fixes.back()));
        }
        rmse.back().push_back(tagRmse(fixes, sim.run.truth));
    }
    std::printf(
        "| method | median RMSE (m) | mean RMSE (m) | p90 RMSE (m) | CPU per run (s) |\n|---|---|---|---|---|\n");
    for (std::size_t m = 0; m <= methods.size(); ++m)
        std::printf("| %s | %.3f | %.3f | %.3f | %s |\n",
                    m < methods.size() ? methods[m].name : "(10) oracle (simulator's NLOS flags)",
                    percentile(rmse[m], 50), mean(rmse[m]), percentile(rmse[m], 90),
                    m < methods.size() ? QByteArray::number(seconds[m] / runs, 'f', 3).constData() : "—");
    std::printf("\n");
    std::fflush(stdout);
}

// Grid search of one selection parameter on the tuning seed (thesis: κ over 10…60 step 0.5 and the
// thresholds of methods 3 and 8), both NLOS rows: median RMSE per value, the best marked.
int gridSearch(const QString& spec, int runs, std::uint64_t seed) {
    const QStringList nameRange = spec.split(QLatin1Char('='));
    const QStringList range = nameRange.size() == 2 ? nameRange[1].split(QLatin1Char(':')) : QStringList();
    const QString name = nameRange.value(0);
    bool ok0 = false, ok1 = false, ok2 = false;
    const double from = range.value(0).toDouble(&ok0), to = range.value(1).toDouble(&ok1),
                 step = range.value(2).toDouble(&ok2);
    if (!ok0 || !ok1 || !ok2 || !(step > 0) || to < from ||
        !(name == u"kappa" || name == u"gate" || name == u"rejection")) {
        std::fprintf(stderr, "--grid: expected kappa|gate|rejection=FROM:TO:STEP, got '%s'\n", qPrintable(spec));
        return 2;
    }
    std::printf(
        "## Grid search of %s on seed %llu (%d runs per row)\n\n| %s | median RMSE, NLOS (m) | median RMSE, "
        "NLOS + 1 %% outliers (m) |\n|---|---|---|\n",
        qPrintable(name), static_cast<unsigned long long>(seed), runs, qPrintable(name));
    std::vector<NlosRun> sims[2];
    for (int row = 0; row < 2; ++row)
        for (int r = 0; r < runs; ++r) sims[row].push_back(nlosRun(r, seed, row == 1));
    double bestValue = from, bestScore = INFINITY;
    for (double v = from; v <= to + 1e-9 * step; v += step) {
        SelectionSetup setup;
        if (name == u"kappa") {
            setup.method = BeaconSelection::Method::FieldOfView;
            setup.kappa = v;
        } else if (name == u"gate") {
            setup.screening = TdoaScreening::Method::KalmanGate;
            setup.gate = v;
        } else {
            setup.method = BeaconSelection::Method::LargestResidual;
            setup.rejection = v;
        }
        double med[2];
        for (int row = 0; row < 2; ++row) {
            std::vector<double> e;
            for (const NlosRun& s : sims[row])
                e.push_back(tagRmse(position(s.run.epochs, s.beacons, setup, kRunHeight), s.run.truth));
            med[row] = percentile(e, 50);
        }
        std::printf("| %g | %.3f | %.3f |\n", v, med[0], med[1]);
        std::fflush(stdout);
        if (med[0] + med[1] < bestScore) {
            bestScore = med[0] + med[1];
            bestValue = v;
        }
    }
    std::printf("\nbest %s = %g (lowest sum of the two medians)\n", qPrintable(name), bestValue);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    bool quick = false;
    int runs = 25, nlosRuns = 34;  // 34 runs as in the thesis' selection study
    std::uint64_t seed = 20170101;
    bool calibration = true, selection = true;
    std::vector<int> levels;  // --levels 4,6: only these perturbation levels (0-based, Table 3.2 order)
    QString grid;             // --grid kappa=95:106:0.5: grid search on the tuning seed instead of the studies
    bool seedGiven = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--quick")
            quick = true;
        else if (a == "--runs" && i + 1 < argc)
            runs = std::atoi(argv[++i]);
        else if (a == "--nlos-runs" && i + 1 < argc)
            nlosRuns = std::atoi(argv[++i]);
        else if (a == "--seed" && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 10);
            seedGiven = true;
        } else if (a == "--grid" && i + 1 < argc)
            grid = QString::fromLocal8Bit(argv[++i]);
        else if (a == "--levels" && i + 1 < argc) {
            for (const auto& part : QString::fromLatin1(argv[++i]).split(QLatin1Char(',')))
                levels.push_back(part.toInt());
        } else if (a == "--only-calibration")
            selection = false;
        else if (a == "--only-selection")
            calibration = false;
        else {
            std::fprintf(stderr,
                         "usage: athlos-eval-lps [--quick] [--runs N] [--nlos-runs N] [--seed S] "
                         "[--only-calibration|--only-selection] [--levels 0,4,6] "
                         "[--grid kappa|gate|rejection=FROM:TO:STEP]\n");
            return 2;
        }
    }
    if (quick) {
        runs = std::min(runs, 5);
        nlosRuns = std::min(nlosRuns, 8);
    }
    // Parameters are tuned on seed 777, disjoint from the study's seeds (docs/validation/lps.md).
    if (!grid.isEmpty()) return gridSearch(grid, quick ? 4 : 8, seedGiven ? seed : 777);
    std::printf("# athlos-eval-lps (seed %llu%s)\n\n", static_cast<unsigned long long>(seed), quick ? ", quick" : "");
    if (calibration) calibrationStudy(runs, seed, quick, levels);
    if (selection) {
        selectionStudy(nlosRuns, seed, false);
        selectionStudy(nlosRuns, seed, true);
    }
    return 0;
}
