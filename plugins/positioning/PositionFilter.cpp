#include "plugins/positioning/PositionFilter.h"

#include "core/estimation/Ekf.h"
#include "core/estimation/SrUkf.h"
#include "core/math/Statistics.h"
#include "plugins/positioning/ConstantVelocity.h"
#include "plugins/positioning/TrackGapBridge.h"
#include "plugins/positioning/TrackModels.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace athlos::positioning {

using namespace estimation;

namespace {

// Upper medians (math::upperMedian): the initialisation and noise guess were tuned with them.
// The window is never empty (window() returns at least one sample of a non-empty input).
Eigen::Vector2d medianPosition(const PositionSamples& in, std::size_t begin, std::size_t end) {
    std::vector<double> xs, ys;
    for (std::size_t i = begin; i < end && i < in.p.size(); ++i) {
        xs.push_back(in.p[i].x());
        ys.push_back(in.p[i].y());
    }
    return {math::upperMedian(xs), math::upperMedian(ys)};
}

// Index range of the samples in [t0, t1) (at least `minimum` samples when available).
std::pair<std::size_t, std::size_t> window(const PositionSamples& in, std::size_t from, double duration,
                                           std::size_t minimum) {
    std::size_t end = from;
    while (end < in.t.size() && (in.t[end] < in.t[from] + duration || end - from < minimum)) ++end;
    return {from, end};
}

// Initial state from the first second of data, robust to a leading outlier (medians).
struct Initial {
    Eigen::Vector2d p;
    double speed = 0.0, heading = 0.0;
    bool headingKnown = false;
};

Initial initialKinematics(const PositionSamples& in, const TrackGeometry* track) {
    Initial init;
    const auto [b0, e0] = window(in, 0, 0.5, 5);
    init.p = medianPosition(in, b0, e0);
    if (e0 < in.t.size()) {
        const auto [b1, e1] = window(in, e0, 0.5, 5);
        const Eigen::Vector2d p1 = medianPosition(in, b1, e1);
        const double dt = 0.5 * (in.t[b1] + in.t[std::min(e1, in.t.size()) - 1]) -
                          0.5 * (in.t[b0] + in.t[std::min(e0, in.t.size()) - 1]);
        const Eigen::Vector2d dp = p1 - init.p;
        if (dt > 0 && dp.norm() > 1.0) {
            init.speed = dp.norm() / dt;
            init.heading = std::atan2(dp.y(), dp.x());
            init.headingKnown = true;
        }
    }
    if (track && !init.headingKnown) init.heading = track->headingAt(init.p);
    return init;
}

template <class Model>
struct ModelTraits;

template <>
struct ModelTraits<ConstantVelocityModel> {
    static Vector<4> initialState(const Initial& i) {
        return Vector<4>(i.p.x(), i.p.y(), i.speed * std::cos(i.heading), i.speed * std::sin(i.heading));
    }
    static Matrix<4, 4> initialCovariance(double r, const Initial&) {
        return Vector<4>(r + 1.0, r + 1.0, 4.0, 4.0).asDiagonal();
    }
};

template <class Model>
struct CtraTraits {
    static Vector<6> initialState(const Initial& i) {
        Vector<6> x;
        x << i.p.x(), i.p.y(), i.speed, 0.0, i.heading, 0.0;
        return x;
    }
    static Matrix<6, 6> initialCovariance(double r, const Initial& i) {
        Vector<6> d;
        d << r + 1.0, r + 1.0, 4.0, 4.0, i.headingKnown ? 0.25 : 2.5, 0.25;
        return d.asDiagonal();
    }
};
template <>
struct ModelTraits<CtraModel> : CtraTraits<CtraModel> {};
template <>
struct ModelTraits<AugmentedTrackModel> : CtraTraits<AugmentedTrackModel> {};
template <>
struct ModelTraits<PseudoTrackModel> : CtraTraits<PseudoTrackModel> {};

template <class Filter>
PositionFilterResult runFilter(Filter filter, const PositionFilter::Params& params, const PositionSamples& in,
                               const std::vector<double>& tOut, Smoothing smoothing,
                               const PositionFilter::ProgressFn& progress, const TrackGeometry* track) {
    using Model = typename Filter::ModelType;
    PositionFilterResult result;
    if (in.t.empty()) return result;
    const Initial init = initialKinematics(in, track);
    const double r = std::max(params.noise.ctra.rX, params.noise.ctra.rY);
    filter.reset(ModelTraits<Model>::initialState(init), ModelTraits<Model>::initialCovariance(r, init));

    std::vector<typename Filter::Measurement> y(in.p.size());
    for (std::size_t k = 0; k < in.p.size(); ++k) y[k] = Model::observation(in.p[k]);

    typename TimeGridRunner<Filter>::Params rp;
    rp.gate = params.noise.gate;
    rp.smoothing = smoothing;
    rp.lag = params.lag;
    rp.maxStep = params.maxStep;
    const TimeGridRunner<Filter> runner(rp);
    auto out = runner.run(filter, in.t.front(), in.t, y, tOut, progress);
    if (out.samples.empty()) {
        result.cancelled = true;
        return result;
    }
    result.t = std::move(out.t);
    result.states.reserve(out.x.size());
    for (const auto& x : out.x) result.states.push_back(Model::kinematics(x));
    result.mahalanobis2.reserve(in.t.size());
    result.outlier.reserve(in.t.size());
    for (const auto& s : out.samples) {
        result.mahalanobis2.push_back(s.mahalanobis2);
        result.logDetSigma.push_back(s.logDetSigma);
        result.outlier.push_back(s.accepted ? 0 : 1);
    }
    return result;
}

template <class Model>
PositionFilterResult dispatchFilter(const Model& model, const PositionFilter::Params& params, const PositionSamples& in,
                                    const std::vector<double>& tOut, Smoothing smoothing,
                                    const PositionFilter::ProgressFn& progress) {
    const TrackGeometry* track = params.track.get();
    switch (params.filter) {
        case FilterKind::Ekf:
            return runFilter(Ekf<Model>(model), params, in, tOut, smoothing, progress, track);
        case FilterKind::Ukf:
            return runFilter(Ukf<Model>(model, params.unscented), params, in, tOut, smoothing, progress, track);
        case FilterKind::SrUkf:
            return runFilter(SrUkf<Model>(model, params.unscented), params, in, tOut, smoothing, progress, track);
    }
    return {};
}

PositionFilterResult dispatch(const PositionFilter::Params& params, const PositionSamples& in,
                              const std::vector<double>& tOut, Smoothing smoothing,
                              const PositionFilter::ProgressFn& progress) {
    const NoiseSettings& n = params.noise;
    const double inf = std::numeric_limits<double>::infinity();
    const double cvAfter = params.cvSwitch && !in.t.empty() ? PositionFilter::detectStart(in) + params.accelPhase : inf;
    TrackConstraintParams constraint;
    constraint.track = params.track;
    switch (params.model) {
        case ModelKind::Unconstrained:
            return dispatchFilter(CtraModel({n.ctra, inf}), params, in, tOut, smoothing, progress);
        case ModelKind::ConstantVelocity:
            return dispatchFilter(ConstantVelocityModel({n.qAccelCv, n.ctra.rX, n.ctra.rY}), params, in, tOut,
                                  smoothing, progress);
        case ModelKind::Augmented:
            return dispatchFilter(AugmentedTrackModel({n.ctra, constraint, cvAfter}), params, in, tOut, smoothing,
                                  progress);
        case ModelKind::Pseudo:
            return dispatchFilter(PseudoTrackModel({n.ctra, constraint, cvAfter, n.rHeading, n.rTurnRate, n.rAccel}),
                                  params, in, tOut, smoothing, progress);
    }
    return {};
}

}  // namespace

