#pragma once
// Anatomical joint angles from two sensor orientations (spec §5): ISB recommendations (Wu et al.
// 2002/2005) with the Grood & Suntay joint coordinate system.
//
// Frames. Sensor orientations q_p, q_d are scalar-first sensor→earth quaternions. Each sensor sits
// on its segment with a fixed mount m (the segment frame expressed in the sensor frame: it maps
// segment coordinates to sensor coordinates), so the segment→earth orientation is q ⊗ m. Segment
// frames follow the ISB: X anterior, Y superior (along the long axis), Z to the right — on BOTH
// sides, which is why the left side needs mirrored signs below.
//
// Decomposition. The relative rotation r = (q_p ⊗ m_p)* ⊗ (q_d ⊗ m_d) (distal segment → proximal
// segment coordinates) is split as the intrinsic Cardan sequence Z-X-Y, r = R_Z(α) R_X(β) R_Y(γ):
// α about the proximal Z (flexion/extension), β about the floating axis (ab/adduction), γ about the
// distal Y (internal/external rotation); this equals the Grood & Suntay joint coordinate system.
//
// Signs (explicit, per joint and side), so that a positive value means the same anatomically on both
// sides: flexion positive (hip flexion α, knee flexion −α, ankle dorsiflexion α, trunk flexion −α);
// abduction positive (right −β, left +β); internal rotation positive (right +γ, left −γ). For the
// trunk the side is ignored: "abduction" is lateral bending to the right (β) and "rotation" axial
// rotation to the left (γ).
//
// Two sensors filtered in 6D (no magnetometer) have independent, arbitrary headings. Their earth
// frames differ by a rotation about the vertical; `estimateHeadingOffset` finds it from a window in
// which the two segments' anterior axes point the same way horizontally (standing, or any posture
// with flexion in the sagittal plane only), and Params::headingOffset applies it to the distal side.
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"

#include <QString>
#include <QStringList>
#include <span>
#include <vector>

namespace athlos::inertial {

enum class Joint { Knee, Hip, Ankle, Trunk };
enum class Side { Right, Left };

QStringList jointNames();  // "knee", "hip", "ankle", "trunk"
Expected<Joint> parseJoint(const QString& name);
QString jointName(Joint joint);
Expected<Side> parseSide(const QString& name);  // "right", "left"
QString sideName(Side side);
// Default segment names of a joint (proximal, distal): knee = thigh, shank; hip = pelvis, thigh;
// ankle = shank, foot; trunk = pelvis, thorax.
QStringList jointSegments(Joint joint);

// Anatomical angles (rad), signs as in the file comment.
struct AnatomicalAngles {
    double flexion = 0.0;
    double abduction = 0.0;
    double rotation = 0.0;
    math::Vec3 vector() const { return {flexion, abduction, rotation}; }
};

// Cardan Z-X-Y angles (α, β, γ) ↔ anatomical angles for a joint and side (exact inverses).
AnatomicalAngles anatomicalFromCardan(const math::Vec3& zxy, Joint joint, Side side);
math::Vec3 cardanFromAnatomical(const AnatomicalAngles& angles, Joint joint, Side side);
// The relative rotation (distal → proximal segment) that has these anatomical angles.
math::Quat relativeFromAnatomical(const AnatomicalAngles& angles, Joint joint, Side side);

// Simpler 2D angles (spec §5): inclination of a segment's long axis from the vertical,
// acos(y_segment · up), and the angle between two long axes, acos(y_distal · y_proximal) (for the knee
// this is the flexion magnitude, independent of the mounts' rotation about Y).
double segmentInclination(const math::Quat& segment);
double longAxisAngle(const math::Quat& proximalSegment, const math::Quat& distalSegment);

class JointAngles {
public:
    struct Params {
        Joint joint = Joint::Knee;
        Side side = Side::Right;
        math::Quat proximalMount = math::Quat::Identity();  // segment → sensor coordinates
        math::Quat distalMount = math::Quat::Identity();
        double headingOffset = 0.0;  // rad, rotation about earth z applied to the distal sensor's earth frame
    };

    struct Sample {
        AnatomicalAngles angles;
        math::Vec3 cardan = math::Vec3::Zero();        // α, β, γ of the Z-X-Y decomposition (rad)
        math::Quat relative = math::Quat::Identity();  // distal segment → proximal segment
        double longAxisAngle = 0.0;                    // rad, acos(y_d · y_p)
        double proximalInclination = 0.0;              // rad
        double distalInclination = 0.0;                // rad
    };

    JointAngles() = default;
    explicit JointAngles(const Params& params) : params_(params) {}

    const Params& params() const { return params_; }
    // One sample from the two sensor→earth orientations.
    Sample update(const math::Quat& proximalSensor, const math::Quat& distalSensor) const;
    // The columns of a batch, in order (all rad): flexion, abduction, rotation, long_axis_angle,
    // proximal_inclination, distal_inclination (the joint-angles stream's layout).
    static constexpr std::size_t kColumns = 6;
    // Every sample of two sequences (the shorter one's length n) as rows of kColumns values, row-major,
    // written to rows (size ≥ n × kColumns); a gap (non-finite quaternion) in either input is a row of
    // NaN. Only the six values are formed, not a Sample per sample: at 500 Hz over 10 minutes a
    // Sample array is 31 MB per joint, four times the rows.
    void updateBatch(std::span<const math::Quat> proximalSensor, std::span<const math::Quat> distalSensor,
                     std::span<double> rows) const;
    std::vector<double> updateBatch(std::span<const math::Quat> proximalSensor,
                                    std::span<const math::Quat> distalSensor) const;

    // Heading offset (rad, about earth z) to apply to the distal sensor's earth frame so that both
    // segments' anterior axes point the same way on the horizontal plane over the given samples
    // (circular mean; samples where an anterior axis is nearly vertical are skipped). 0 if none is usable.
    static double estimateHeadingOffset(std::span<const math::Quat> proximalSensor,
                                        std::span<const math::Quat> distalSensor, const math::Quat& proximalMount,
                                        const math::Quat& distalMount);

private:
    Sample sample(const math::Quat& proximalSensor, const math::Quat& distalSensor, const math::Quat& heading) const;

    Params params_;
};

// Sample of a quaternion sequence at times t by SLERP between neighbours (times strictly increasing);
// outside the sequence's span the result is NaN.
std::vector<math::Quat> slerpAt(std::span<const double> sourceTime, std::span<const math::Quat> source,
                                std::span<const double> t);

// "w,x,y,z" (commas or spaces) → normalised quaternion; error names the parameter.
Expected<math::Quat> parseQuaternion(const QString& text, const QString& parameter);
QString formatQuaternion(const math::Quat& q);

}  // namespace athlos::inertial
