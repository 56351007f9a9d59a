//! Self-intersections of a triangle mesh, decided exactly: the pairs of
//! triangles that share no vertex position (after welding exactly equal
//! positions, so neighbours across an unwelded seam do not count) and whose
//! closed point sets intersect or touch, coplanar overlaps included. Uses
//! CGAL's exact predicates (Epick); a degenerate triangle is tested as the
//! segment or point it is. Broad phase on the triangles' boxes
//! (triangle_box_pairs.h), narrow phase in parallel (TBB). Reports progress;
//! throws Error(CANCELLED).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::surface {

//! The intersecting pairs (i, j), i < j, sorted.
std::vector<std::pair<uint32_t, uint32_t>> self_intersecting_pairs(const Mesh& mesh, Progress& progress);

}  // namespace fabvdb::surface
