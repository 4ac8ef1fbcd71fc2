#include "plugins/lps/BeaconSelection.h"

#include "plugins/lps/RobustStatistics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace athlos::lps {

TagFix BeaconSelection::solve(FixInput& input, TdoaSolver& solver, const TagFix* start, const View* view) const {
    switch (params_.method) {
        case Method::All:
            return solveAll(input, solver, start);
        case Method::Irls:
            return solveIrls(input, solver, start);
        case Method::LargestResidual:
            return solveLargestResidual(input, solver, start);
        case Method::FieldOfView:
            return view ? solveFieldOfView(input, solver, start, *view) : solveLargestResidual(input, solver, start);
        case Method::AllSubsets:
            return solveAllSubsets(input, solver, start);
        case Method::BestSubset:
            return solveBestSubset(input, solver, start);
    }
    return {};
}

TagFix BeaconSelection::solveAll(FixInput& input, TdoaSolver& solver, const TagFix* start) const {
    input.setAllWeights(1.0);
    return solver.solve(input, start);
}

TagFix BeaconSelection::solveIrls(FixInput& input, TdoaSolver& solver, const TagFix* start) const {
    input.setAllWeights(1.0);
    return solveIrlsWeighted(input, solver, start, input.weights);
}

TagFix BeaconSelection::solveIrlsWeighted(FixInput& input, TdoaSolver& solver, const TagFix* start,
                                          const std::vector<double> mask) const {
    input.weights = mask;
    std::vector<double> inMask;
    TagFix fix = solver.solve(input, start);
    if (!fix.valid) return fix;
    std::vector<double> e, u(std::size_t(input.size())), previous;
    for (int it = 0; it < params_.irlsIterations; ++it) {
        TdoaSolver::residuals(input, fix.position, fix.offset, e);
        // Scale from all readings, so that a rejected reading can return when the fix moves.
        // (Only the readings in the mask: all of them for method 6.)
        inMask.clear();
        for (int i = 0; i < input.size(); ++i)
            if (mask[size_t(i)] > 0.0) inMask.push_back(e[size_t(i)]);
        const double centre = math::median(inMask);
        const double scale = std::max(1.4826 * medianAbsoluteDeviation(inMask), params_.irlsMinScale);
        const double cut = params_.irlsK * scale;
        previous = input.weights;
        for (int i = 0; i < input.size(); ++i) {
            u[size_t(i)] = mask[size_t(i)] > 0.0 ? std::abs(e[size_t(i)] - centre) / cut : 1e9;
            const double a = 1.0 - u[size_t(i)] * u[size_t(i)];
            input.weights[size_t(i)] = u[size_t(i)] < 1.0 ? a * a : 0.0;  // Tukey bisquare
        }
        // Keep B_min readings: the least suspicious ones get a small positive weight.
        if (input.activeCount() < params_.minBeacons) {
            std::vector<int> order(std::size_t(input.size()));
            std::iota(order.begin(), order.end(), 0);
            std::sort(order.begin(), order.end(), [&](int a, int b) { return u[size_t(a)] < u[size_t(b)]; });
            for (int k = 0; k < std::min(params_.minBeacons, input.size()); ++k)
                input.weights[size_t(order[size_t(k)])] = std::max(input.weights[size_t(order[size_t(k)])], 0.05);
        }
        const TagFix next = solver.solve(input, &fix);
        if (!next.valid) break;
        fix = next;
        double change = 0.0;
        for (std::size_t i = 0; i < previous.size(); ++i)
            change = std::max(change, std::abs(previous[i] - input.weights[i]));
        if (change < 1e-3) break;
    }
    return fix;
}

TagFix BeaconSelection::solveBestSubset(FixInput& input, TdoaSolver& solver, const TagFix* start) const {
    const int n = input.size(), k = std::max(params_.bestSubsetSize, solver.unknowns() + 1);
    TagFix all = solveAll(input, solver, start);
    if (n <= k) return all;
    const TagFix* seed = all.valid ? &all : start;
    // Every combination of k readings: a selection mask permuted through all arrangements.
    std::vector<char> pick(std::size_t(n), 0);
    std::fill(pick.begin(), pick.begin() + k, 1);
    std::vector<double> e, best;
    TagFix bestFix;
    double bestRms = std::numeric_limits<double>::infinity();
    do {
        for (int i = 0; i < n; ++i) input.weights[size_t(i)] = pick[size_t(i)] ? 1.0 : 0.0;
        const TagFix fix = solver.solve(input, seed);
        if (!fix.valid) continue;
        TdoaSolver::residuals(input, fix.position, fix.offset, e);
        const double rms = TdoaSolver::weightedRms(input, e);
        if (rms < bestRms) {
            bestRms = rms;
            bestFix = fix;
            best = input.weights;
        }
    } while (std::prev_permutation(pick.begin(), pick.end()));
    if (!bestFix.valid) {
        input.setAllWeights(1.0);
        return all;
    }
    input.weights = best;
    return bestFix;
}

