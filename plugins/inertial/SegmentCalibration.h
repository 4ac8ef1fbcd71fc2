#pragma once
// Functional sensor-to-segment calibration (spec §4, Fasel ch. 6–7): the segment's superior axis Y
// is the direction of gravity measured while standing upright (the accelerometer's mean points up),
// its medio-lateral axis Z is the principal axis of the angular velocity during a sagittal movement
// (squats: PCA of the gyroscope samples, Eigen's SelfAdjointEigenSolver), made orthogonal to Y; the
// anterior axis is X = Y × Z. The result is the mount of JointAngles.h (segment → sensor).
//
// The principal axis has no sign. ISB Z points to the right on both sides, and in a squat each
// segment starts by turning one known way about it: the thigh positively (knee forward), the shank
// and the pelvis negatively (the shank leans forward, the pelvis tilts anteriorly). firstRotation
// gives that sign; the first 10° of integrated rotation about the axis decide its direction.
#include "core/math/QuaternionOps.h"
#include "core/util/Expected.h"

#include <span>

namespace athlos::inertial {

class SegmentCalibration {
public:
    struct Params {
        double firstRotation = 1.0;     // +1 or −1: sign of the first turn about the right-pointing axis
        double decisionAngle = 0.1745;  // rad of integrated rotation that decides the sign (10°)
        // Which segment axis the movement turns about: 2 = Z (medio-lateral, squats; the default) or
        // 0 = X (antero-posterior, hip ab/adduction: the foot's frame, FunctionalCalibration.h).
        int functionalAxis = 2;
    };

    struct Result {
        math::Quat mount = math::Quat::Identity();      // segment → sensor
        math::Vec3 superior = math::Vec3::UnitY();      // Y in sensor coordinates
        math::Vec3 mediolateral = math::Vec3::UnitZ();  // Z in sensor coordinates
        math::Vec3 functional = math::Vec3::UnitZ();    // signed principal axis, before orthogonalisation
        double axisShare = 0.0;                         // fraction of the angular velocity energy on the principal axis
        double orthogonality =
            0.0;  // angle (rad) between the functional axis and the plane ⊥ Y, before re-orthogonalisation
    };

    SegmentCalibration() = default;
    explicit SegmentCalibration(const Params& params) : params_(params) {}

    // staticAcc: accelerometer samples (sensor frame) while standing upright; movementGyr: gyroscope
    // samples during the movement, movementDt their sampling interval. Errors when the windows are
    // empty, the segment was not at rest or the movement has no dominant axis.
    Expected<Result> calibrate(std::span<const math::Vec3> staticAcc, std::span<const math::Vec3> movementGyr,
                               double movementDt) const;

private:
    Params params_;
};

}  // namespace athlos::inertial
