#include "plugins/positioning/RangeFilter.h"

#include "core/math/Statistics.h"
#include "plugins/positioning/ConstantVelocity.h"
#include "plugins/positioning/TrackModels.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace athlos::positioning {

using namespace estimation;

namespace {

// The motion model augmented with B constant range offsets β_0..β_{B−1} (one per beacon, random walk
// with density qBias), plus the scalar range noise: x = [x_motion, β]. Consistent per-beacon offsets
// (antenna delays, a cable, an anchor's survey error along the line of sight) rotate or shift every fix
// far from a compact anchor group; near the group the ranges are redundant and the offsets observable,
// and the RTS smoother carries them over the whole recording. B = 0: no offsets.
template <class Motion, int B>
class RangeModel {
public:
    static constexpr int kMotionDim = Motion::kStateDim;
    static constexpr int kStateDim = kMotionDim + B;
    static constexpr int kMeasurementDim = 1;
    using StateVector = Vector<kStateDim>;
    using StateMatrix = Matrix<kStateDim, kStateDim>;
    using MotionVector = Vector<kMotionDim>;
    using MotionMatrix = Matrix<kMotionDim, kMotionDim>;

    RangeModel(Motion motion, double rRange, double qBias)
        : motion_(std::move(motion)), rRange_(rRange), qBias_(qBias) {}

    StateVector predict(const StateVector& x, double T, double t, StateMatrix* jacobian = nullptr) const {
        StateVector y = x;
        MotionMatrix Phi;
        y.template head<kMotionDim>() = motion_.predict(x.template head<kMotionDim>(), T, t, jacobian ? &Phi : nullptr);
        if (jacobian) {
            jacobian->setIdentity();
            jacobian->template topLeftCorner<kMotionDim, kMotionDim>() = Phi;
        }
        return y;
    }
    StateMatrix processNoise(double T, double t) const {
        StateMatrix Q = StateMatrix::Zero();
        Q.template topLeftCorner<kMotionDim, kMotionDim>() = motion_.processNoise(T, t);
        for (int i = kMotionDim; i < kStateDim; ++i) Q(i, i) = qBias_ * T;
        return Q;
    }
    StateVector difference(const StateVector& a, const StateVector& b) const {
        StateVector d = a - b;
        d.template head<kMotionDim>() =
            motion_.difference(a.template head<kMotionDim>(), b.template head<kMotionDim>());
        return d;
    }
    void normalize(StateVector& x) const {
        MotionVector m = x.template head<kMotionDim>();
        motion_.normalize(m);
        x.template head<kMotionDim>() = m;
    }
    Matrix<1, 1> measurementNoise(double) const { return Matrix<1, 1>::Constant(rRange_); }

private:
    Motion motion_;
    double rRange_, qBias_;
};

// EKF with one scalar range update per measurement (eqs. 2.15–2.19 with M = 1, gate eq. 4.1):
// h = |m − b_i| + β_i. The prediction is the Ekf's; the beacon of each update comes with the observation.
template <class Motion, int B>
class RangeEkf {
public:
    using ModelType = RangeModel<Motion, B>;
    static constexpr int N = ModelType::kStateDim;
    static constexpr int M = 1;
    using Observation = RangeObservation;
    using StateVector = Vector<N>;
    using StateMatrix = Matrix<N, N>;

    RangeEkf(ModelType model, const std::vector<Eigen::Vector3d>& beacons, double tagHeight)
        : model_(std::move(model)), beacons_(beacons), tagHeight_(tagHeight) {}

    void reset(const StateVector& x0, const StateMatrix& P0) {
        x_ = x0;
        P_ = P0;
    }

    StateMatrix predict(double T, double t) {
        StateMatrix Phi;
        x_ = model_.predict(x_, T, t, &Phi);
        model_.normalize(x_);
        const StateMatrix C = P_.lazyProduct(Phi.transpose());
        P_ = Phi.lazyProduct(C) + model_.processNoise(T, t);
        return C;
    }

