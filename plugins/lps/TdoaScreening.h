#pragma once
// Screening of a whole TDoA recording before the per-instant fixes (thesis §3.2.3, Fig. 3.16 methods 2
// and 3): both assume that a beacon's TDoA varies smoothly while the tag follows a continuous
// movement, so a rapid change of its rate is an NLOS error, and drop such readings (weight 0).
//   GrubbsRate  method 2: per beacon, the rate of change (Δt_k − Δt_{k−1})/(t_k − t_{k−1}) of
//               consecutive readings; outliers found off-line by the two-sided Grubbs test
//               (Grubbs 1969, RobustStatistics.h) at significance α = 0.05, repeated while at least
//               `minSamples` rates remain; the reading a flagged rate leads into is dropped.
//   KalmanGate  method 3: per beacon, a linear Kalman filter with a constant-velocity model tracks
//               c·Δt (m); a reading whose squared Mahalanobis distance to the prediction exceeds the
//               gate is dropped and does not update the filter (Ting 2007; threshold by grid search,
//               `athlos-eval-lps --grid gate=…`). After `maxRejected` seconds of rejections in a row
//               the filter restarts on the next reading.
#include "plugins/lps/Tdoa.h"

namespace athlos::lps {

class TdoaScreening {
public:
    enum class Method { None, GrubbsRate, KalmanGate };

    struct Params {
        Method method = Method::None;
        double alpha = 0.05;        // Grubbs significance level (thesis §3.2.3)
        double maxGap = 1.0;        // s; consecutive readings farther apart start a new rate series / filter
        int minSamples = 12;        // Grubbs' t quantile needs N − 2 ≥ 10 degrees of freedom
        double gate = 9.0;          // d² threshold of KalmanGate (grid search on seed 777, docs/validation/lps.md)
        double accelDensity = 4.0;  // m²/s³, white-noise acceleration of c·Δt (a runner's ≤ 5 m/s²)
        double measurementVariance = 0.01;  // m², (0.1 m)² TDoA noise as range
        double maxRejected = 1.0;           // s
    };

    explicit TdoaScreening(const Params& params) : p_(params) {}

    // The epochs without the dropped readings; `dropped` (optional) counts them.
    std::vector<TdoaEpoch> screen(const std::vector<TdoaEpoch>& epochs, int beacons, int* dropped = nullptr) const;

private:
    std::vector<std::vector<char>> grubbsFlags(const std::vector<TdoaEpoch>& epochs, int beacons) const;
    std::vector<std::vector<char>> kalmanFlags(const std::vector<TdoaEpoch>& epochs, int beacons) const;
    Params p_;
};

}  // namespace athlos::lps
