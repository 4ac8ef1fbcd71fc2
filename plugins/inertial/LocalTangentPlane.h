#pragma once
// The geodesy moved to core (core/geometry/LocalTangentPlane.h), where the importers need it too.
#include "core/geometry/LocalTangentPlane.h"

namespace athlos::inertial {
using athlos::LocalTangentPlane;
}  // namespace athlos::inertial
