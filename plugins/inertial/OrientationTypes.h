#pragma once
// Types shared by the orientation algorithms: a view on IMU samples stored row-major (as in a
// StreamData) and the per-sample outputs of a batch run, plus the one batch loop all algorithms use.
#include "core/math/QuaternionOps.h"

#include <cstddef>
#include <vector>

namespace athlos::inertial {

using math::Quat;
using math::Vec3;
using Mat3 = Eigen::Matrix3d;

// Row r of gyr is gyr[r * stride + 0..2] (rad/s); the same for acc (m/s²) and mag (µT, nullable = 6D).
struct ImuBatch {
    const double* gyr = nullptr;
    const double* acc = nullptr;
    const double* mag = nullptr;
    std::size_t rows = 0;
    std::size_t stride = 3;
};

struct OrientationTrack {
    std::vector<Quat> q;                      // sensor→earth (ENU)
    std::vector<Vec3> bias;                   // gyroscope bias estimate (rad/s), zero if not estimated
    std::vector<unsigned char> rest;          // 1 = rest detected
    std::vector<unsigned char> magDisturbed;  // 1 = magnetic disturbance detected
    void resize(std::size_t n) {
        q.resize(n);
        bias.resize(n);
        rest.resize(n);
        magDisturbed.resize(n);
    }
};

// The batch loop shared by every filter: Filter needs update(gyr, acc, mag*), quaternion(), and
// may provide bias(), restDetected(), magDisturbed().
// Rows [begin, end) into an already sized track (chunked runs can poll for cancellation).
template <class Filter>
void runRange(Filter& filter, const ImuBatch& in, OrientationTrack& out, std::size_t begin, std::size_t end) {
    for (std::size_t r = begin; r < end; ++r) {
        const std::size_t o = r * in.stride;
        const Vec3 g(in.gyr[o], in.gyr[o + 1], in.gyr[o + 2]);
        const Vec3 a(in.acc[o], in.acc[o + 1], in.acc[o + 2]);
        if (in.mag) {
            const Vec3 m(in.mag[o], in.mag[o + 1], in.mag[o + 2]);
            filter.update(g, a, &m);
        } else {
            filter.update(g, a, nullptr);
        }
        out.q[r] = filter.quaternion();
        out.bias[r] = filter.bias();
        out.rest[r] = filter.restDetected();
        out.magDisturbed[r] = filter.magDisturbed();
    }
}

template <class Filter>
void runBatch(Filter& filter, const ImuBatch& in, OrientationTrack& out) {
    out.resize(in.rows);
    runRange(filter, in, out, 0, in.rows);
}

}  // namespace athlos::inertial
