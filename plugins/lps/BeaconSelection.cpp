#include "plugins/lps/BeaconSelection.h"

#include "plugins/lps/RobustStatistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace athlos::lps {

TagFix BeaconSelection::solve(FixInput& input, TdoaSolver& solver, const TagFix* start, const View* view) const {
    switch (params_.method) {
    case Method::All: return solveAll(input, solver, start);
    case Method::Irls: return solveIrls(input, solver, start);
    case Method::LargestResidual: return solveLargestResidual(input, solver, start);
    case Method::FieldOfView:
        return view ? solveFieldOfView(input, solver, start, *view) : solveLargestResidual(input, solver, start);
    }
    return {};
}

TagFix BeaconSelection::solveAll(FixInput& input, TdoaSolver& solver, const TagFix* start) const {
    input.setAllWeights(1.0);
    return solver.solve(input, start);
}

TagFix BeaconSelection::solveIrls(FixInput& input, TdoaSolver& solver, const TagFix* start) const {
    input.setAllWeights(1.0);
    TagFix fix = solver.solve(input, start);
    if (!fix.valid) return fix;
    std::vector<double> e, u(std::size_t(input.size())), previous;
    for (int it = 0; it < params_.irlsIterations; ++it) {
        TdoaSolver::residuals(input, fix.position, fix.offset, e);
        // Scale from all readings, so that a rejected reading can return when the fix moves.
        const double centre = median(e);
        const double scale = std::max(1.4826 * medianAbsoluteDeviation(e), params_.irlsMinScale);
        const double cut = params_.irlsK * scale;
        previous = input.weights;
        for (int i = 0; i < input.size(); ++i) {
            u[size_t(i)] = std::abs(e[size_t(i)] - centre) / cut;
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
        for (std::size_t i = 0; i < previous.size(); ++i) change = std::max(change, std::abs(previous[i] - input.weights[i]));
        if (change < 1e-3) break;
    }
    return fix;
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
        for (int k = 0; k < std::min(params_.minBeacons, input.size()); ++k) input.weights[size_t(order[size_t(k)])] = 1.0;
    }
    TagFix fix = solver.solve(input, start);
    return params_.fovRefine ? rejectLargest(input, solver, fix) : fix;
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
        m(axis) = lps::median(c);
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
