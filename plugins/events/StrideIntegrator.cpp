#include "plugins/events/StrideIntegrator.h"

#include "core/math/QuaternionOps.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace athlos::events {

namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

struct Imu {
    const double* t;
    const double* acc;
    const double* gyr;
    std::size_t accStride, gyrStride, rows;
    Vector3d a(std::size_t k) const { return Vector3d(acc + k * accStride); }
    Vector3d w(std::size_t k) const { return Vector3d(gyr + k * gyrStride); }
};

// Mean accelerometer over [t_k − w/2, t_k + w/2]: the specific force of a still foot, i.e. "up".
Vector3d meanAcc(const Imu& imu, std::size_t k, double window) {
    Vector3d sum = Vector3d::Zero();
    int n = 0;
    for (std::size_t j = k;; --j) {
        if (imu.t[j] < imu.t[k] - 0.5 * window) break;
        sum += imu.a(j);
        ++n;
        if (j == 0) break;
    }
    for (std::size_t j = k + 1; j < imu.rows && imu.t[j] <= imu.t[k] + 0.5 * window; ++j, ++n) sum += imu.a(j);
    return sum / double(n);
}

// Eq. 1: levelled orientation with the accelerometer mean `up` and the given heading: the smallest
// rotation taking `up` to the vertical (its axis is horizontal, so it has no heading of its own),
// then the heading about the vertical.
Quaterniond levelled(const Vector3d& up, double heading) {
    const Quaterniond tilt = Quaterniond::FromTwoVectors(up, Vector3d::UnitZ());
    return (Quaterniond(Eigen::AngleAxisd(heading, Vector3d::UnitZ())) * tilt).normalized();
}

// Eq. 1 at a later mid-stance: q turned about a horizontal axis so that `up` points up. The heading
// is kept without naming a sensor axis, so this holds for any mounting.
Quaterniond relevelled(const Quaterniond& q, const Vector3d& up) {
    return (Quaterniond::FromTwoVectors(q * up, Vector3d::UnitZ()) * q).normalized();
}

// Heading change from q0 to q1: the twist about the vertical of the rotation between them (earth
// frame). The sensor's mounting cancels in q1 q0*, so no sensor axis has to be horizontal.
double headingChange(const Quaterniond& q0, const Quaterniond& q1) {
    return math::twistHeadingAngle((q1 * q0.conjugate()).normalized());
}

// Eq. 2: one gyroscope step from k to k + 1 (body-frame rotation by the mean rate).
Quaterniond step(const Imu& imu, std::size_t k, const Quaterniond& q) {
    const Vector3d w = 0.5 * (imu.w(k) + imu.w(k + 1));
    const double angle = w.norm() * (imu.t[k + 1] - imu.t[k]);
    if (angle <= 0.0) return q;
    return (q * Quaterniond(Eigen::AngleAxisd(angle, w.normalized()))).normalized();
}

}  // namespace

Eigen::Vector3d meanAccelerometer(const double* t, const double* acc, std::size_t accStride, std::size_t rows,
                                  std::size_t k, double window) {
    return meanAcc(Imu{t, acc, nullptr, accStride, 0, rows}, k, window);
}

Eigen::Quaterniond levelledOrientation(const Eigen::Vector3d& up, double heading) { return levelled(up, heading); }

FootTrajectory integrateStrides(const StrideIntegrationParams& params, const std::vector<StrideSegment>& segments,
                                const double* t, const double* acc, std::size_t accStride, const double* gyr,
                                std::size_t gyrStride, std::size_t rows) {
    FootTrajectory out;
    if (segments.empty() || rows == 0) return out;
    const Imu imu{t, acc, gyr, accStride, gyrStride, rows};
    out.first = segments.front().start;
    const std::size_t last = segments.back().end;
    out.position.assign(last - out.first + 1, Vector3d::Zero());

    // The heading runs through the whole recording: gyroscope between strides as within them.
    Quaterniond q = levelled(meanAcc(imu, out.first, params.levelWindow), 0.0);
    Vector3d position = Vector3d::Zero();
    std::size_t k = out.first;
    std::vector<Quaterniond> orientation;
    std::vector<Vector3d> velocity;
    for (const StrideSegment& s : segments) {
        for (; k < s.start; ++k) {  // between strides: orientation only, the foot stays put
            q = step(imu, k, q);
            out.position[k + 1 - out.first] = position;
        }
        const Vector3d upStart = meanAcc(imu, s.start, params.levelWindow);
        const Vector3d upEnd = meanAcc(imu, s.end, params.levelWindow);
        q = relevelled(q, upStart);
        const std::size_t n = s.end - s.start + 1;
        orientation.assign(n, q);
        for (std::size_t i = 1; i < n; ++i) orientation[i] = step(imu, s.start + i - 1, orientation[i - 1]);

        // Eq. 3: the inclination error at the end, spread linearly over the stride.
        const Quaterniond delta =
            Quaterniond::FromTwoVectors(orientation.back() * upEnd.normalized(), Vector3d::UnitZ());
        const Eigen::AngleAxisd error(delta);
        const double t0 = t[s.start], duration = t[s.end] - t0;
        for (std::size_t i = 0; i < n; ++i) {
            const double alpha = (t[s.start + i] - t0) / duration;
            orientation[i] =
                (Quaterniond(Eigen::AngleAxisd(alpha * error.angle(), error.axis())) * orientation[i]).normalized();
        }
        // Eqs. 4–6.
        const double g = 0.5 * (upStart.norm() + upEnd.norm());
        velocity.assign(n, Vector3d::Zero());
        Vector3d aPrev = orientation[0] * imu.a(s.start) - g * Vector3d::UnitZ();
        for (std::size_t i = 1; i < n; ++i) {
            const Vector3d a = orientation[i] * imu.a(s.start + i) - g * Vector3d::UnitZ();
            velocity[i] = velocity[i - 1] + 0.5 * (aPrev + a) * (t[s.start + i] - t[s.start + i - 1]);
            aPrev = a;
        }
        const Vector3d drift = velocity.back();
        for (std::size_t i = 0; i < n; ++i) velocity[i] -= (t[s.start + i] - t0) / duration * drift;
        const Vector3d origin = position;
        double maxZ = 0.0;
        for (std::size_t i = 1; i < n; ++i) {
            position += 0.5 * (velocity[i - 1] + velocity[i]) * (t[s.start + i] - t[s.start + i - 1]);
            out.position[s.start + i - out.first] = position;
            maxZ = std::max(maxZ, position.z() - origin.z());
        }
        StrideEstimate e;
        e.tStart = t0;
        e.tEnd = t[s.end];
        const Vector3d d = position - origin;
        e.length = d.head<2>().norm();
        e.height = d.z();
        e.maxClearance = maxZ - std::max(0.0, e.height);
        e.turningAngle = headingChange(orientation.front(), orientation.back());
        e.tilt = error.angle();
        e.endSpeed = drift.norm();
        out.strides.push_back(e);
        q = orientation.back();
        k = s.end;
    }
    return out;
}

}  // namespace athlos::events
