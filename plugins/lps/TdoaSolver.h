#pragma once
// Per-instant TDoA fix (thesis Eqn. 2.5):
//   (m̂, ô) = argmin Σ_i w_i ρ( |m − b_i| − y_i − o ),   y_i = c·Δt_i + |r − b_i|,   o = −c·t_off (Tdoa.h)
// so that the summand is the residual e_i of Eqn. 3.1. Planar mode fixes the tag height
// (unknowns x, y, o: at least 3 beacons, 4 for an over-determined fix); spatial mode also solves z.
//
// Backends. The hot path is ceres::TinySolver (Ceres' dense Levenberg–Marquardt for tiny problems,
// fixed-size Eigen normal equations, no allocation per fix once sized): about 1–2 µs per 12-beacon
// fix. A full ceres::Problem costs tens of µs of set-up per fix (bench/bench_lps.cpp measures both),
// too slow for ≥ 50 000 fixes/s, so it is used only where it adds something: robust loss functions
// (Huber, Cauchy) via ceres::LossFunction.
#include "plugins/lps/Tdoa.h"

#include <memory>
#include <optional>

namespace athlos::lps {

// The readings of one instant in solver form. assign() reuses the vectors' storage.
struct FixInput {
    double t = 0.0;
    std::vector<Vector3> beacons;
    std::vector<double> ranges;   // y_i (m)
    std::vector<double> weights;  // w_i ≥ 0; 0 excludes the beacon
    std::vector<int> index;       // beacon index in the layout

    // referenceDistance[i] = |r − b_i| for every beacon of the layout.
    void assign(const TdoaEpoch& epoch, const BeaconLayout& layout, const std::vector<double>& referenceDistance);
    int size() const { return static_cast<int>(ranges.size()); }
    int activeCount() const;
    void setAllWeights(double w) { weights.assign(ranges.size(), w); }
};

std::vector<double> referenceDistances(const BeaconLayout& layout);

class TdoaSolver {
public:
    enum class Geometry { Planar, Spatial };
    enum class Loss { None, Huber, Cauchy };

    struct Params {
        Geometry geometry = Geometry::Planar;
        double tagHeight = 1.2;  // m, planar mode
        Loss loss = Loss::None;  // != None uses a ceres::Problem per fix
        double lossScale = 0.5;  // m, where the robust loss leaves the quadratic regime
        int maxIterations = 30;
        // A warm-started fix whose RMS residual exceeds this is re-solved from the closed-form start
        // and the lower-cost solution kept (guards against TDoA's secondary minima).
        double retryResidual = 2.0;  // m
        // A fix farther from the beacons' centroid than this factor times the beacons' largest
        // distance from it is invalid: with one-sided geometry a bad reading can send the solution
        // along a diverging hyperbola branch, hundreds of metres off.
        double maxSpread = 1.5;
    };

    TdoaSolver();
    explicit TdoaSolver(const Params& params);
    ~TdoaSolver();
    TdoaSolver(TdoaSolver&&) noexcept;
    TdoaSolver& operator=(TdoaSolver&&) noexcept;

    const Params& params() const { return params_; }
    int unknowns() const { return params_.geometry == Geometry::Planar ? 3 : 4; }

    // Solves one instant; start = a previous fix (warm start) or nullptr (closed-form start).
    TagFix solve(const FixInput& input, const TagFix* start = nullptr);

    // Closed-form start: differencing the squared range equations |m − b_i|² = (y_i + o)² against
    // one beacon gives equations linear in (m, o) (spherical-interpolation idea of Smith & Abel).
    std::optional<TagFix> linearStart(const FixInput& input) const;

    // Residuals e_i (Eqn. 3.1) of every reading at (m, o), weights ignored.
    static void residuals(const FixInput& input, const Vector3& m, double offset, std::vector<double>& e);
    // sqrt(Σ w e² / Σ w) over readings with w > 0.
    static double weightedRms(const FixInput& input, const std::vector<double>& e);

private:
    TagFix solveTiny(const FixInput& input, const TagFix& start);
    TagFix solveCeres(const FixInput& input, const TagFix& start) const;
    TagFix finish(const FixInput& input, const Vector3& m, double offset);
    bool plausible(const FixInput& input, const Vector3& m) const;

    struct Tiny;
    Params params_;
    std::unique_ptr<Tiny> tiny_;
    std::vector<double> scratch_;
};

}  // namespace athlos::lps
