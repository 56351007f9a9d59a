//! Test parts for mold generation: the upper half of a spherical shell (a
//! sphere split at the equator gives two of them), closed, outward and a
//! double height field along +Z.
#pragma once

#include "core/mesh.h"

namespace fabvdb::test {

//! Outer dome of radius `outer` and inner dome of radius `inner` around the
//! origin, joined by a flat ring at z = 0 (facing down); `rings` latitude
//! rings per dome, `segments` around.
Mesh make_dome_shell(double outer, double inner, int rings, int segments);

}  // namespace fabvdb::test