    Innovation update(const Observation& y, double t, double gate) {
        const Eigen::Vector3d d = Eigen::Vector3d(x_[0], x_[1], tagHeight_) - beacons_[std::size_t(y.beacon)];
        const double h = std::max(d.norm(), 1e-6);
        Matrix<1, N> H = Matrix<1, N>::Zero();
        H(0, 0) = d.x() / h;
        H(0, 1) = d.y() / h;
        double z = y.range - h;
        if (y.beacon < B) {
            H(0, ModelType::kMotionDim + y.beacon) = 1.0;
            z -= x_[ModelType::kMotionDim + y.beacon];
        }
        const Vector<N> PHt = P_ * H.transpose();
        const double S = H.dot(PHt) + model_.measurementNoise(t)(0, 0);
        Innovation innovation;
        innovation.mahalanobis2 = z * z / S;
        innovation.logDetSigma = std::log(S);
        innovation.accepted = innovation.mahalanobis2 <= gate;
        residual_(0) = z;
        if (!innovation.accepted) return innovation;
        const Vector<N> K = PHt / S;
        x_ += K * z;
        model_.normalize(x_);
        P_ -= K * PHt.transpose();
        P_ = 0.5 * (P_ + P_.transpose());
        return innovation;
    }

    void inflate(double factor) { P_ *= factor; }
    const Vector<1>& residual() const { return residual_; }
    const StateVector& x() const { return x_; }
    StateMatrix covariance() const { return P_; }
    const ModelType& model() const { return model_; }

private:
    ModelType model_;
    const std::vector<Eigen::Vector3d>& beacons_;
    double tagHeight_;
    StateVector x_ = StateVector::Zero();
    StateMatrix P_ = StateMatrix::Identity();
    Vector<1> residual_ = Vector<1>::Zero();
};

// Initial state: the start position, at rest, with wide velocity and heading uncertainty.
template <class Motion>
struct Start;

template <>
struct Start<ConstantVelocityModel> {
    static Vector<4> state(const Eigen::Vector2d& p) { return Vector<4>(p.x(), p.y(), 0.0, 0.0); }
    static Matrix<4, 4> covariance() { return Vector<4>(4.0, 4.0, 4.0, 4.0).asDiagonal(); }
    static Kinematics kinematics(const Vector<4>& x) { return ConstantVelocityModel::kinematics(x); }
};

template <class Model>
struct CtraStart {
    static Vector<6> state(const Eigen::Vector2d& p) {
        Vector<6> x;
        x << p.x(), p.y(), 0.0, 0.0, 0.0, 0.0;
        return x;
    }
    static Matrix<6, 6> covariance() {
        Vector<6> d;
        d << 4.0, 4.0, 4.0, 4.0, 10.0, 0.25;
        return d.asDiagonal();
    }
    static Kinematics kinematics(const Vector<6>& x) { return CtraModel::kinematics(x); }
};
template <>
struct Start<CtraModel> : CtraStart<CtraModel> {};
template <>
struct Start<AugmentedTrackModel> : CtraStart<AugmentedTrackModel> {};

template <class Motion, int B>
RangeFilter::Result runWith(const Motion& motion, const RangeFilter::Params& params, const RangeMeasurements& in,
                            const Eigen::Vector2d& start, const std::vector<double>& tOut, Smoothing smoothing,
                            const RangeFilter::ProgressFn& progress) {
    using Filter = RangeEkf<Motion, B>;
    constexpr int Nm = Motion::kStateDim;
    RangeFilter::Result result;
    result.start = start;
    Filter filter(typename Filter::ModelType(motion, params.rRange, params.qBias), in.beacons, params.tagHeight);
    Vector<Filter::N> x0 = Vector<Filter::N>::Zero();
    Matrix<Filter::N, Filter::N> P0 = Matrix<Filter::N, Filter::N>::Zero();
    x0.template head<Nm>() = Start<Motion>::state(start);
    P0.template topLeftCorner<Nm, Nm>() = Start<Motion>::covariance();
    // Only the offsets relative to each other are estimated: their mean (a common offset) moves every
    // fix radially and trades with the tag height and the radial distance, so its prior is tight
    // (σ²(I − 11ᵀ/n) + ε I over the n beacons with an offset state).
    const int n = std::min<int>(B, int(in.beacons.size()));
    const double s2 = params.biasSigma * params.biasSigma;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) P0(Nm + i, Nm + j) = s2 * ((i == j ? 1.0 : 0.0) - 1.0 / n) + (i == j ? 1e-6 : 0.0);
    for (int i = Nm + n; i < Filter::N; ++i) P0(i, i) = 1e-6;
    filter.reset(x0, P0);
    typename TimeGridRunner<Filter>::Params rp;
    rp.gate = params.noise.gate;
    rp.smoothing = smoothing;
    rp.lag = params.lag;
    rp.maxStep = params.maxStep;
    rp.covariance = params.covariance;
    const TimeGridRunner<Filter> runner(rp);
    auto out = runner.run(filter, in.t.front(), in.t, in.y, tOut, progress);
    PositionFilterResult& r = result.filtered;
    if (out.samples.empty()) {
        r.cancelled = true;
        return result;
    }
    r.t = std::move(out.t);
    r.states.reserve(out.x.size());
    for (const auto& x : out.x) r.states.push_back(Start<Motion>::kinematics(x.template head<Nm>()));
    for (const auto& P : out.P)
        result.sd.emplace_back(std::sqrt(std::max(P(0, 0), 0.0)), std::sqrt(std::max(P(1, 1), 0.0)));
    if (B > 0 && !out.x.empty()) {
        // The offsets are constant up to the slow random walk: report the smoothed values at the middle.
        const auto& mid = out.x[out.x.size() / 2];
        for (int i = 0; i < std::min<int>(B, int(in.beacons.size())); ++i) result.offsets.push_back(mid[Nm + i]);
    }
    r.mahalanobis2.reserve(in.size());
    r.logDetSigma.reserve(in.size());
    r.outlier.reserve(in.size());
    for (const auto& s : out.samples) {
        r.mahalanobis2.push_back(s.mahalanobis2);
        r.logDetSigma.push_back(s.logDetSigma);
        r.outlier.push_back(s.accepted ? 0 : 1);
    }
    return result;
}

