#pragma once
// The sampling rate of an IMU recording whose file gives only a sample index (gaitmap's index
// columns), found from the motion itself: the rate that makes the gyroscope and the accelerometer
// agree. Between two still samples the strapdown velocity must come back to zero; how far it
// misses depends on the rate through the orientation only — a wrong Δt turns every swing by the
// wrong angle, so gravity leaks into the velocity — and not through the plain Δt scaling of
// ∫(R a − g) dt, which is removed by dividing by the path ∫|R a − g| dt:
//
//   score(f) = median over segments of |Σ (R_k a_k − g e_z) Δt| / Σ |R_k a_k − g e_z| Δt,  Δt = 1/f,
//
// R_k the orientation levelled from the accelerometer at the segment's first still sample and
// integrated with the gyroscope (q_{k+1} = q_k ⊗ Exp(ω_k Δt)), g the median accelerometer norm of
// the still samples. The score is dimensionless and about 0.1 at the true rate of a walk; it is
// summed over the streams of the file (the feet move differently, the rate is one). A still sample:
// |ω| < `stillRate` and ||a| − g| < `stillAccTolerance`.
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"

#include <vector>

namespace athlos {

class ImuSamplingRate {
public:
    struct Params {
        double stillRate = 0.6;          // rad/s (34 °/s): a foot in stance, not the swing
        double stillAccTolerance = 0.5;  // m/s²
        int minSegmentSamples = 6;       // samples between two still samples for a segment to count
        int minSegments = 5;             // fewer: no estimate
    };

    struct Imu {
        std::vector<math::Vec3> acc;  // m/s², sensor frame, one per sample
        std::vector<math::Vec3> gyr;  // rad/s
    };

    struct Candidate {
        double rate = 0.0;  // Hz
        double score = 0.0;
        int segments = 0;
    };

    ImuSamplingRate() = default;
    explicit ImuSamplingRate(const Params& params) : params_(params) {}

    // The score of every candidate rate (summed over the IMUs; lower is better), in the order given.
    std::vector<Candidate> scores(const std::vector<Imu>& imus, const std::vector<double>& rates) const;
    // The candidate with the lowest score; an error when no IMU has `minSegments` still-to-still
    // segments (e.g. no stance at all) or no rate is given.
    Expected<Candidate> best(const std::vector<Imu>& imus, const std::vector<double>& rates) const;
    // The same from scores() already computed (the importer reports them all).
    Expected<Candidate> best(const std::vector<Candidate>& scored) const;

private:
    Params params_;
};

}  // namespace athlos
