//! Fan triangulation of a polygon face, as the mesh formats that store
//! polygons (OBJ, OFF, PLY, ASCII STL loops) are read: corners c0..c(n-1)
//! become triangles (c0, ci, ci+1) for i = 1..n-2, in order, so a convex
//! polygon keeps its orientation. Corner indices are taken as given (range
//! checks happen once the whole mesh is read).
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/mesh.h"

namespace fabvdb::io {

//! Appends the n-2 fan triangles of the polygon `corners[0..count)`; requires count >= 3.
void add_polygon_fan(Mesh& mesh, const uint32_t* corners, size_t count);

}  // namespace fabvdb::io