// Offset states for up to 8 beacons (fixed sizes keep the inner loop allocation-free); more beacons or
// offsets=false: none.
template <class Motion>
RangeFilter::Result runWithOffsets(const Motion& motion, const RangeFilter::Params& params, const RangeMeasurements& in,
                                   const Eigen::Vector2d& start, const std::vector<double>& tOut, Smoothing smoothing,
                                   const RangeFilter::ProgressFn& progress) {
    const std::size_t beacons = in.beacons.size();
    if (params.offsets && beacons <= 4) return runWith<Motion, 4>(motion, params, in, start, tOut, smoothing, progress);
    if (params.offsets && beacons <= 8) return runWith<Motion, 8>(motion, params, in, start, tOut, smoothing, progress);
    return runWith<Motion, 0>(motion, params, in, start, tOut, smoothing, progress);
}

RangeFilter::Result dispatch(const RangeFilter::Params& params, const RangeMeasurements& in,
                             const Eigen::Vector2d& start, const std::vector<double>& tOut, Smoothing smoothing,
                             const RangeFilter::ProgressFn& progress) {
    const NoiseSettings& n = params.noise;
    const double inf = std::numeric_limits<double>::infinity();
    switch (params.model) {
        case ModelKind::ConstantVelocity:
            return runWithOffsets(ConstantVelocityModel({n.qAccelCv, params.rRange, params.rRange}), params, in, start,
                                  tOut, smoothing, progress);
        case ModelKind::Augmented: {
            TrackConstraintParams constraint;
            constraint.track = params.track;
            return runWithOffsets(AugmentedTrackModel({n.ctra, constraint, inf}), params, in, start, tOut, smoothing,
                                  progress);
        }
        case ModelKind::Unconstrained:
        case ModelKind::Pseudo:
            break;
    }
    return runWithOffsets(CtraModel({n.ctra, inf}), params, in, start, tOut, smoothing, progress);
}

double rangeCost(const Eigen::Vector2d& p, double tagHeight, const std::vector<std::pair<Eigen::Vector3d, double>>& r) {
    double cost = 0.0;
    for (const auto& [b, d] : r) {
        const double e = (Eigen::Vector3d(p.x(), p.y(), tagHeight) - b).norm() - d;
        cost += e * e;
    }
    return cost;
}

}  // namespace

RangeMeasurements RangeMeasurements::slice(double a, double b) const {
    RangeMeasurements out;
    out.beacons = beacons;
    const auto lo = std::lower_bound(t.begin(), t.end(), a) - t.begin();
    const auto hi = std::upper_bound(t.begin(), t.end(), b) - t.begin();
    out.t.assign(t.begin() + lo, t.begin() + hi);
    out.y.assign(y.begin() + lo, y.begin() + hi);
    return out;
}

