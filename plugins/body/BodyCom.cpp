#include "plugins/body/BodyCom.h"

#include <cmath>
#include <limits>

namespace athlos::body {

namespace {
Vec3 mirrored(const Vec3& v) { return Vec3(v.x(), v.y(), -v.z()); }
Quat aboutZ(double angle) { return math::quatFromAxisAngle(Vec3::UnitZ(), angle); }
int idx(Segment s) { return static_cast<int>(s); }
int idx(Joint j) { return static_cast<int>(j); }
}  // namespace

std::array<double, kSegments> BodyCom::segmentMasses(const Anthropometry& a, double bodyMass,
                                                     const std::array<double, kSegments>& equipment) {
    std::array<double, kSegments> m{};
    for (int s = 0; s < kSegments; ++s) m[s] = a.segments[s].massFraction * bodyMass + equipment[s];
    return m;
}

BodyCom::BodyCom(Params params) : p_(std::move(params)) {}

Vec3 BodyCom::pointOn(const Pose& pose, Segment s, const Vec3& offset) {
    return pose.joint[idx(proximalJoint(s))] + pose.segment[idx(s)] * offset;
}

BodyCom::Pose BodyCom::update(const std::array<std::optional<Quat>, kSegments>& orientation) const {
    Pose pose;
    const Anthropometry& a = p_.geometry;
    // Orientations: given, or the parent's (arms in the fixed posture). Parents precede children in the enum.
    for (int s = 0; s < kSegments; ++s) {
        const Segment seg = static_cast<Segment>(s);
        if (orientation[s]) {
            pose.segment[s] = orientation[s]->normalized();
            continue;
        }
        const Quat parent = s == 0 ? Quat::Identity() : pose.segment[idx(parentSegment(seg))];
        switch (seg) {
            case Segment::RightUpperArm:
            case Segment::LeftUpperArm:
                pose.segment[s] = parent * aboutZ(p_.shoulderFlexion);
                break;
            case Segment::RightForearm:
            case Segment::LeftForearm:
                pose.segment[s] = parent * aboutZ(p_.elbowFlexion);
                break;
            default:
                pose.segment[s] = parent;
        }
    }
    const auto& q = pose.segment;
    std::array<Vec3, kJoints>& j = pose.joint;
    const auto vec = [&](const std::optional<Vec3>& measured, const Vec3& table) {
        return measured ? *measured : table;
    };
    // The chain (spec §6).
    j[idx(Joint::Lumbar)] = Vec3::Zero();
    j[idx(Joint::RightHip)] = q[idx(Segment::Pelvis)] * vec(p_.rightHip, a.rightHip);
    j[idx(Joint::LeftHip)] = q[idx(Segment::Pelvis)] * vec(p_.leftHip, mirrored(a.rightHip));
    j[idx(Joint::RightKnee)] =
        j[idx(Joint::RightHip)] + q[idx(Segment::RightThigh)] * vec(p_.rightKnee, a[Segment::RightThigh].distal);
    j[idx(Joint::LeftKnee)] =
        j[idx(Joint::LeftHip)] + q[idx(Segment::LeftThigh)] * vec(p_.leftKnee, a[Segment::LeftThigh].distal);
    j[idx(Joint::RightAnkle)] =
        j[idx(Joint::RightKnee)] + q[idx(Segment::RightShank)] * vec(p_.rightAnkle, a[Segment::RightShank].distal);
    j[idx(Joint::LeftAnkle)] =
        j[idx(Joint::LeftKnee)] + q[idx(Segment::LeftShank)] * vec(p_.leftAnkle, a[Segment::LeftShank].distal);
    j[idx(Joint::Cervical)] = q[idx(Segment::Thorax)] * a[Segment::Thorax].distal;
    j[idx(Joint::HeadVertex)] = j[idx(Joint::Cervical)] + q[idx(Segment::Head)] * a[Segment::Head].distal;
    j[idx(Joint::RightShoulder)] = j[idx(Joint::Cervical)] + q[idx(Segment::Thorax)] * a.rightShoulder;
    j[idx(Joint::LeftShoulder)] = j[idx(Joint::Cervical)] + q[idx(Segment::Thorax)] * mirrored(a.rightShoulder);
    for (int side = 0; side < 2; ++side) {
        const int o = 3 * side;
        j[idx(Joint::RightElbow) + o] =
            j[idx(Joint::RightShoulder) + o] + q[idx(Segment::RightUpperArm) + o] * a.segments[3 + o].distal;
        j[idx(Joint::RightWrist) + o] =
            j[idx(Joint::RightElbow) + o] + q[idx(Segment::RightForearm) + o] * a.segments[4 + o].distal;
    }
    // Segment CoMs. Where the proximal → distal vector was measured, the longitudinal part of the table's CoM
    // is taken as a fraction of it.
    double total = 0.0;
    Vec3 sum = Vec3::Zero();
    for (int s = 0; s < kSegments; ++s) {
        const Segment seg = static_cast<Segment>(s);
        const SegmentParameters& sp = a.segments[s];
        Vec3 c;
        if (seg == Segment::Pelvis) {
            const Vec3 origin =
                sp.comFromMidHip ? Vec3(0.5 * (j[idx(Joint::RightHip)] + j[idx(Joint::LeftHip)])) : Vec3(Vec3::Zero());
            c = origin + q[s] * sp.com;
        } else {
            const int d = distalJoint(seg);
            const Vec3 prox = j[idx(proximalJoint(seg))];
            const double length = sp.distal.norm();
            if (d >= 0 && length > 0.0 && std::abs(sp.distal.y()) > 0.99 * length) {
                const double f = sp.com.y() / sp.distal.y();  // fraction along proximal → distal
                c = prox + f * (j[d] - prox) + q[s] * Vec3(sp.com.x(), 0.0, sp.com.z());
            } else {
                c = prox + q[s] * sp.com;
            }
        }
        pose.segmentCom[s] = c;
        sum += p_.mass[s] * c;
        total += p_.mass[s];
    }
    pose.com = total > 0.0 ? Vec3(sum / total) : Vec3::Zero();
    // Fore-aft position against the feet (thesis ch. 7): along the horizontal heading of the two feet.
    const Vec3 midAnkle = 0.5 * (j[idx(Joint::RightAnkle)] + j[idx(Joint::LeftAnkle)]);
    Vec3 forward = q[idx(Segment::RightFoot)] * Vec3::UnitX() + q[idx(Segment::LeftFoot)] * Vec3::UnitX();
    forward.z() = 0.0;
    const Vec3 rel = pose.com - midAnkle;
    pose.foreAft = forward.norm() > 1e-9 ? rel.dot(forward.normalized()) : std::numeric_limits<double>::quiet_NaN();
    pose.aboveAnkles = rel.z();
    return pose;
}

}  // namespace athlos::body