PositionFilter::PositionFilter(Params params) : params_(std::move(params)) {}

PositionFilterResult PositionFilter::run(const PositionSamples& in, const std::vector<double>& tOut,
                                         const ProgressFn& progress) const {
    PositionFilterResult result = dispatch(params_, in, tOut, params_.smoothing, progress);
    // The augmented model's prediction follows the track; across long outages the smoother can only
    // follow it linearly, so those gaps are bridged along the track between their observed ends.
    if (!result.cancelled && params_.model == ModelKind::Augmented && params_.smoothing == Smoothing::Rts &&
        params_.track && params_.bridgeGap > 0) {
        TrackConstraintParams constraint;
        constraint.track = params_.track;
        TrackGapBridge(constraint, {params_.bridgeGap}).apply(in, result);
    }
    return result;
}

double PositionFilter::objective(const PositionSamples& in) const {
    // Estimation uses the observation times only (thesis: steps k ∉ O\M are omitted).
    const PositionFilterResult r = dispatch(params_, in, in.t, Smoothing::None, {});
    return robustInnovationObjective(r.mahalanobis2, r.logDetSigma, params_.noise.gate);
}

PositionFilter::Estimate PositionFilter::estimateNoise(const Params& params, const std::vector<PositionSamples>& runs,
                                                       const NoiseEstimator::Params& search,
                                                       const ProgressFn& progress) {
    // The searched parameters depend on the model; each maps to one field of NoiseSettings.
    struct Field {
        NoiseEstimator::Parameter parameter;
        double NoiseSettings::*member = nullptr;
        double CtraNoise::*ctraMember = nullptr;
    };
    double r0 = 0.0;
    for (const auto& run : runs) r0 += roughMeasurementVariance(run) / double(runs.size());
    const NoiseSettings& n = params.noise;
    std::vector<Field> fields;
    auto ctra = [&](const char* name, double CtraNoise::*m, double lo, double hi) {
        fields.push_back({{name, n.ctra.*m, lo, hi}, nullptr, m});
    };
    auto other = [&](const char* name, double NoiseSettings::*m, double lo, double hi) {
        fields.push_back({{name, n.*m, lo, hi}, m, nullptr});
    };
    if (params.model == ModelKind::ConstantVelocity) {
        other("q_accel", &NoiseSettings::qAccelCv, 1e-4, 1e3);
    } else {
        // q_position (0 in the thesis) gives the track models lateral freedom: their heading is pinned
        // to the track, so a lane change is otherwise a deterministic offset the smoother would smear.
        ctra("q_position", &CtraNoise::qPosition, 1e-6, 1e1);
        ctra("q_speed", &CtraNoise::qSpeed, 1e-5, 1e2);
        ctra("q_accel", &CtraNoise::qAccel, 1e-4, 1e3);
        ctra("q_heading", &CtraNoise::qHeading, 1e-6, 1e1);
        ctra("q_turn_rate", &CtraNoise::qTurnRate, 1e-6, 1e1);
    }
    ctra("r_x", &CtraNoise::rX, 1e-4, 1e2);
    ctra("r_y", &CtraNoise::rY, 1e-4, 1e2);
    fields[fields.size() - 2].parameter.initial = r0;
    fields[fields.size() - 1].parameter.initial = r0;
    if (params.model == ModelKind::Pseudo) {
        other("r_heading", &NoiseSettings::rHeading, 1e-6, 1e1);
        other("r_turn_rate", &NoiseSettings::rTurnRate, 1e-6, 1e1);
        other("r_accel", &NoiseSettings::rAccel, 1e-4, 1e2);
    }
    other("gate", &NoiseSettings::gate, 2.0, 1e4);

    auto apply = [&](const std::vector<double>& values) {
        Params p = params;
        for (std::size_t i = 0; i < fields.size(); ++i) {
            if (fields[i].member)
                p.noise.*fields[i].member = values[i];
            else
                p.noise.ctra.*fields[i].ctraMember = values[i];
        }
        return p;
    };
    std::vector<NoiseEstimator::Parameter> parameters;
    for (const auto& f : fields) parameters.push_back(f.parameter);
    const NoiseEstimator estimator(parameters, search);
    const auto best = estimator.minimize(
        [&](const std::vector<double>& values) {
            const PositionFilter filter(apply(values));
            double sum = 0.0;
            for (const auto& run : runs) sum += filter.objective(run);
            return sum;
        },
        progress);
    Estimate e;
    e.noise = apply(best.values).noise;
    e.objective = best.objective;
    e.evaluations = best.evaluations;
    e.cancelled = best.cancelled;
    for (std::size_t i = 0; i < fields.size(); ++i) e.values.emplace_back(fields[i].parameter.name, best.values[i]);
    return e;
}

