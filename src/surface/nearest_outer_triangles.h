//! For each triangle of the full-resolution input, the triangle of S_low
//! (a shell's outer surface) nearest to its centroid: how the decomposition's
//! labels, made on S_low, reach the input. Takes the input and S_low in the
//! same (millimetre) frame; exact nearest by CGAL's AABB tree. Costs building
//! the tree over S_low and one query per input triangle, in parallel.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

//! `outer`: at least one triangle. One index into outer.triangles per input triangle.
std::vector<uint32_t> nearest_outer_triangles(const Mesh& input, const Mesh& outer);

}  // namespace fabvdb::surface
