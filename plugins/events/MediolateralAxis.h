#pragma once
// The medio-lateral (ML) axis of a foot-mounted IMU, in its own sensor frame.
//
// In walking, running and on stairs the foot rotates mostly about its ML axis: plantar- and
// dorsiflexion in swing (mid-swing peaks of 4–7 rad/s in walking, Rampp et al. 2015) and the
// heel-to-toe roll in stance, against well under half of that about the other two axes. The ML axis
// is therefore the principal axis of the angular velocity (Pearson's PCA without centring):
//
//   S = Σ_k ω_k ω_kᵀ,   S u = λ₁ u,   λ₁ ≥ λ₂ ≥ λ₃                                       (1)
//
// u does not depend on how the sensor is mounted (gaitmap's files are turned into "x forward, z up";
// a raw lateral NilsPod has its ML axis along z and x pointing up). Its sign is arbitrary, so it is
// fixed to make the largest component positive and the swing sign is found from the data
// (GaitEventDetector::swingSign). `dominance` = λ₁ / (λ₁ + λ₂ + λ₃) says how clear the axis is:
// 0.58–0.81 on gaitmap's walk and stairs; a value near 1/3 means there is no dominant rotation.
//
// Turns and foot roll that go with the swing pull u off the true axis: on gaitmap's stairs, whose
// y axis is the medio-lateral one by construction, u lies 6° (left) and 11° (right) from y, and the
// tilted u loses the first swing of the right foot (a turning step onto the stairs). Foot sensors are
// usually mounted along the foot, so `ml_axis = auto` takes the sensor axis nearest to u when it lies
// within kSnapAngle of it, and u itself otherwise (an oblique mount).
#include "core/processing/ParameterSpec.h"

#include <Eigen/Core>
#include <QString>

#include <cstddef>
#include <optional>

namespace athlos::events {

struct MediolateralAxis {
    Eigen::Vector3d axis = Eigen::Vector3d::UnitY();       // unit vector in the sensor frame, the one used
    Eigen::Vector3d principal = Eigen::Vector3d::UnitY();  // u of eq. 1 (auto), before snapping
    double dominance = 0.0;                                // λ₁ / (λ₁ + λ₂ + λ₃) of eq. 1; 0 when given
};

// auto: a sensor axis within this angle of u is taken instead of u. 20° is above the 11° of gaitmap's
// stairs, and a sensor axis 20° off the true one still sees cos 20° = 94 % of the swing.
inline constexpr double kSnapAngle = 20.0 * 3.14159265358979323846 / 180.0;  // rad

// Eq. 1 over `rows` samples (gyr: x of the first sample, `stride` doubles between samples). Samples
// with a non-finite component are skipped. An all-zero recording gives the y axis, dominance 0.
MediolateralAxis principalRotationAxis(const double* gyr, std::size_t rows, std::size_t stride);

// The `ml_axis` parameter of the gait processors: "x", "y", "z" (a sensor axis) or "auto" (eq. 1,
// then the nearest sensor axis if within kSnapAngle). Anything else: nullopt.
std::optional<MediolateralAxis> mediolateralAxis(const QString& choice, const double* gyr, std::size_t rows,
                                                 std::size_t stride);

// The two declarations gait-events and gait-parameters share: `ml_axis` (auto | x | y | z, default
// auto) and `swing_sign` (auto | positive | negative, default auto: GaitEventDetector::swingSign).
ParameterSpec mlAxisParameter();
ParameterSpec swingSignParameter();
// swing_sign's value: +1, −1, or 0 for auto.
int swingSignOf(const QString& choice);

// For attributes and messages: "[0.021, 0.998, -0.055]".
QString axisText(const Eigen::Vector3d& axis);

}  // namespace athlos::events
