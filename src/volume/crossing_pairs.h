//! The pairs of triangles of a mesh that cross: meet other
//! than along the edge or at the corner they share, decided as CGAL's
//! self-intersection test does (exact predicates, Epick): no shared vertex,
//! the triangles intersect; one shared vertex, the edge opposite it in one
//! meets the other; a shared edge, the two lie in one plane on the same side
//! of it; all three shared, a duplicate. Only pairs with a candidate in them
//! are tested, among the triangles whose boxes meet a candidate's, so a few
//! candidates cost little on a large mesh. Broad phase on uniform grids, one
//! per size class of triangle (triangle_box_pairs.h), so it stays near linear
//! for adaptive meshes too; pairs at an embedded fan skipped
//! (embedded_fans.h); the exact test in triangles_cross.h. Parallel (TBB).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

//! The crossing pairs (i, j), i < j, sorted (the same on every run). `candidates`:
//! per triangle, whether pairs with it are tested; empty: all are.
std::vector<std::pair<uint32_t, uint32_t>> crossing_pairs(const Mesh& mesh, const std::vector<char>& candidates = {});

}  // namespace fabvdb::volume
