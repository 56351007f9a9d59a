//! The generalized winding number of a triangle mesh at a point, computed
//! independently of the library (src/volume/winding_number is what some
//! checks compare against): the triangles' signed solid angles seen from the
//! point (Van Oosterom and Strackee) summed and divided by 4π. About 1 inside
//! a closed outward surface, 0 outside, a vote of the triangles for a soup.
//! Cost: one atan2 per triangle, no acceleration.
#pragma once

#include "core/mesh.h"

namespace fabvdb::test {

double winding_number(const Mesh& mesh, const Vec3& p);

}  // namespace fabvdb::test