std::vector<PositionSamples> PositionFilter::noiseChunks(const PositionSamples& fixes, double duration, int count) {
    std::vector<PositionSamples> chunks;
    for (const auto& [a, b] : chunkWindows(fixes.t.front(), fixes.t.back(), duration, count)) {
        const auto lo = std::lower_bound(fixes.t.begin(), fixes.t.end(), a) - fixes.t.begin();
        const auto hi = std::upper_bound(fixes.t.begin(), fixes.t.end(), b) - fixes.t.begin();
        if (hi - lo < 10) continue;
        PositionSamples chunk;
        chunk.t.assign(fixes.t.begin() + lo, fixes.t.begin() + hi);
        chunk.p.assign(fixes.p.begin() + lo, fixes.p.begin() + hi);
        chunks.push_back(std::move(chunk));
    }
    if (chunks.empty()) return {fixes};
    return chunks;
}

std::vector<std::pair<double, double>> PositionFilter::chunkWindows(double t0, double t1, double duration, int count) {
    std::vector<std::pair<double, double>> windows;
    if (count <= 0 || !(duration > 0) || (t1 - t0) <= count * duration) return windows;
    const double spacing = (t1 - t0 - duration) / (count - 1 > 0 ? count - 1 : 1);
    for (int c = 0; c < count; ++c) windows.emplace_back(t0 + c * spacing, t0 + c * spacing + duration);
    return windows;
}

