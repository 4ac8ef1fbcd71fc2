#pragma once
// Zero-velocity-aided integration of a foot-mounted IMU over strides (StrideSegmenter), the
// classic ZUPT stride-length method (Foxlin 2005; Skog et al. 2010; digest
// inertial-biomechanics.md §2, "the same idea on a foot-mounted IMU"). Per stride [k0, k1], both
// ends mid-stances where the foot is still:
//  1. orientation at k0 levelled from gravity: the mean accelerometer over levelWindow is the
//     world up axis in the sensor frame (eq. 1: q_tilt = shortest rotation taking â to e_z); the
//     heading is carried over from the previous stride (through the gyroscope between strides);
//  2. gyroscope integration q_{k+1} = q_k ⊗ exp(½ ω̄_k Δt), ω̄_k the mean of ω_k and ω_{k+1}
//     (eq. 2); at k1 the inclination error δ (shortest rotation taking R_k1·â_k1 to e_z) is spread
//     linearly over the stride, q'_k = exp(α_k log δ) ⊗ q_k with α_k = (t_k − t_0)/(t_1 − t_0)
//     (eq. 3; the thesis's linear drift spreading between static instants);
//  3. gravity removal in the world frame, a_w = R'_k a_k − g e_z, g the mean accelerometer norm
//     at the two mid-stances (absorbs a scale error of the accelerometer) (eq. 4);
//  4. velocity by trapezoidal integration, minus the linear drift that makes it zero at both ends,
//     v'_k = v_k − α_k v_k1 (eq. 5), position by trapezoidal integration of v' (eq. 6).
// The positions are in a world frame: z up, x the sensor's heading at the first mid-stance,
// origin at the first mid-stance; between strides the foot is held where the last stride ended.
#include "plugins/events/StrideSegmenter.h"

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace athlos::events {

struct StrideIntegrationParams {
    double levelWindow = 0.15;  // s: accelerometer mean for levelling at a mid-stance
};

struct StrideEstimate {
    double tStart = 0.0, tEnd = 0.0;  // s (mid-stances)
    double length = 0.0;              // m, horizontal displacement
    double height = 0.0;              // m, vertical displacement (end − start)
    double maxClearance = 0.0;        // m, max height above the higher of the two mid-stance heights
    double turningAngle = 0.0;        // rad, heading change, counter-clockwise (seen from above) positive
    double tilt = 0.0;                // rad, inclination error corrected at the end (δ's angle)
    double endSpeed = 0.0;            // m/s, velocity drift removed at the end (|v_k1|)
};

struct FootTrajectory {
    std::size_t first = 0;                  // input sample of positions[0]
    std::vector<Eigen::Vector3d> position;  // m, one per input sample from `first`
    std::vector<StrideEstimate> strides;    // one per segment
};

// acc/gyr: acc_x / gyr_x of the first sample (m/s², rad/s), accStride/gyrStride doubles between samples.
FootTrajectory integrateStrides(const StrideIntegrationParams& params, const std::vector<StrideSegment>& segments,
                                const double* t, const double* acc, std::size_t accStride, const double* gyr,
                                std::size_t gyrStride, std::size_t rows);

// Mean accelerometer over [t_k − window/2, t_k + window/2]: the specific force of a still foot ("up").
Eigen::Vector3d meanAccelerometer(const double* t, const double* acc, std::size_t accStride, std::size_t rows,
                                  std::size_t k, double window);
// Eq. 1: the orientation whose z axis is the measured `up`, with the given heading (rad).
Eigen::Quaterniond levelledOrientation(const Eigen::Vector3d& up, double heading);

}  // namespace athlos::events