RangeMeasurements RangeFilter::thinned(const RangeMeasurements& in, double spacing) {
    RangeMeasurements out;
    out.beacons = in.beacons;
    std::vector<double> last(in.beacons.size(), -std::numeric_limits<double>::infinity());
    for (std::size_t k = 0; k < in.size(); ++k) {
        double& previous = last[std::size_t(in.y[k].beacon)];
        if (in.t[k] - previous < spacing) continue;
        previous = in.t[k];
        out.t.push_back(in.t[k]);
        out.y.push_back(in.y[k]);
    }
    return out;
}

RangeFilter::RangeFilter(Params params) : params_(std::move(params)) {}

std::optional<Eigen::Vector2d> RangeFilter::initialPosition(const RangeMeasurements& in, double tagHeight,
                                                            double window) {
    if (in.t.empty()) return std::nullopt;
    std::map<int, std::vector<double>> byBeacon;
    const double t0 = in.t.front();
    for (std::size_t k = 0; k < in.size(); ++k) {
        if (in.t[k] > t0 + window && byBeacon.size() >= 3) break;
        if (in.t[k] > t0 + 10.0 * window) break;
        if (std::isfinite(in.y[k].range)) byBeacon[in.y[k].beacon].push_back(in.y[k].range);
    }
    if (byBeacon.size() < 3) return std::nullopt;
    std::vector<std::pair<Eigen::Vector3d, double>> ranges;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    double reach = 0.0;
    for (auto& [beacon, values] : byBeacon) {
        const double d = math::median(values);
        ranges.emplace_back(in.beacons[std::size_t(beacon)], d);
        centre += in.beacons[std::size_t(beacon)].head<2>() / double(byBeacon.size());
        reach = std::max(reach, d);
    }
    // Coarse grid (0.25 m, or finer steps when the ranges are short) over the disc every range reaches,
    // then Gauss–Newton: the cost has mirror minima when the beacons are nearly collinear, the grid
    // picks the better one.
    const double extent = reach + 2.0;
    const double step = std::clamp(extent / 200.0, 0.05, 0.5);
    Eigen::Vector2d best = centre;
    double bestCost = std::numeric_limits<double>::infinity();
    for (double x = -extent; x <= extent; x += step)
        for (double y = -extent; y <= extent; y += step) {
            const Eigen::Vector2d p = centre + Eigen::Vector2d(x, y);
            const double c = rangeCost(p, tagHeight, ranges);
            if (c < bestCost) bestCost = c, best = p;
        }
    for (int iteration = 0; iteration < 20; ++iteration) {
        Eigen::Matrix2d JtJ = Eigen::Matrix2d::Zero();
        Eigen::Vector2d Jte = Eigen::Vector2d::Zero();
        for (const auto& [b, d] : ranges) {
            const Eigen::Vector3d v = Eigen::Vector3d(best.x(), best.y(), tagHeight) - b;
            const double h = std::max(v.norm(), 1e-6);
            const Eigen::Vector2d j = v.head<2>() / h;
            JtJ += j * j.transpose();
            Jte += j * (h - d);
        }
        const Eigen::Vector2d delta = JtJ.ldlt().solve(-Jte);
        if (!delta.allFinite()) break;
        best += delta;
        if (delta.norm() < 1e-6) break;
    }
    return best;
}

Expected<RangeFilter::Result> RangeFilter::run(const RangeMeasurements& in, const std::vector<double>& tOut,
                                               const ProgressFn& progress) const {
    const auto start = initialPosition(in, params_.tagHeight);
    if (!start)
        return makeError(QStringLiteral(
            "no starting position: fewer than 3 beacons report a range in the first 10 s of the measurements"));
    return dispatch(params_, in, *start, tOut, params_.smoothing, progress);
}

double RangeFilter::objective(const RangeMeasurements& in) const {
    const auto start = initialPosition(in, params_.tagHeight);
    if (!start) return std::numeric_limits<double>::infinity();
    const Result r = dispatch(params_, in, *start, in.t, Smoothing::None, {});
    return robustInnovationObjective(r.filtered.mahalanobis2, r.filtered.logDetSigma, params_.noise.gate);
}

