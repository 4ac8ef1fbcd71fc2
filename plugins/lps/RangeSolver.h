#pragma once
// Per-instant ToA fix from two-way ranges (issue #16 item 1):
//   m̂ = argmin Σ w_i (|m − b_i| − d_i)²                      (thesis eq. 2.4, no clock offset)
// with m = [x, y, tag_height] (planar) or [x, y, z] (spatial), Gauss–Newton through Ceres'
// TinySolver from a warm start or the closed form of the differenced squared ranges
// (|m − b_i|² − |m − b_0|² = d_i² − d_0² is linear in m). Beacon selection against NLOS: all, or
// IRLS with Tukey's bisquare at k·1.4826·MAD of the residuals (the TDoA default of §3.2).
#include "plugins/lps/Tdoa.h"

#include <memory>
#include <optional>

namespace athlos::lps {

struct RangeFixInput {
    double t = 0.0;
    std::vector<Vector3> beacons;
    std::vector<double> ranges;   // d_i (m)
    std::vector<double> weights;  // w_i ≥ 0
    std::vector<int> index;       // beacon index in the layout
    void assign(const TdoaEpoch& epoch, const BeaconLayout& layout);
    int size() const { return int(ranges.size()); }
};

class RangeSolver {
public:
    enum class Geometry { Planar, Spatial };
    enum class Selection { All, Irls };

    struct Params {
        Geometry geometry = Geometry::Planar;
        double tagHeight = 1.0;  // m, planar
        Selection selection = Selection::Irls;
        double irlsK = 2.5;          // bisquare cut-off in units of 1.4826·MAD
        double irlsMinScale = 0.05;  // m, floor of the residual scale (noise-free data)
        int irlsIterations = 5;
        int maxIterations = 30;
        double maxResidual = 2.0;  // m, a fix whose weighted RMS residual exceeds this is refused
    };

    RangeSolver();
    explicit RangeSolver(const Params& params);
    ~RangeSolver();
    RangeSolver(RangeSolver&&) noexcept;
    RangeSolver& operator=(RangeSolver&&) noexcept;

    // One instant; start = the previous fix (warm start) or nullptr. TagFix::offset is 0 (no clock offset),
    // beaconsUsed counts the readings with weight ≥ 0.5 after the selection.
    TagFix solve(RangeFixInput input, const TagFix* start = nullptr);
    std::optional<Vector3> linearStart(const RangeFixInput& input) const;
    int unknowns() const { return params_.geometry == Geometry::Planar ? 2 : 3; }

private:
    TagFix solveWeighted(const RangeFixInput& input, const Vector3& start);

    struct Tiny;
    Params params_;
    std::unique_ptr<Tiny> tiny_;
};

}  // namespace athlos::lps
