#pragma once
// The streams of the body simulators (simulate-limb, simulate-body): each sensor's IMU, the true
// segment orientations and the true joint angles, with the simulation's attributes.
#include "core/math/QuaternionOps.h"
#include "core/processing/Processor.h"
#include "plugins/inertial/JointAngles.h"

#include <QJsonObject>
#include <QStringList>
#include <vector>

namespace athlos::inertial {

// acc_x..z (m/s²) and gyr_x..z (rad/s) in the sensor frame; attributes `segment` and `true_mount`
// (segment → sensor, qw qx qy qz) added.
Stream simulatedImuStream(const std::vector<double>& t, const std::vector<math::Vec3>& acc,
                          const std::vector<math::Vec3>& gyr, const QString& segment, const math::Quat& mount,
                          QJsonObject attributes);

// <segment>_qw..qz per segment (segment → ENU, canonical sign), one orientation per sample of t.
Stream trueSegmentOrientations(const std::vector<double>& t, const QStringList& segments,
                               const std::vector<const std::vector<math::Quat>*>& orientations,
                               const QJsonObject& attributes);

// flexion, abduction, rotation (rad) of `joint` on `side`, marked `reference`.
Stream trueJointAngles(const std::vector<double>& t, const std::vector<AnatomicalAngles>& angles, Joint joint,
                       Side side, QJsonObject attributes);

}  // namespace athlos::inertial
