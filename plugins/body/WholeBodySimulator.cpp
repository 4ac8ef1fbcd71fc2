#include "plugins/body/WholeBodySimulator.h"

#include <cmath>
#include <numbers>
#include <random>

namespace athlos::body {

using inertial::BodyJoint;
using inertial::BodySegment;

namespace {
Quat about(int axis, double angle) { return math::quatFromAxisAngle(Vec3::Unit(axis), angle); }
}  // namespace

WholeBodySimulation simulateWholeBody(const WholeBodyParams& p) {
    WholeBodySimulation w;
    w.body = inertial::simulateBody(p.body);
    auto geometry = anthropometry(p.table, p.sex, p.height);
    if (!geometry) return w;  // height out of range: no truth
    w.geometry = *geometry;
    const Anthropometry& a = w.geometry;
    for (int s = 0; s < kSegments; ++s) w.mass[s] = a.segments[s].massFraction * p.mass + p.equipment[s];
    const inertial::BodySimulation& b = w.body;
    const std::size_t n = b.t.size();
    w.segment.resize(n);
    w.lumbar.resize(n);
    w.com.resize(n);
    w.antenna.resize(n);
    const double twoPi = 2.0 * std::numbers::pi;
    const auto centre = [&](BodyJoint j, std::size_t k) { return b[j].centre[k]; };
    const auto orient = [&](BodySegment s, std::size_t k) { return b[s].segment[k]; };
    double total = 0.0;
    for (double m : w.mass) total += m;
    for (std::size_t k = 0; k < n; ++k) {
        const double t = b.t[k], ph = twoPi * p.swingFrequency * t;
        std::array<Quat, kSegments>& q = w.segment[k];
        q[0] = orient(BodySegment::Sacrum, k);
        q[1] = orient(BodySegment::Sternum, k);
        q[2] = q[1] * about(2, p.headNod * std::sin(0.7 * ph));
        for (int side = 0; side < 2; ++side) {
            const int o = 3 * side;
            const double sign = side == 0 ? 1.0 : -1.0, phase = side == 0 ? 0.0 : std::numbers::pi;
            // Flexion about Z, then a little abduction about X (away from the body on both sides).
            q[3 + o] = q[1] * about(2, p.shoulderFlexion + p.shoulderSwing * std::sin(ph + phase)) *
                       about(0, sign * p.abductionSwing * (1.0 + std::sin(1.3 * ph)));
            q[4 + o] = q[3 + o] * about(2, p.elbowFlexion + p.elbowSwing * std::sin(ph + phase + 0.5));
            q[5 + o] = q[4 + o];
            q[9 + 3 * side] = orient(side == 0 ? BodySegment::RightThigh : BodySegment::LeftThigh, k);
            q[10 + 3 * side] = orient(side == 0 ? BodySegment::RightShank : BodySegment::LeftShank, k);
            q[11 + 3 * side] = orient(side == 0 ? BodySegment::RightFoot : BodySegment::LeftFoot, k);
        }
        // True points in ENU: legs and lumbar joint from the simulator, the rest from the table on the thorax.
        const Vec3 lumbar = centre(BodyJoint::Lumbar, k);
        const Vec3 hip[2] = {centre(BodyJoint::RightHip, k), centre(BodyJoint::LeftHip, k)};
        const Vec3 knee[2] = {centre(BodyJoint::RightKnee, k), centre(BodyJoint::LeftKnee, k)};
        const Vec3 ankle[2] = {centre(BodyJoint::RightAnkle, k), centre(BodyJoint::LeftAnkle, k)};
        const Vec3 cervical = lumbar + q[1] * a[Segment::Thorax].distal;
        const Vec3 vertex = cervical + q[2] * a[Segment::Head].distal;
        Vec3 sum = Vec3::Zero();
        const auto add = [&](Segment s, const Vec3& c) { sum += w.mass[static_cast<int>(s)] * c; };
        // Pelvis: Dumas from the lumbar joint, de Leva from the mid-hip point.
        const Vec3 pelvisOrigin = a[Segment::Pelvis].comFromMidHip ? Vec3(0.5 * (hip[0] + hip[1])) : lumbar;
        add(Segment::Pelvis, pelvisOrigin + q[0] * a[Segment::Pelvis].com);
        add(Segment::Thorax, lumbar + q[1] * a[Segment::Thorax].com);
        add(Segment::Head, cervical + q[2] * a[Segment::Head].com);
        for (int side = 0; side < 2; ++side) {
            const int o = 3 * side;
            const double mz = side == 0 ? 1.0 : -1.0;
            const Vec3 shoulder =
                cervical + q[1] * Vec3(a.rightShoulder.x(), a.rightShoulder.y(), mz * a.rightShoulder.z());
            const Vec3 elbow = shoulder + q[3 + o] * a.segments[3 + o].distal;
            const Vec3 wrist = elbow + q[4 + o] * a.segments[4 + o].distal;
            add(static_cast<Segment>(3 + o), shoulder + q[3 + o] * a.segments[3 + o].com);
            add(static_cast<Segment>(4 + o), elbow + q[4 + o] * a.segments[4 + o].com);
            add(static_cast<Segment>(5 + o), wrist + q[5 + o] * a.segments[5 + o].com);
            // Thigh and shank: the table's fraction of the simulator's own joint-to-joint vector, plus the
            // anterior/lateral offsets in the segment frame.
            const int th = 9 + 3 * side, sh = 10 + 3 * side, ft = 11 + 3 * side;
            const auto limb = [&](int s, const Vec3& from, const Vec3& to) {
                const SegmentParameters& sp = a.segments[s];
                const double f = sp.com.y() / sp.distal.y();
                add(static_cast<Segment>(s), from + f * (to - from) + q[s] * Vec3(sp.com.x(), 0.0, sp.com.z()));
            };
            limb(th, hip[side], knee[side]);
            limb(sh, knee[side], ankle[side]);
            add(static_cast<Segment>(ft), ankle[side] + q[ft] * a.segments[ft].com);
        }
        w.lumbar[k] = lumbar;
        w.com[k] = sum / total - lumbar;
        w.antenna[k] = vertex + q[2] * p.antennaOffset;
    }
    // GNSS: every (rate / gnssRate)-th sample, white noise plus a slowly varying offset (two sinusoids of
    // random phase per axis, periods of tens of seconds: the satellite-constellation error of spec §10).
    std::mt19937_64 rng(p.body.seed * 7919 + 13);
    std::normal_distribution<double> normal(0.0, 1.0);
    std::uniform_real_distribution<double> phase(0.0, twoPi);
    std::array<double, 6> phases{};
    for (double& v : phases) v = phase(rng);
    const std::size_t step = std::max<std::size_t>(1, std::size_t(std::lround(p.body.rate / p.gnssRate)));
    for (std::size_t k = 0; k < n; k += step) {
        const double t = b.t[k];
        Vec3 e;
        for (int i = 0; i < 3; ++i)
            e[i] = p.gnssNoise * normal(rng) +
                   p.gnssWander * 0.5 *
                       (std::sin(twoPi * t / 47.0 + phases[i]) + std::sin(twoPi * t / 19.0 + phases[3 + i]));
        w.gnssT.push_back(t);
        w.gnss.push_back(w.antenna[k] + e);
    }
    return w;
}

}  // namespace athlos::body