PositionFilter::Estimate RangeFilter::estimateNoise(const Params& params, const std::vector<RangeMeasurements>& runs,
                                                    double& rRange, const NoiseEstimator::Params& search,
                                                    const ProgressFn& progress) {
    struct Field {
        NoiseEstimator::Parameter parameter;
        double* (*target)(Params&);
    };
    double r0 = 0.0;
    for (const auto& run : runs) r0 += roughRangeVariance(run) / double(runs.size());
    const NoiseSettings& n = params.noise;
    std::vector<Field> fields;
    if (params.model == ModelKind::ConstantVelocity) {
        fields.push_back({{"q_accel", n.qAccelCv, 1e-4, 1e3}, [](Params& p) { return &p.noise.qAccelCv; }});
    } else {
        fields.push_back(
            {{"q_position", n.ctra.qPosition, 1e-6, 1e1}, [](Params& p) { return &p.noise.ctra.qPosition; }});
        fields.push_back({{"q_speed", n.ctra.qSpeed, 1e-5, 1e2}, [](Params& p) { return &p.noise.ctra.qSpeed; }});
        fields.push_back({{"q_accel", n.ctra.qAccel, 1e-4, 1e3}, [](Params& p) { return &p.noise.ctra.qAccel; }});
        fields.push_back({{"q_heading", n.ctra.qHeading, 1e-6, 1e1}, [](Params& p) { return &p.noise.ctra.qHeading; }});
        fields.push_back(
            {{"q_turn_rate", n.ctra.qTurnRate, 1e-6, 1e1}, [](Params& p) { return &p.noise.ctra.qTurnRate; }});
    }
    fields.push_back({{"r_range", r0, 1e-5, 1e2}, [](Params& p) { return &p.rRange; }});
    fields.push_back({{"gate", n.gate, 2.0, 1e4}, [](Params& p) { return &p.noise.gate; }});
    if (!std::isfinite(fields.back().parameter.initial)) fields.back().parameter.initial = 16.0;

    auto apply = [&](const std::vector<double>& values) {
        Params p = params;
        for (std::size_t i = 0; i < fields.size(); ++i) *fields[i].target(p) = values[i];
        return p;
    };
    std::vector<NoiseEstimator::Parameter> parameters;
    for (const auto& f : fields) parameters.push_back(f.parameter);
    const NoiseEstimator estimator(parameters, search);
    const auto best = estimator.minimize(
        [&](const std::vector<double>& values) {
            const RangeFilter filter(apply(values));
            double sum = 0.0;
            for (const auto& run : runs) sum += filter.objective(run);
            return sum;
        },
        progress);
    const Params chosen = apply(best.values);
    PositionFilter::Estimate e;
    e.noise = chosen.noise;
    rRange = chosen.rRange;
    e.objective = best.objective;
    e.evaluations = best.evaluations;
    e.cancelled = best.cancelled;
    for (std::size_t i = 0; i < fields.size(); ++i) e.values.emplace_back(fields[i].parameter.name, best.values[i]);
    return e;
}

std::vector<RangeMeasurements> RangeFilter::noiseChunks(const RangeMeasurements& in, double duration, int count) {
    if (in.t.empty()) return {in};
    std::vector<RangeMeasurements> chunks;
    for (const auto& [a, b] : PositionFilter::chunkWindows(in.t.front(), in.t.back(), duration, count)) {
        RangeMeasurements chunk = in.slice(a, b);
        if (chunk.size() >= 30 && initialPosition(chunk, 0.0)) chunks.push_back(std::move(chunk));
    }
    if (chunks.empty()) return {in};
    return chunks;
}

double RangeFilter::roughRangeVariance(const RangeMeasurements& in) {
    // d_{k+1} − 2 d_k + d_{k−1} of one beacon's series ≈ noise·√6 when the motion between reports is
    // smooth (a·T² ≪ noise at 10 Hz).
    std::map<int, std::vector<double>> series;
    for (std::size_t k = 0; k < in.size(); ++k) series[in.y[k].beacon].push_back(in.y[k].range);
    std::vector<double> sigmas;
    for (const auto& [beacon, d] : series) {
        std::vector<double> second;
        for (std::size_t k = 1; k + 1 < d.size(); ++k) second.push_back(std::abs(d[k + 1] - 2.0 * d[k] + d[k - 1]));
        if (second.size() >= 5) sigmas.push_back(1.4826 * math::median(second) / std::sqrt(6.0));
    }
    if (sigmas.empty()) return 0.01;
    const double s = math::median(sigmas);
    return std::max(s * s, 1e-5);
}

}  // namespace athlos::positioning
