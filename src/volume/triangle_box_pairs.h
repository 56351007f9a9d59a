//! The broad phase of a pairwise triangle test: which triangles of a mesh
//! have bounding boxes that overlap (closed boxes: touching counts), so that
//! only those pairs need the exact test. Every pair of overlapping boxes is
//! visited once, found on uniform grids, one per size class of triangle, so
//! the cost stays near linear in the triangles and the pairs found, for
//! adaptive meshes too. Pure; parallel (TBB).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

//! Calls `visit(i, j)` once for every pair of distinct triangles whose boxes
//! overlap, in no fixed order and with i and j in either order. `visit` is
//! called concurrently from several threads. Nothing for fewer than two
//! triangles.
void for_each_overlapping_box_pair(const Mesh& mesh, const std::function<void(uint32_t, uint32_t)>& visit);

//! The triangles, in index order, whose box overlaps the box of a `marked`
//! one (per triangle; the marked ones included): only they can meet a marked
//! triangle. Costs a pass over the mesh and a grid of the marked boxes, so a
//! few marked triangles cost little on a large mesh. Empty when none is
//! marked.
std::vector<uint32_t> triangles_near_marked(const Mesh& mesh, const std::vector<char>& marked);

}  // namespace fabvdb::volume
