//! Per patch of a closed oriented surface (a patch: triangles between which
//! the winding number does not jump, as from cut_patches.h), the winding
//! number just in front of it, on the side its normals point to: counted
//! exactly along a ray from the centre of one of its triangles (exact
//! orientation predicates). A ray through an edge, a vertex or a coplanar
//! overlap, or one that crosses a triangle whose plane passes within 1e-9 ×
//! the mesh's diagonal of its start, is not counted, and another of the
//! patch's triangles is tried, up to 4, those facing the fixed ray direction
//! most first. All rays
//! of a round are cast in one pass over the triangles. Pure; parallel (TBB);
//! throws Error(CANCELLED).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

//! `patch`: per triangle, its patch, below `patch_count`. Nothing when some
//! patch gets no decisive ray.
std::optional<std::vector<int>> front_winding_numbers(const Mesh& mesh, const std::vector<uint32_t>& patch,
                                                      size_t patch_count, Progress& progress);

}  // namespace fabvdb::volume
