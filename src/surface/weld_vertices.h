//! Welding of vertices at exactly equal positions (all three coordinates
//! compare equal as doubles, so -0.0 and 0.0 are the same; no tolerance).
//! Pure functions; the mesh given is not changed.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::surface {

//! For each vertex, the index of the first vertex (lowest index) at exactly
//! the same position: a vertex that is alone at its position maps to itself.
std::vector<uint32_t> coincident_vertex_map(const Mesh& mesh);

//! The mesh with one vertex per distinct position (kept in the order of first
//! appearance, unreferenced ones included) and triangles renumbered to them.
//! Triangles are kept as they are, even those that become degenerate.
Mesh weld_coincident_vertices(const Mesh& mesh);

}  // namespace fabvdb::surface
