#include "plugins/positioning/AnchorPipeline.h"

#include "core/math/Statistics.h"

#include <algorithm>

namespace athlos::positioning {

using math::Vec3;

Expected<AnchorPipelineResult> runAnchorPipeline(const AnchorPipelineInput& in, const AnchorPipelineParams& params,
                                                 const std::function<bool(double)>& keepGoing) {
    const std::size_t n = in.t.size();
    if (n < 10 || in.acc.size() != n || in.gyr.size() != n || in.mag.size() != n || in.orientation.size() != n)
        return makeError(QStringLiteral("the IMU and orientation streams need the same, at least 10, samples"));
    AnchorPipelineResult out;

    // Rest at the start and the finish: low angular rate and gravity-free acceleration.
    std::vector<double> gyrNorm(n), freeAcc(n);
    auto stillWith = [&](const std::vector<math::Quat>& q) {
        for (std::size_t k = 0; k < n; ++k) {
            gyrNorm[k] = in.gyr[k].norm();
            freeAcc[k] = (q[k].normalized() * in.acc[k] - params.gravity * Vec3::UnitZ()).norm();
        }
        return AnchorSmoother::startFinishStill(gyrNorm, freeAcc, params.stillGyr, params.stillAcc);
    };
    out.orientation = in.orientation;
    std::vector<unsigned char> still = stillWith(out.orientation);
    if (params.restAligned) {
        // The start rest from the stream; the finish rest from the re-integrated orientation (the
        // stream may still be tilted there), then the drift removal that uses it.
        std::vector<unsigned char> none(n, 0);
        auto first = RestAlignedStrapdown::compute(in.t, in.gyr, in.acc, in.orientation, still, none);
        if (!first) return first.error();
        const std::vector<unsigned char> finish = stillWith(*first);
        auto aligned = RestAlignedStrapdown::compute(in.t, in.gyr, in.acc, in.orientation, still, finish);
        if (!aligned) return aligned.error();
        out.orientation = std::move(*aligned);
        still = stillWith(out.orientation);
    }

    // Earth-frame magnetic field, its ambient value (component-wise median) and the anomaly e(t).
    std::vector<Vec3> magEarth(n);
    std::vector<double> mx(n), my(n), mz(n), yawRate(n);
    AnchorSmoother::Input s;
    s.t = in.t;
    s.acc.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Eigen::Matrix3d R = out.orientation[k].normalized().toRotationMatrix();
        magEarth[k] = R * in.mag[k];
        mx[k] = magEarth[k].x();
        my[k] = magEarth[k].y();
        mz[k] = magEarth[k].z();
        yawRate[k] = (R * in.gyr[k]).z();
        s.acc[k] = R * in.acc[k] - params.gravity * Vec3::UnitZ();
    }
    const Vec3 ambient(math::median(mx), math::median(my), math::median(mz));
    if (!(ambient.norm() > 0.0)) return makeError(QStringLiteral("the magnetometer reads zero"));
    out.anomaly.resize(n);
    double peak = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        out.anomaly[k] = (magEarth[k] - ambient).norm() / ambient.norm();
        peak = std::max(peak, out.anomaly[k]);
    }
    out.crossings = GateDetector(params.detector).detect(in.t, out.anomaly, yawRate);
    if (out.crossings.empty())
        return makeError(QStringLiteral("no gate crossing found (magnetometer anomaly never above the threshold %1, "
                                        "its peak is %2 of the ambient field)")
                             .arg(params.detector.threshold)
                             .arg(peak, 0, 'g', 3));

    s.still = std::move(still);
    s.crossings = out.crossings;
    s.gates = in.gates;
    s.start = in.start;
    auto smoothed = AnchorSmoother(params.smoother).run(s, keepGoing);
    if (!smoothed) return smoothed.error();
    out.smoothed = std::move(*smoothed);
    return out;
}

}  // namespace athlos::positioning