std::vector<double> PositionFilter::outputGrid(double tBegin, double tEnd, double rate) {
    std::vector<double> grid;
    if (!(rate > 0) || tEnd < tBegin) return grid;
    const long long first = static_cast<long long>(std::ceil(tBegin * rate - 1e-9));
    const long long last = static_cast<long long>(std::floor(tEnd * rate + 1e-9));
    grid.reserve(static_cast<std::size_t>(std::max(0LL, last - first + 1)));
    for (long long k = first; k <= last; ++k) grid.push_back(double(k) / rate);
    return grid;
}

double PositionFilter::roughMeasurementVariance(const PositionSamples& in) {
    // y_{k+1} − 2y_k + y_{k−1} ≈ noise·√6 at LPS rates (motion contributes a·T² ≪ noise).
    std::vector<double> dx, dy;
    for (std::size_t k = 1; k + 1 < in.p.size(); ++k) {
        const Eigen::Vector2d d = in.p[k + 1] - 2.0 * in.p[k] + in.p[k - 1];
        dx.push_back(std::abs(d.x()));
        dy.push_back(std::abs(d.y()));
    }
    if (dx.empty()) return 0.01;
    const double sx = 1.4826 * math::upperMedian(dx) / std::sqrt(6.0),
                 sy = 1.4826 * math::upperMedian(dy) / std::sqrt(6.0);
    return std::max(0.5 * (sx * sx + sy * sy), 1e-4);
}

double PositionFilter::detectStart(const PositionSamples& in) {
    if (in.t.empty()) return 0.0;
    const auto [b0, e0] = window(in, 0, 0.5, 5);
    const Eigen::Vector2d p0 = medianPosition(in, b0, e0);
    // Median of 5 consecutive samples ignores isolated outliers and short bursts.
    for (std::size_t k = 0; k + 5 <= in.p.size(); ++k) {
        std::vector<double> dist;
        for (std::size_t j = k; j < k + 5; ++j) dist.push_back((in.p[j] - p0).norm());
        if (math::upperMedian(dist) > 2.0) return in.t[k];
    }
    return in.t.front();
}

}  // namespace athlos::positioning
