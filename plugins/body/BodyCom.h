#pragma once
// Joint centres and centre of mass through the kinematic chain (issue #18 item 2, Fasel 2017 ch. 7–8,
// spec §6): from the lumbar joint centre (the origin), p_hip = R_pelvis v_hip, p_knee = p_hip + R_thigh v_knee,
// p_ankle = p_knee + R_shank v_ankle, p_cervical = R_thorax v_cervical, …; each segment's CoM from the
// anthropometric table (Anthropometry.h) and the CoM of the body = Σ m_s c_s / Σ m_s (equipment masses sit at
// their segment's CoM). Segments without a sensor ride rigidly on their parent: the head on the thorax; the
// arms on the thorax in a fixed posture (shoulder and elbow flexion, default a skier holding the poles);
// a foot without a sensor on its shank.
//
// Orientations are segment → ENU (sensor orientation × mount). Where a joint's vector is measured (the
// sensor-to-joint vectors of drift reduction, in segment coordinates here) it replaces the table's length;
// the segment's CoM then lies at the table's fraction of the measured proximal → distal vector plus the
// table's anterior/lateral offsets.
#include "plugins/body/Anthropometry.h"

#include <array>
#include <optional>

namespace athlos::body {

class BodyCom {
public:
    struct Params {
        Anthropometry geometry;
        std::array<double, kSegments> mass{};                  // kg per segment, equipment included
        double shoulderFlexion = 20.0 * 0.017453292519943295;  // rad, rigid arm posture (assumption)
        double elbowFlexion = 60.0 * 0.017453292519943295;     // rad
        // Measured joint vectors in the proximal segment's coordinates (m): lumbar → right/left hip in the
        // pelvis, hip → knee in the thigh, knee → ankle in the shank (both sides); absent = the table's.
        std::optional<Vec3> rightHip, leftHip, rightKnee, leftKnee, rightAnkle, leftAnkle;
    };
    // Masses from the body mass and the table's fractions plus equipment (kg per segment).
    static std::array<double, kSegments> segmentMasses(const Anthropometry& a, double bodyMass,
                                                       const std::array<double, kSegments>& equipment = {});

    struct Pose {
        std::array<Vec3, kJoints> joint;  // relative to the lumbar joint centre, ENU axes (m)
        std::array<Vec3, kSegments> segmentCom;
        std::array<Quat, kSegments> segment;  // all segment orientations used (derived ones included)
        Vec3 com = Vec3::Zero();              // relative to the lumbar joint centre (m)
        double foreAft = 0;                   // CoM − mid-ankle along the feet's horizontal heading (m)
        double aboveAnkles = 0;               // CoM − mid-ankle, vertical (m)
    };

    explicit BodyCom(Params params);
    // `orientation[s]`: segment → ENU, or nothing for segments that ride on their parent. The pelvis must be
    // given.
    Pose update(const std::array<std::optional<Quat>, kSegments>& orientation) const;
    // The position of a point fixed in segment `s` (offset from its proximal joint, segment coordinates).
    static Vec3 pointOn(const Pose& pose, Segment s, const Vec3& offset);
    const Params& params() const { return p_; }

private:
    Params p_;
};

}  // namespace athlos::body
