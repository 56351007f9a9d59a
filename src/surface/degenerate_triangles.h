//! Degenerate triangles: a vertex index repeated, or three corners exactly
//! collinear (coincident corners included), decided with CGAL's exact
//! orientation predicate on the double coordinates (no tolerance).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

bool is_degenerate_triangle(const Mesh& mesh, const Triangle& triangle);

//! Indices of the degenerate triangles, ascending.
std::vector<uint32_t> degenerate_triangles(const Mesh& mesh);

}  // namespace fabvdb::surface
