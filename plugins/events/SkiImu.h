#pragma once
// Ski-frame helpers shared by the skiing processors: rows of acc_x..z, gyr_x..z in the sensor frame
// to the ski frame (forward, left, up) given which sensor axes point forward and left.
#include "core/processing/Processor.h"
#include "plugins/events/SkiCycleAnalyzer.h"

#include <Eigen/Core>
#include <QString>
#include <vector>

namespace athlos::events {

// "x", "-x", "y", "-y", "z", "-z" → unit vector; zero vector when unknown.
Eigen::Vector3d skiAxis(const QString& name);

// acc and gyr row-major x, y, z per sample; forward and left orthogonal unit vectors.
SkiImu toSkiFrame(const std::vector<double>& t, const std::vector<double>& acc, const std::vector<double>& gyr,
                  const Eigen::Vector3d& forward, const Eigen::Vector3d& left);

// An IMU input of a skiing processor: t, acc and gyr rows (x, y, z). Errors name the input and the
// missing column or wrong unit (acc in m/s^2, gyr in rad/s).
struct ImuRows {
    std::vector<double> t, acc, gyr;
};
Expected<ImuRows> imuRowsOf(const RunContext& context, int index);

// The forward_axis and ml_axis parameters as orthogonal unit vectors; errors name the parameter.
Expected<std::pair<Eigen::Vector3d, Eigen::Vector3d>> skiAxesOf(const RunContext& context);

}  // namespace athlos::events
