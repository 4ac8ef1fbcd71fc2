#pragma once
// Gyroscope bias from the standing phases of a recording: the mean angular rate over the samples
// of every stretch of at least minDuration seconds whose gyroscope norm, averaged over `window`,
// stays below `threshold` (gaitmap NormZuptDetector's static threshold: 15 deg/s over 0.15 s). A
// standing foot does not rotate, so what the gyroscope reads there is its bias; heading, which
// gravity cannot correct, drifts with it otherwise (0.02 rad/s → 1.3° per 1.1 s stride).
#include <Eigen/Core>
#include <cstddef>

namespace athlos::events {

struct StaticGyroBias {
    Eigen::Vector3d bias = Eigen::Vector3d::Zero();  // rad/s
    double staticTime = 0.0;                         // s of standing used (0: none, bias zero)
};

StaticGyroBias estimateStaticGyroBias(const double* t, const double* gyr, std::size_t rows, std::size_t stride,
                                      double window, double threshold, double minDuration);

}  // namespace athlos::events