TagFix BeaconSelection::solveAllSubsets(FixInput& input, TdoaSolver& solver, const TagFix* start) const {
    const int n = input.size();
    TagFix all = solveAll(input, solver, start);
    const int maxOut = std::min(params_.subsetMaxExcluded > 0 ? params_.subsetMaxExcluded : n, n - params_.minBeacons);
    if (maxOut < 1 || n > 31) return all;
    const TagFix* seed = all.valid ? &all : start;
    std::vector<double> sum(std::size_t(n), 0.0), e;
    int hypotheses = 0;
    // Hypotheses by size: every set of `out` readings assumed NLOS (weight 0), the rest weighted
    // equally so that Σ w = B (§3.2.3).
    for (int out = 0; out <= maxOut; ++out) {
        std::vector<char> nlos(std::size_t(n), 0);
        std::fill(nlos.begin(), nlos.begin() + out, 1);
        do {
            for (int i = 0; i < n; ++i) input.weights[size_t(i)] = nlos[size_t(i)] ? 0.0 : double(n) / (n - out);
            const TagFix fix = solver.solve(input, seed);
            if (!fix.valid) continue;
            TdoaSolver::residuals(input, fix.position, fix.offset, e);
            for (int i = 0; i < n; ++i) sum[size_t(i)] += std::abs(e[size_t(i)]);
            ++hypotheses;
        } while (std::prev_permutation(nlos.begin(), nlos.end()));
    }
    if (hypotheses == 0) {
        input.setAllWeights(1.0);
        return all;
    }
    // Bisquare weights of the summed residuals (Cleveland 1979), one-sided: a small sum is never suspicious.
    for (double& v : sum) v /= hypotheses;
    const double centre = math::median(sum);
    const double scale = std::max(1.4826 * medianAbsoluteDeviation(sum), params_.irlsMinScale);
    std::vector<double> u(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        u[size_t(i)] = std::max(0.0, sum[size_t(i)] - centre) / (params_.irlsK * scale);
        const double a = 1.0 - u[size_t(i)] * u[size_t(i)];
        input.weights[size_t(i)] = u[size_t(i)] < 1.0 ? a * a : 0.0;
    }
    if (input.activeCount() < params_.minBeacons) {
        std::vector<int> order(static_cast<std::size_t>(n));
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](int a, int b) { return u[size_t(a)] < u[size_t(b)]; });
        for (int k = 0; k < std::min(params_.minBeacons, n); ++k)
            input.weights[size_t(order[size_t(k)])] = std::max(input.weights[size_t(order[size_t(k)])], 0.05);
    }
    const TagFix fix = solver.solve(input, seed);
    if (fix.valid) return fix;
    input.setAllWeights(1.0);
    return all;
}

TagFix BeaconSelection::solveLargestResidual(FixInput& input, TdoaSolver& solver, const TagFix* start) const {
    input.setAllWeights(1.0);
    return rejectLargest(input, solver, solver.solve(input, start));
}

TagFix BeaconSelection::rejectLargest(FixInput& input, TdoaSolver& solver, TagFix fix) const {
    std::vector<double> e;
    while (fix.valid && input.activeCount() > params_.minBeacons) {
        TdoaSolver::residuals(input, fix.position, fix.offset, e);
        double meanAbs = 0.0;
        int worst = -1;
        for (int i = 0; i < input.size(); ++i) {
            if (input.weights[size_t(i)] <= 0.0) continue;
            meanAbs += std::abs(e[size_t(i)]);
            if (worst < 0 || std::abs(e[size_t(i)]) > std::abs(e[size_t(worst)])) worst = i;
        }
        meanAbs /= input.activeCount();
        if (meanAbs <= params_.rejectionThreshold) break;
        input.weights[size_t(worst)] = 0.0;
        const TagFix next = solver.solve(input, &fix);
        if (!next.valid) {
            input.weights[size_t(worst)] = 1.0;
            break;
        }
        fix = next;
    }
    return fix;
}

double BeaconSelection::freeSpaceLoss(double distance) const {
    return 20.0 * std::log10(std::max(distance, 0.1)) + 20.0 * std::log10(params_.frequency) - 147.55;
}

double BeaconSelection::linkMargin(const Vector3& beacon, const View& view) const {
    const Vector3 d = beacon - view.position;
    const double phi = std::atan2(d.y(), d.x()) - view.heading;  // bearing relative to the body [inferred]
    return params_.gain.gainDb(phi) - freeSpaceLoss(d.norm()) + params_.kappa;
}

