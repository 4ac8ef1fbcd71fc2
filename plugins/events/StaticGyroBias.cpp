#include "plugins/events/StaticGyroBias.h"

#include "plugins/events/StrideSegmenter.h"

namespace athlos::events {

StaticGyroBias estimateStaticGyroBias(const double* t, const double* gyr, std::size_t rows, std::size_t stride,
                                      double window, double threshold, double minDuration) {
    StaticGyroBias out;
    if (rows < 2 || minDuration <= 0.0) return out;
    const std::vector<double> rest = meanGyroNorm(t, gyr, rows, stride, window);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    std::size_t count = 0;
    for (std::size_t k = 0; k < rows;) {
        if (rest[k] >= threshold) {
            ++k;
            continue;
        }
        std::size_t end = k;
        while (end + 1 < rows && rest[end + 1] < threshold) ++end;
        if (t[end] - t[k] >= minDuration) {
            for (std::size_t j = k; j <= end; ++j) sum += Eigen::Vector3d(gyr + j * stride);
            count += end - k + 1;
            out.staticTime += t[end] - t[k];
        }
        k = end + 1;
    }
    if (count) out.bias = sum / double(count);
    return out;
}

}  // namespace athlos::events
