#pragma once
// The table that carries sensor mounts (segment → sensor rotations, JointAngles.h) between
// processors: kind "segment-calibration", one row per segment, columns segment (text) and
// qw, qx, qy, qz. simulate-limb writes the true mounts in it; joint-angles reads it.
#include "core/math/QuaternionOps.h"
#include "core/model/Table.h"
#include "core/util/Expected.h"

#include <QStringList>
#include <vector>

namespace athlos::inertial {

inline const QString kSegmentCalibrationKind = QStringLiteral("segment-calibration");

Table segmentMountTable(const QStringList& segments, const std::vector<math::Quat>& mounts,
                        QJsonObject attributes = {});
// The mount of `segment`, or an error naming the table and what is missing.
Expected<math::Quat> segmentMount(const Table& table, const QString& path, const QString& segment);

}  // namespace athlos::inertial
