#pragma once
// IMU calibration (Fasel thesis ch. 2, spec §1):
//  - gyroscope offset: mean of static samples;
//  - accelerometer offset and scale from static positions (the six-position method of Ferraris et al.
//    1995 generalised to any ≥ 6 positions): a_m = s ⊙ a + o with |a| = g, least squares (Ceres);
//  - magnetometer hard/soft iron: m_cal = A (m − b), A symmetric, fitted so that |m_cal| is constant
//    (ellipsoid → sphere, Ceres), the sphere radius kept at the ellipsoid's geometric-mean radius;
//  - saturation: samples at (or, with no range given, flat-topped at) the measuring range.
#include "plugins/inertial/OrientationTypes.h"

#include <optional>
#include <vector>

namespace athlos::inertial {

struct AccCalibration {
    Vec3 offset = Vec3::Zero();  // m/s²
    Vec3 scale = Vec3::Ones();   // 1
    double rms = 0.0;            // m/s², residual of |a| − g
    Vec3 apply(const Vec3& a) const { return (a - offset).cwiseQuotient(scale); }
};

struct MagCalibration {
    Vec3 hardIron = Vec3::Zero();      // µT
    Mat3 softIron = Mat3::Identity();  // A, symmetric
    double radius = 0.0;               // µT, field magnitude after calibration
    double rms = 0.0;                  // µT, residual of |m_cal| − radius
    Vec3 apply(const Vec3& m) const { return softIron * (m - hardIron); }
};

// The static positions (means of rest segments) must include each axis near +g and −g.
std::optional<AccCalibration> calibrateAccelerometer(const std::vector<Vec3>& staticMeans, double gravity);
// Needs samples spread over many directions (3D coverage); nullopt when they are not or the fit fails.
std::optional<MagCalibration> calibrateMagnetometer(const std::vector<Vec3>& samples);

// Rest segments of at least minDuration (s) found with RestDetector: per segment, the sample range
// and the mean accelerometer and gyroscope.
struct StaticSegment {
    std::size_t begin = 0, end = 0;
    Vec3 acc = Vec3::Zero(), gyr = Vec3::Zero();
};
std::vector<StaticSegment> findStaticSegments(const ImuBatch& imu, double ts, double minDuration);

// Number of saturated samples per axis: |x| ≥ 0.995·range, or with range ≤ 0 the number of samples
// equal to the column's extreme value when that value repeats ≥ 3 times in a row (clipping).
Eigen::Vector3i countSaturated(const double* values, std::size_t rows, std::size_t stride, double range);

}  // namespace athlos::inertial
