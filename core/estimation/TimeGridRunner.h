#pragma once
// The robust Kalman framework of thesis §4.1 around any filter (Ekf, Ukf, SrUkf):
//  - non-uniform input, output on any requested time grid: at an observation time predict + update,
//    at an output time without a valid observation predict only (variable T_k, Fig. 4.3);
//  - long steps are split into sub-steps ≤ maxStep (smaller linearisation errors, and a constrained
//    model re-reads the track geometry while it coasts through an outage);
//  - Mahalanobis gating: d_k² > α ⇒ the observation is an outlier and the update is skipped;
//  - re-acquisition: gating alone can lock a filter out for good once its prediction is off by more
//    than the gate (a lane change the model cannot follow, a long outage). When the last
//    `reacquireCount` consecutive rejected innovations lie on a straight line in time within the
//    measurement noise (outliers scatter, a lost track drifts smoothly), the covariance is inflated
//    until the current observation passes the gate;
//  - optional RTS or fixed-lag smoothing (lag in seconds) over the stored forward pass.
// Per input sample it reports d_k², log det Σ_k and the accept flag, which the noise estimator
// (eq. 4.13) and the processor's outlier output use.
#include "core/estimation/RtsSmoother.h"

#include <algorithm>
#include <functional>
#include <vector>

namespace athlos::estimation {

enum class Smoothing { None, Rts, FixedLag };

// What the runner hands to Filter::update(): the measurement vector, or the filter's own Observation
// type when it has one (e.g. a range with the index of its beacon).
template <class Filter>
struct ObservationOf {
    using type = Vector<Filter::M>;
};
template <class Filter>
requires requires { typename Filter::Observation; }
struct ObservationOf<Filter> {
    using type = typename Filter::Observation;
};

template <class Filter>
class TimeGridRunner {
public:
    static constexpr int N = Filter::N;
    static constexpr int M = Filter::M;
    using Model = typename Filter::ModelType;
    using StateVector = Vector<N>;
    using StateMatrix = Matrix<N, N>;
    using Measurement = Vector<M>;
    using Observation = typename ObservationOf<Filter>::type;

    struct Params {
        double gate = kNoGate;  // α on d²
        Smoothing smoothing = Smoothing::None;
        double lag = 0.5;                   // s, fixed-lag smoothing
        double maxStep = kNoGate;           // s, longest single prediction step
        bool covariance = false;            // also return P at the output times
        int reacquireCount = 8;             // consecutive rejections tested for consistency; 0 = off
        double reacquireConsistency = 4.0;  // max mean squared residual of the line fit, in units of R
    };

    struct SampleDiagnostics {
        double mahalanobis2 = 0.0;
        double logDetSigma = 0.0;
        bool accepted = true;
    };

    struct Result {
        std::vector<double> t;
        std::vector<StateVector> x;
        std::vector<StateMatrix> P;              // only with Params::covariance
        std::vector<SampleDiagnostics> samples;  // one per input sample
    };

    // Progress callback: fraction done of the forward pass; returning false cancels (run() then
    // returns an empty Result).
    using ProgressFn = std::function<bool(double)>;

    explicit TimeGridRunner(Params params) : params_(params) {}