TagFix BeaconSelection::solveFieldOfView(FixInput& input, TdoaSolver& solver, const TagFix* start,
                                         const View& view) const {
    std::vector<double> margin(std::size_t(input.size()));
    for (int i = 0; i < input.size(); ++i) {
        margin[size_t(i)] = linkMargin(input.beacons[size_t(i)], view);
        input.weights[size_t(i)] = margin[size_t(i)] > 0.0 ? 1.0 : 0.0;
    }
    // Fewer than B_min in view: take the beacons closest to being visible.
    if (input.activeCount() < params_.minBeacons) {
        std::vector<int> order(std::size_t(input.size()));
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&](int a, int b) { return margin[size_t(a)] > margin[size_t(b)]; });
        for (int k = 0; k < std::min(params_.minBeacons, input.size()); ++k)
            input.weights[size_t(order[size_t(k)])] = 1.0;
    }
    const std::vector<double> fovWeights = input.weights;
    TagFix fix = solver.solve(input, start);
    if (!params_.fovRefine) return fix;
    fix = rejectLeaveOneOut(input, solver, fix);
    // Consistency over time: m̂_ini is the median of the last fixes, so a fix far from it (more than a
    // runner covers in that time) is implausible: the one-sided set in view was dragged off by a late
    // reading. Re-solve from m̂_ini with the bisquare reweighting (method 6) over all readings, whose
    // two-sided geometry one late reading cannot move by metres.
    if (!fix.valid || (fix.position - view.position).head<2>().norm() > params_.fovMaxJump) {
        input.weights = fovWeights;
        TagFix seed = fix.valid ? fix : (start ? *start : TagFix{});
        seed.position.head<2>() = view.position.head<2>();
        seed.valid = true;
        const TagFix alt = solveIrlsWeighted(input, solver, &seed, std::vector<double>(fovWeights.size(), 1.0));
        if (alt.valid) fix = alt;
    }
    return fix;
}

TagFix BeaconSelection::rejectLeaveOneOut(FixInput& input, TdoaSolver& solver, TagFix fix) const {
    // In the one-sided geometry of the field of view a gross outlier pulls the fix towards itself and
    // its own residual can be smaller than a neighbour's; the largest |e_i| then names the wrong
    // beacon. Instead, drop the reading whose removal leaves the most consistent fix (smallest mean
    // |e| of the remaining readings), until the mean |e| is below the threshold or B_min is reached.
    std::vector<double> e;
    const auto meanAbsResidual = [&](const TagFix& f) {
        TdoaSolver::residuals(input, f.position, f.offset, e);
        double sum = 0.0;
        for (int i = 0; i < input.size(); ++i)
            if (input.weights[size_t(i)] > 0.0) sum += std::abs(e[size_t(i)]);
        return sum / std::max(input.activeCount(), 1);
    };
    while (fix.valid && input.activeCount() > params_.minBeacons) {
        if (meanAbsResidual(fix) <= params_.rejectionThreshold) break;
        int best = -1;
        double bestScore = 0.0;
        TagFix bestFix;
        for (int i = 0; i < input.size(); ++i) {
            if (input.weights[size_t(i)] <= 0.0) continue;
            const double w = input.weights[size_t(i)];
            input.weights[size_t(i)] = 0.0;
            const TagFix trial = solver.solve(input, &fix);
            if (trial.valid) {
                const double score = meanAbsResidual(trial);
                if (best < 0 || score < bestScore) {
                    best = i;
                    bestScore = score;
                    bestFix = trial;
                }
            }
            input.weights[size_t(i)] = w;
        }
        if (best < 0) break;
        input.weights[size_t(best)] = 0.0;
        fix = bestFix;
    }
    return fix;
}

void FixHistory::push(const TagFix& fix) {
    if (!fix.valid) return;
    if (!fixes_.empty() && fix.t - fixes_.back().t > maxGap_) fixes_.clear();
    fixes_.push_back(fix);
    while (int(fixes_.size()) > size_) fixes_.pop_front();
}

std::optional<Vector3> FixHistory::median(double t) const {
    if (fixes_.empty() || t - fixes_.back().t > maxGap_) return std::nullopt;
    Vector3 m;
    std::vector<double> c(fixes_.size());
    for (int axis = 0; axis < 3; ++axis) {
        for (std::size_t k = 0; k < fixes_.size(); ++k) c[k] = fixes_[k].position(axis);
        m(axis) = math::median(c);
    }
    return m;
}

std::optional<double> FixHistory::motionHeading(double t, double minDistance) const {
    if (fixes_.size() < 2 || t - fixes_.back().t > maxGap_) return std::nullopt;
    const Vector3 d = fixes_.back().position - fixes_.front().position;
    if (d.head<2>().norm() < minDistance) return std::nullopt;
    return std::atan2(d.y(), d.x());
}

}  // namespace athlos::lps
