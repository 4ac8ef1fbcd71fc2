#pragma once
// A noise profile (issue #16 item 6, thesis §4.4 "filter deployment"): the filter's noise parameters
// Θ = (Q, R, α) estimated once on a set of representative training recordings (eq. 4.13 over all of
// them) and applied to new recordings with `position-filter --param noise=profile:<path>`, as the thesis
// deploys its filter (record a representative set, estimate offline, then filter with fixed values).
// Stored in the project as a table of kind "noise-profile": one row per parameter (text column
// `parameter`, numeric `value`, text `unit`); attributes name the motion model it was estimated for.
#include "core/model/Table.h"
#include "core/util/Expected.h"
#include "plugins/positioning/PositionFilter.h"

namespace athlos::positioning {

inline const QString kNoiseProfileKind = QStringLiteral("noise-profile");

// "unconstrained", "pseudo", "augmented", "constant-velocity".
QString modelKindName(ModelKind model);

struct NoiseProfile {
    NoiseSettings noise;
    ModelKind model = ModelKind::Augmented;
};

Table noiseProfileTable(const NoiseProfile& profile, QJsonObject attributes = {});
// The profile of a table, or an error naming `path` and what is missing or implausible.
Expected<NoiseProfile> noiseProfileFromTable(const Table& table, const QString& path);

}  // namespace athlos::positioning
