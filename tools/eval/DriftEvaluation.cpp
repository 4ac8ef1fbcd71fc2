#include "tools/eval/DriftEvaluation.h"

#include "plugins/inertial/DriftReductionProcessor.h"
#include "plugins/inertial/JointAngles.h"
#include "plugins/inertial/SegmentCalibration.h"

#include <chrono>
#include <cmath>
#include <limits>

namespace athlos::eval {

using namespace athlos::inertial;
using math::Quat;
using math::Vec3;

namespace {
// Sign of the first turn about the right-pointing axis in a squat (SegmentCalibration.h).
double squatSign(int segment) {
    switch (static_cast<BodySegment>(segment)) {
        case BodySegment::RightThigh:
        case BodySegment::LeftThigh:
            return 1.0;
        default:
            return -1.0;
    }
}
}  // namespace

DriftEvaluation evaluateDriftReduction(const DriftEvaluationOptions& options) {
    const BodySimulation sim = simulateBody(options.simulation);
    const std::size_t n = sim.t.size();
    const double ts = 1.0 / options.simulation.rate;
    DriftEvaluation result;

    // Orientation per sensor (6D).
    std::vector<DriftReduction::Segment> segments(kBodySegments);
    inertial::OrientationOptions oo = options.orientation;
    oo.useMagnetometer = false;
    for (int s = 0; s < kBodySegments; ++s) {
        const BodySensor& sensor = sim.sensors[s];
        std::vector<double> gyr(3 * n), acc(3 * n);
        for (std::size_t k = 0; k < n; ++k)
            for (int i = 0; i < 3; ++i) {
                gyr[3 * k + i] = sensor.gyr[k][i];
                acc[3 * k + i] = sensor.acc[k][i];
            }
        const ImuBatch batch{gyr.data(), acc.data(), nullptr, n, 3};
        segments[s].q = estimateOrientation(oo, batch, ts).track.q;
        segments[s].acc = sensor.acc;
        segments[s].gyr = sensor.gyr;
    }

    // Functional calibration: upright standing, then squats (spec §4). Feet keep the true mounts (they
    // do not turn in a squat: ski boots).
    std::array<Quat, kBodySegments> mounts;
    const auto rows = [&](double a, double b) {
        std::pair<std::size_t, std::size_t> r{std::size_t(std::ceil(a / ts)), std::min(n, std::size_t(b / ts))};
        return r;
    };
    const auto [s0, s1] = rows(1.0, sim.uprightEnd - 1.0);
    const auto [m0, m1] = rows(sim.squatBegin, sim.squatEnd);
    for (int s = 0; s < kBodySegments; ++s) {
        mounts[s] = sim.sensors[s].mount;
        result.calibrationAxisError[s] = std::numeric_limits<double>::quiet_NaN();
        const bool foot = s == static_cast<int>(BodySegment::RightFoot) || s == static_cast<int>(BodySegment::LeftFoot);
        if (options.trueMounts || foot || m1 <= m0) continue;
        SegmentCalibration::Params cp;
        cp.firstRotation = squatSign(s);
        auto cal = SegmentCalibration(cp).calibrate(std::span(sim.sensors[s].acc).subspan(s0, s1 - s0),
                                                    std::span(sim.sensors[s].gyr).subspan(m0, m1 - m0), ts);
        if (!cal) continue;
        mounts[s] = cal->mount;
        result.calibrationAxisError[s] =
            math::rotationVectorFromQuat(cal->mount * sim.sensors[s].mount.conjugate()).norm();
    }

    if (options.driftReduction) {
        std::vector<DriftReduction::Link> links;
        for (int j = 0; j < kBodyJoints; ++j) {
            const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
            links.push_back({static_cast<int>(info.proximal), static_cast<int>(info.distal)});
        }
        const auto start = std::chrono::steady_clock::now();
        DriftReduction::Params reduction = options.reduction;
        if (options.staticCorrectionAuto)
            reduction.staticCorrection = staticCorrectionSuits(orientationAlgorithmName(oo.algorithm));
        DriftReduction::Result r = DriftReduction(reduction).run(segments, links, ts);
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        for (int s = 0; s < kBodySegments; ++s) segments[s].q = std::move(r.q[s]);
        for (int j = 0; j < kBodyJoints; ++j) {
            const DriftReduction::HeadingStatus h = r.links[static_cast<std::size_t>(j)].heading;
            result.headingKept[j] =
                h == DriftReduction::HeadingStatus::TooFewSamples || h == DriftReduction::HeadingStatus::Incoherent;
        }
    }

    // Joint angles as the joint-angles processor computes them (heading aligned over the first 2 s).
    const auto [e0, e1] = rows(sim.motionBegin, sim.motionEnd);
    const std::size_t align = std::size_t(2.0 / ts);
    for (int j = 0; j < kBodyJoints; ++j) {
        const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
        const int p = static_cast<int>(info.proximal), d = static_cast<int>(info.distal);
        JointAngles::Params jp;
        jp.joint = info.joint;
        jp.side = info.side;
        jp.proximalMount = mounts[p];
        jp.distalMount = mounts[d];
        // After drift reduction the headings are aligned already (joint-angles --param heading=none),
        // except where drift reduction found the joint's heading unobservable and kept the input's
        // relative heading; without it, the 6D headings are aligned at the start (heading=align-start).
        jp.headingOffset =
            options.driftReduction && !result.headingKept[j]
                ? 0.0
                : JointAngles::estimateHeadingOffset(std::span(segments[p].q).first(align),
                                                     std::span(segments[d].q).first(align), mounts[p], mounts[d]);
        const JointAngles angles(jp);
        std::array<double, 3> sum{};
        for (std::size_t k = e0; k < e1; ++k) {
            const AnatomicalAngles a = angles.update(segments[p].q[k], segments[d].q[k]).angles;
            const Vec3 err = a.vector() - sim.joints[j].angles[k].vector();
            for (int i = 0; i < 3; ++i) sum[i] += math::wrapAngle(err[i]) * math::wrapAngle(err[i]);
        }
        for (int i = 0; i < 3; ++i)
            result.joints[j].rmse[i] = std::sqrt(sum[i] / double(std::max<std::size_t>(1, e1 - e0)));
    }
    for (int s = 0; s < kBodySegments; ++s) {
        double sum = 0.0;
        for (std::size_t k = e0; k < e1; ++k) {
            // Inclination error only: the 6D heading is arbitrary.
            const Vec3 up = segments[s].q[k].conjugate() * Vec3::UnitZ();
            const Vec3 trueUp = sim.sensors[s].sensor[k].conjugate() * Vec3::UnitZ();
            sum += std::acos(std::clamp(up.dot(trueUp), -1.0, 1.0));
        }
        result.orientationError[s] = sum / double(std::max<std::size_t>(1, e1 - e0));
    }
    return result;
}

}  // namespace athlos::eval
