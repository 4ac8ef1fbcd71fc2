#include "tools/eval/BodyComEvaluation.h"

#include "plugins/body/BodyCom.h"
#include "plugins/inertial/DriftReductionProcessor.h"
#include "plugins/inertial/SegmentCalibration.h"

#include <cmath>
#include <numbers>

namespace athlos::eval {

using namespace athlos::inertial;
using body::Segment;
using math::Quat;
using math::Vec3;

namespace {
double squatSign(int segment) {
    const auto s = static_cast<BodySegment>(segment);
    return s == BodySegment::RightThigh || s == BodySegment::LeftThigh ? 1.0 : -1.0;
}
double yawOf(const Quat& segment) {
    const Vec3 x = segment * Vec3::UnitX();
    return std::atan2(x.y(), x.x());
}
// The body segment each of the simulator's eight sensors sits on.
constexpr std::array<Segment, kBodySegments> kSegmentOf{Segment::Pelvis,     Segment::Thorax,    Segment::RightThigh,
                                                        Segment::RightShank, Segment::RightFoot, Segment::LeftThigh,
                                                        Segment::LeftShank,  Segment::LeftFoot};
// Circular mean of yaw differences over rows [0, m).
double meanYawOffset(const std::vector<Quat>& reference, const std::vector<Quat>& other, std::size_t m) {
    double c = 0, s = 0;
    for (std::size_t k = 0; k < m; ++k) {
        const double d = yawOf(reference[k]) - yawOf(other[k]);
        c += std::cos(d);
        s += std::sin(d);
    }
    return std::atan2(s, c);
}
Quat aboutUp(double a) { return math::quatFromAxisAngle(Vec3::UnitZ(), a); }
}  // namespace

BodyComEvaluation evaluateBodyCom(const BodyComEvaluationOptions& options) {
    const body::WholeBodySimulation w = body::simulateWholeBody(options.simulation);
    const BodySimulation& sim = w.body;
    const std::size_t n = sim.t.size();
    const double ts = 1.0 / options.simulation.body.rate;
    BodyComEvaluation result;
    if (n == 0 || w.com.empty()) return result;

    // Segment orientations (segment → ENU) of the eight instrumented segments.
    std::array<std::vector<Quat>, kBodySegments> segment;
    std::array<Vec3, 7> proximalToJoint, distalToJoint;  // sensor frames, per BodyJoint
    std::array<Quat, kBodySegments> mounts;
    for (int s = 0; s < kBodySegments; ++s) mounts[s] = sim.sensors[s].mount;
    for (int j = 0; j < kBodyJoints; ++j) {
        proximalToJoint[j] = sim.joints[j].proximalToJoint;
        distalToJoint[j] = sim.joints[j].distalToJoint;
    }
    if (options.orientations == ComOrientations::True) {
        for (int s = 0; s < kBodySegments; ++s) segment[s] = sim.sensors[s].segment;
    } else {
        std::vector<DriftReduction::Segment> segs(kBodySegments);
        OrientationOptions oo = options.orientation;
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
            segs[s].q = estimateOrientation(oo, batch, ts).track.q;
            segs[s].acc = sensor.acc;
            segs[s].gyr = sensor.gyr;
        }
        // Functional calibration (upright + squats), as DriftEvaluation; feet keep their true mounts.
        const std::size_t s0 = std::size_t(std::ceil(1.0 / ts)),
                          s1 = std::min(n, std::size_t((sim.uprightEnd - 1.0) / ts));
        const std::size_t m0 = std::size_t(std::ceil(sim.squatBegin / ts)),
                          m1 = std::min(n, std::size_t(sim.squatEnd / ts));
        for (int s = 0; s < kBodySegments; ++s) {
            const bool foot = s == int(BodySegment::RightFoot) || s == int(BodySegment::LeftFoot);
            if (options.trueMounts || foot || m1 <= m0) continue;
            SegmentCalibration::Params cp;
            cp.firstRotation = squatSign(s);
            auto cal = SegmentCalibration(cp).calibrate(std::span(sim.sensors[s].acc).subspan(s0, s1 - s0),
                                                        std::span(sim.sensors[s].gyr).subspan(m0, m1 - m0), ts);
            if (cal) mounts[s] = cal->mount;
        }
        if (options.orientations == ComOrientations::Corrected) {
            std::vector<DriftReduction::Link> links;
            for (int j = 0; j < kBodyJoints; ++j) {
                const BodyJointInfo info = bodyJointInfo(static_cast<BodyJoint>(j));
                links.push_back({static_cast<int>(info.proximal), static_cast<int>(info.distal)});
            }
            // static_correction=auto, as the processor decides it from the orientation algorithm.
            DriftReduction::Params reduction = options.reduction;
            reduction.staticCorrection = reduction.staticCorrection &&
                                         staticCorrectionSuits(orientationAlgorithmName(options.orientation.algorithm));
            DriftReduction::Result r = DriftReduction(reduction).run(segs, links, ts);
            for (int s = 0; s < kBodySegments; ++s) segs[s].q = std::move(r.q[s]);
            if (options.vectors == ComVectors::Estimated)
                for (int j = 0; j < kBodyJoints; ++j) {
                    result.vectorError[j] = std::max((r.links[j].proximalToJoint - proximalToJoint[j]).norm(),
                                                     (r.links[j].distalToJoint - distalToJoint[j]).norm());
                    proximalToJoint[j] = r.links[j].proximalToJoint;
                    distalToJoint[j] = r.links[j].distalToJoint;
                }
        }
        for (int s = 0; s < kBodySegments; ++s) {
            segment[s].resize(n);
            for (std::size_t k = 0; k < n; ++k) segment[s][k] = (segs[s].q[k] * mounts[s]).normalized();
        }
        if (options.orientations == ComOrientations::Uncorrected) {
            // 6D headings are unrelated: align each segment to the pelvis over the first 2 s (standing upright,
            // all anterior axes forward), as joint-angles' heading=align-start.
            const std::size_t m = std::min(n, std::size_t(2.0 / ts));
            for (int s = 1; s < kBodySegments; ++s) {
                const Quat r = aboutUp(meanYawOffset(segment[0], segment[s], m));
                for (Quat& q : segment[s]) q = (r * q).normalized();
            }
        }
    }

