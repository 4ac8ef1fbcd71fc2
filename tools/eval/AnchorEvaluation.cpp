#include "tools/eval/AnchorEvaluation.h"

#include "core/math/Angles.h"
#include "plugins/inertial/OrientationEstimation.h"
#include "plugins/positioning/GateAveraging.h"

#include <complex>

#include <cmath>

namespace athlos::positioning {

using math::Vec3;

namespace {

std::vector<math::Quat> vqfOrientation(const GateRunSimulator::Result& sim, const AnchorEvalOptions& o) {
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
    return o.truthOrientation ? sim.orientation : orientation.track.q;
}

// Horizontal errors of estimated gates after the similarity that maps their first and last onto the truth's.
std::vector<double> alignedErrors(const std::vector<Vec3>& est, const std::vector<Gate>& truth) {
    using C = std::complex<double>;
    const C f(est.front().x(), est.front().y()), l(est.back().x(), est.back().y());
    const C F(truth.front().position.x(), truth.front().position.y()),
        L(truth.back().position.x(), truth.back().position.y());
    const C a = (L - F) / (l - f);
    std::vector<double> e;
    for (std::size_t m = 0; m < est.size(); ++m)
        e.push_back(
            std::abs(F + a * (C(est[m].x(), est[m].y()) - f) - C(truth[m].position.x(), truth[m].position.y())));
    return e;
}

}  // namespace

Expected<GateAverageScore> evaluateGateAveraging(AnchorEvalOptions o, int runs, std::uint64_t seed0) {
    o.simulation.courseSeed = 1000 + seed0;
    o.pipeline.smoother.passes = 0;
    std::vector<std::vector<Vec3>> estimates;
    std::vector<Gate> truth;
    GateAverageScore score;
    for (int r = 0; r < runs; ++r) {
        o.simulation.seed = seed0 + std::uint64_t(r);
        const auto sim = GateRunSimulator::simulate(o.simulation);
        AnchorPipelineInput in;
        in.t = sim.t;
        in.acc = sim.acc;
        in.gyr = sim.gyr;
        in.mag = sim.mag;
        in.orientation = vqfOrientation(sim, o);
        in.gates = sim.gates;
        auto run = runAnchorPipeline(in, o.pipeline);
        if (!run) return run.error();
        if (run->smoothed.inertialGates.size() != sim.gates.size())
            return makeError(QStringLiteral("run %1: %2 crossings for %3 gates")
                                 .arg(r + 1)
                                 .arg(run->smoothed.inertialGates.size())
                                 .arg(sim.gates.size()));
        estimates.push_back(run->smoothed.inertialGates);
        truth = sim.gates;
        double sum = 0.0;
        for (double e : alignedErrors(estimates.back(), truth)) sum += e;
        score.singleMean += sum / double(truth.size()) / runs;
    }
    auto mean = GateAveraging::average(estimates);
    if (!mean) return mean.error();
    const auto errors = alignedErrors(*mean, truth);
    for (double e : errors) {
        score.averagedMean += e / double(errors.size());
        score.averagedMax = std::max(score.averagedMax, e);
    }
    return score;
}

Expected<AnchorScore> evaluateAnchorRun(const AnchorEvalOptions& o) {
    const auto sim = GateRunSimulator::simulate(o.simulation);
    const std::size_t n = sim.t.size();
    const std::vector<math::Quat> orientation = vqfOrientation(sim, o);

    AnchorPipelineInput in;
    in.t = sim.t;
    in.acc = sim.acc;
    in.gyr = sim.gyr;
    in.mag = sim.mag;
    in.orientation = orientation;
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
