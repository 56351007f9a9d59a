//! The unit icosphere: an icosahedron whose triangles are split in four
//! `splits` times, vertices projected on the unit sphere (10·4^splits + 2
//! vertices, 20·4^splits triangles, outward-oriented). Its vertices are the
//! candidate directions of the thesis (§3.7: "an icosphere with three
//! subdivisions (162 vertices)" is splits = 2) and the default gravity
//! orientations of the drainability model.
#pragma once

#include <vector>

#include "core/mesh.h"

namespace fabvdb {

Mesh unit_icosphere(int splits);

//! The 162 unit directions of the thesis: unit_icosphere(2) vertices. Opposite
//! directions come in pairs; `direction_opposite[i]` is the index of −d_i.
struct SphereDirections {
    std::vector<Vec3> directions;
    std::vector<int> opposite;
};
SphereDirections thesis_directions();

}  // namespace fabvdb