    // BodyCom with the same table and posture assumptions as body-com's defaults.
    body::BodyCom::Params p;
    p.geometry = w.geometry;
    p.mass = w.mass;
    if (options.vectors != ComVectors::Model) {
        // Lumbar → hip in the pelvis, hip → knee in the thigh, knee → ankle in the shank (segment frames).
        const auto inSegment = [&](int s, const Vec3& v) { return Vec3(mounts[s].conjugate() * v); };
        const Vec3 lumbar = proximalToJoint[int(BodyJoint::Lumbar)];
        p.rightHip = inSegment(0, proximalToJoint[int(BodyJoint::RightHip)] - lumbar);
        p.leftHip = inSegment(0, proximalToJoint[int(BodyJoint::LeftHip)] - lumbar);
        p.rightKnee =
            inSegment(2, proximalToJoint[int(BodyJoint::RightKnee)] - distalToJoint[int(BodyJoint::RightHip)]);
        p.leftKnee = inSegment(5, proximalToJoint[int(BodyJoint::LeftKnee)] - distalToJoint[int(BodyJoint::LeftHip)]);
        p.rightAnkle =
            inSegment(3, proximalToJoint[int(BodyJoint::RightAnkle)] - distalToJoint[int(BodyJoint::RightKnee)]);
        p.leftAnkle =
            inSegment(6, proximalToJoint[int(BodyJoint::LeftAnkle)] - distalToJoint[int(BodyJoint::LeftKnee)]);
    }
    p.shoulderFlexion = options.simulation.shoulderFlexion;
    p.elbowFlexion = options.simulation.elbowFlexion;
    const body::BodyCom com(p);

    // Heading alignment of the whole body for the absolute CoM (6D: arbitrary global heading).
    const std::size_t m = std::min(n, std::size_t(2.0 / ts));
    const Quat global = options.orientations == ComOrientations::True
                            ? Quat::Identity()
                            : aboutUp(meanYawOffset(sim.sensors[0].segment, segment[0], m));

