#include "tools/eval/AnchorEvaluation.h"

#include "core/math/Angles.h"
#include "plugins/inertial/OrientationEstimation.h"

#include <cmath>

namespace athlos::positioning {

using math::Vec3;

Expected<AnchorScore> evaluateAnchorRun(const AnchorEvalOptions& o) {
    const auto sim = GateRunSimulator::simulate(o.simulation);
    const std::size_t n = sim.t.size();

    std::vector<double> gyr(3 * n), acc(3 * n), mag(3 * n);
    for (std::size_t k = 0; k < n; ++k)
        for (int i = 0; i < 3; ++i) {
            gyr[3 * k + i] = sim.gyr[k][i];
            acc[3 * k + i] = sim.acc[k][i];
            mag[3 * k + i] = sim.mag[k][i];
        }
    inertial::ImuBatch batch{gyr.data(), acc.data(), o.useMagnetometer ? mag.data() : nullptr, n, 3};
    inertial::OrientationOptions orientationOptions;
    orientationOptions.useMagnetometer = o.useMagnetometer;
    orientationOptions.offline = o.offlineOrientation;
    orientationOptions.filter.tauAcc = o.tauAcc;
    auto orientation = inertial::estimateOrientation(orientationOptions, batch, 1.0 / o.simulation.imuRate);
    if (o.truthOrientation) orientation.track.q = sim.orientation;

    AnchorPipelineInput in;
    in.t = sim.t;
    in.acc = sim.acc;
    in.gyr = sim.gyr;
    in.mag = sim.mag;
    in.orientation = orientation.track.q;
    for (std::size_t g = 0; g < sim.gates.size(); g += std::size_t(std::max(1, o.keepEveryGate)))
        in.gates.push_back(sim.gates[g]);
    if (o.giveStart) in.start = sim.position.front();
    auto run = runAnchorPipeline(in, o.pipeline);
    if (!run) return run.error();
    AnchorScore score;
    double tilt2 = 0.0, head2 = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const math::Quat e = run->orientation[k] * sim.orientation[k].conjugate();
        tilt2 += std::pow(math::inclinationAngle(e) / math::kDeg, 2);
        head2 += std::pow(math::wrapAngle(math::headingAngle(e)) / math::kDeg, 2);
    }
    score.tiltRmse = std::sqrt(tilt2 / double(n));
    score.headingRmse = std::sqrt(head2 / double(n));

    const auto& r = run->smoothed;
    score.gates = int(in.gates.size());
    score.crossings = int(run->crossings.size());
    score.matched = int(r.matches.size());
    score.azimuthOffset = r.azimuthOffset;

    const double t0 = sim.gateTimes.front(), t1 = sim.gateTimes.back();
    double sumP = 0.0, sumS = 0.0, sumS2 = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < r.t.size(); ++k) {
        const double t = r.t[k];
        if (t < t0 || t > t1) continue;
        const double f = (t - sim.t.front()) * o.simulation.imuRate;
        const std::size_t i = std::min(n - 2, std::size_t(std::max(0.0, std::floor(f))));
        const double w = std::clamp(f - double(i), 0.0, 1.0);
        const Vec3 p = (1.0 - w) * sim.position[i] + w * sim.position[i + 1];
        const Vec3 v = (1.0 - w) * sim.velocity[i] + w * sim.velocity[i + 1];
        sumP += (r.position[k] - p).squaredNorm();
        const double ds = r.velocity[k].norm() - v.norm();
        sumS += ds;
        sumS2 += ds * ds;
        ++count;
    }
    if (count < 2) return makeError(QStringLiteral("no smoothed samples between the first and the last gate"));
    score.positionRmse = std::sqrt(sumP / count);
    score.speedMean = sumS / count;
    score.speedSd = std::sqrt(std::max(0.0, sumS2 / count - score.speedMean * score.speedMean));
    return score;
}

}  // namespace athlos::positioning