    // The filter must be reset() to its state at time t0 (≤ tIn[0]). tOut empty = output at tIn.
    Result run(Filter& filter, double t0, const std::vector<double>& tIn, const std::vector<Observation>& y,
               const std::vector<double>& tOut, const ProgressFn& progress = {}) const {
        const std::vector<double>& grid = tOut.empty() ? tIn : tOut;
        const bool store = params_.smoothing != Smoothing::None;
        Result result;
        result.samples.resize(tIn.size());
        result.t = grid;
        result.x.reserve(grid.size());
        if (params_.covariance) result.P.reserve(grid.size());
        std::vector<SmootherNode<N>> nodes;
        std::vector<std::size_t> outputNode;  // node index of each output sample (smoothing only)
        if (store) {
            nodes.reserve(tIn.size() + grid.size() + 16);
            outputNode.reserve(grid.size());
            nodes.push_back(
                {t0, filter.x(), filter.covariance(), filter.x(), filter.covariance(), StateMatrix::Zero()});
        }

        double now = t0;
        std::vector<Rejected> streak;
        std::size_t i = 0, j = 0, events = 0;
        const std::size_t total = tIn.size() + grid.size();
        while (i < tIn.size() || j < grid.size()) {
            const double tNext = j >= grid.size() || (i < tIn.size() && tIn[i] <= grid[j]) ? tIn[i] : grid[j];
            advance(filter, now, tNext, nodes, store);
            // Observations at tNext first, so an output at the same instant includes them.
            while (i < tIn.size() && tIn[i] <= tNext) {
                Innovation inn = filter.update(y[i], tIn[i], params_.gate);
                result.samples[i] = {inn.mahalanobis2, inn.logDetSigma, inn.accepted};
                if (inn.accepted) {
                    streak.clear();
                } else if (params_.reacquireCount > 0) {
                    streak.push_back({tIn[i], filter.residual()});
                    if (int(streak.size()) > params_.reacquireCount) streak.erase(streak.begin());
                    if (int(streak.size()) == params_.reacquireCount && consistent(streak, filter.model(), tIn[i])) {
                        for (int n = 0; n < 16 && !inn.accepted; ++n) {
                            filter.inflate(4.0);
                            inn = filter.update(y[i], tIn[i], params_.gate);
                        }
                        result.samples[i].accepted = inn.accepted;
                        streak.clear();
                    }
                }
                ++i;
            }
            if (store) {
                nodes.back().xf = filter.x();
                nodes.back().Pf = filter.covariance();
            }
            while (j < grid.size() && grid[j] <= tNext) {
                result.x.push_back(filter.x());
                if (params_.covariance) result.P.push_back(filter.covariance());
                if (store) outputNode.push_back(nodes.size() - 1);
                ++j;
            }
            if (progress && (++events & 1023) == 0 && !progress(double(i + j) / double(total))) return {};
        }
        if (store) smooth(filter.model(), nodes, outputNode, result);
        return result;
    }

private:
    struct Rejected {
        double t;
        Measurement z;
    };

    // Least-squares line z(t) = z₀ + ż t through the rejected innovations; their residual scatter,
    // in units of R, tells a drifting lost track (small) from an outlier burst (large).
    bool consistent(const std::vector<Rejected>& streak, const Model& model, double t) const {
        const auto R = model.measurementNoise(t);
        double tMean = 0.0;
        Measurement zMean = Measurement::Zero();
        for (const auto& r : streak) {
            tMean += r.t / double(streak.size());
            zMean += r.z / double(streak.size());
        }
        double stt = 0.0;
        Measurement szt = Measurement::Zero();
        for (const auto& r : streak) {
            stt += (r.t - tMean) * (r.t - tMean);
            szt += (r.t - tMean) * (r.z - zMean);
        }
        const Measurement slope = stt > 0 ? Measurement(szt / stt) : Measurement::Zero();
        double scatter = 0.0;
        for (const auto& r : streak) {
            const Measurement e = r.z - zMean - slope * (r.t - tMean);
            scatter += (e.array().square() / R.diagonal().array()).sum();
        }
        return scatter / double(streak.size() * M) <= params_.reacquireConsistency;
    }

    void advance(Filter& filter, double& now, double target, std::vector<SmootherNode<N>>& nodes, bool store) const {
        while (target > now) {
            const double T = std::min(target - now, params_.maxStep);
            // Land exactly on target (no accumulated rounding in the last sub-step).
            const double tEnd = target - now - T <= 1e-12 ? target : now + T;
            const StateMatrix C = filter.predict(tEnd - now, tEnd);
            now = tEnd;
            if (store) nodes.push_back({now, filter.x(), filter.covariance(), filter.x(), filter.covariance(), C});
        }
    }

    void smooth(const Model& model, std::vector<SmootherNode<N>>& nodes, const std::vector<std::size_t>& outputNode,
                Result& result) const {
        const RtsSmoother<Model> smoother(model);
        if (params_.smoothing == Smoothing::Rts) {
            smoother.smoothAll(nodes);
            for (std::size_t k = 0; k < outputNode.size(); ++k) {
                result.x[k] = nodes[outputNode[k]].xf;
                if (params_.covariance) result.P[k] = nodes[outputNode[k]].Pf;
            }
            return;
        }
        // Fixed lag: x(t | t + lag) from a short backward pass starting at the last node ≤ t + lag.
        std::size_t horizon = 0;
        for (std::size_t k = 0; k < outputNode.size(); ++k) {
            const std::size_t target = outputNode[k];
            horizon = std::max(horizon, target);
            while (horizon + 1 < nodes.size() && nodes[horizon + 1].t <= nodes[target].t + params_.lag) ++horizon;
            const auto e = smoother.smoothAt(nodes, target, horizon);
            result.x[k] = e.x;
            if (params_.covariance) result.P[k] = e.P;
        }
    }

    Params params_;
};

}  // namespace athlos::estimation