    const Vec3 antenna = w.geometry[Segment::Head].distal + options.simulation.antennaOffset;
    const std::size_t e0 = std::size_t(std::ceil(sim.motionBegin / ts)),
                      e1 = std::min(n, std::size_t(sim.motionEnd / ts));
    std::vector<Vec3> errors;
    std::vector<double> foreAft;
    double ankleSq = 0, pelvisFrameSq = 0;
    std::vector<Vec3> estOffset(n);  // CoM − antenna from the chain (aligned heading), per sample
    for (std::size_t k = 0; k < n; ++k) {
        std::array<std::optional<Quat>, body::kSegments> q;
        for (int s = 0; s < kBodySegments; ++s) q[static_cast<int>(kSegmentOf[s])] = segment[s][k];
        const body::BodyCom::Pose pose = com.update(q);
        // The simulator's antenna sits antennaOffset above the head vertex; body-model stores it from the
        // cervical joint (the head's proximal joint).
        estOffset[k] = global * (pose.com - body::BodyCom::pointOn(pose, Segment::Head, antenna));
        if (k < e0 || k >= e1) continue;
        // Compared in the pelvis sensor's heading frame: the heading part of true × estimated⁻¹ of the sacrum
        // sensor is removed (6D headings are arbitrary and a mount's heading error must not count twice).
        const Quat sensorEst = (segment[0][k] * mounts[0].conjugate()).normalized();
        const Vec3 dx = (sim.sensors[0].sensor[k] * sensorEst.conjugate()) * Vec3::UnitX();
        const Quat toEst = aboutUp(std::atan2(dx.y(), dx.x()));
        const Quat toTrue = Quat::Identity();
        errors.push_back(toEst * pose.com - toTrue * w.com[k]);
        // Fore-aft truth: along the true feet heading from the true mid-ankle.
        const Vec3 ankleR = sim[BodyJoint::RightAnkle].centre[k] - w.lumbar[k];
        const Vec3 ankleL = sim[BodyJoint::LeftAnkle].centre[k] - w.lumbar[k];
        Vec3 fwd = sim[BodySegment::RightFoot].segment[k] * Vec3::UnitX() +
                   sim[BodySegment::LeftFoot].segment[k] * Vec3::UnitX();
        fwd.z() = 0;
        foreAft.push_back(pose.foreAft - (w.com[k] - 0.5 * (ankleR + ankleL)).dot(fwd.normalized()));
        // In the pelvis sensor's frame: the chain's own accuracy, without the whole body's common tilt error.
        const Quat fromEst = sensorEst.conjugate(), fromTrue = sim.sensors[0].sensor[k].conjugate();
        const Vec3 e = fromEst * pose.joint[static_cast<int>(body::Joint::RightAnkle)] - fromTrue * ankleR;
        ankleSq += e.squaredNorm();
        pelvisFrameSq += (fromEst * pose.com - fromTrue * w.com[k]).squaredNorm();
    }
    result.samples = errors.size();
    if (errors.empty()) return result;
    double sq = 0, sum = 0, faSq = 0;
    Vec3 mean = Vec3::Zero();
    for (const Vec3& e : errors) {
        sq += e.squaredNorm();
        sum += e.norm();
        mean += e;
    }
    for (double f : foreAft) faSq += f * f;
    const double N = double(errors.size());
    mean /= N;
    Vec3 var = Vec3::Zero();
    for (const Vec3& e : errors) var += (e - mean).cwiseAbs2();
    result.rmse = std::sqrt(sq / N);
    result.meanError = sum / N;
    result.bias = mean;
    result.sd = (var / N).cwiseSqrt();
    result.foreAftRmse = std::sqrt(faSq / N);
    result.ankleRmse = std::sqrt(ankleSq / N);
    result.pelvisFrameRmse = std::sqrt(pelvisFrameSq / N);

    // Absolute CoM at the GNSS fixes inside the motion phase; speed over ±0.25 s.
    std::vector<double> t;
    std::vector<Vec3> est, tru;
    for (std::size_t r = 0; r < w.gnssT.size(); ++r) {
        const std::size_t k = std::size_t(std::lround(w.gnssT[r] / ts));
        if (k < e0 || k >= e1) continue;
        t.push_back(w.gnssT[r]);
        est.push_back(w.gnss[r] + estOffset[k]);
        tru.push_back(w.lumbar[k] + w.com[k]);
    }
    double absSq = 0;
    std::vector<double> dv;
    for (std::size_t r = 0; r < t.size(); ++r) {
        absSq += (est[r] - tru[r]).squaredNorm();
        std::size_t a = r, b = r;
        while (a > 0 && t[r] - t[a - 1] <= 0.25) --a;
        while (b + 1 < t.size() && t[b + 1] - t[r] <= 0.25) ++b;
        if (b > a) dv.push_back((est[b] - est[a]).norm() / (t[b] - t[a]) - (tru[b] - tru[a]).norm() / (t[b] - t[a]));
    }
    if (!t.empty()) result.absoluteRmse = std::sqrt(absSq / double(t.size()));
    if (!dv.empty()) {
        double s = 0, s2 = 0;
        for (double d : dv) s += d;
        result.speedBias = s / double(dv.size());
        for (double d : dv) s2 += (d - result.speedBias) * (d - result.speedBias);
        result.speedSd = std::sqrt(s2 / double(dv.size()));
    }
    return result;
}

}  // namespace athlos::eval
