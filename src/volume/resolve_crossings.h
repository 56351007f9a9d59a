//! The exact outer surface of a mesh whose only defect is a few crossing
//! triangles: a closed, oriented 2-manifold without degenerate triangles
//! (clean_solid.h finds these, with the crossing pairs), such as overlapping
//! shells or a fold through itself. The result is the boundary of the region
//! of winding number ≥ 1 (inside at least one shell; for a surface stored
//! inside out, a negative volume, ≤ −1: its solid, facing outward), cut out of the input's
//! own triangles: the crossing triangles are split along their intersection
//! curves (CGAL's autorefinement, on them alone), the surface falls into
//! patches between those curves, and a patch is kept when the winding number
//! just in front of it is 0, counted exactly along a ray (exact orientation
//! predicates; a ray through an edge, a vertex or a coplanar overlap is not
//! counted, another is cast). Every output point lies on an input triangle,
//! the cut points rounded to doubles, except where the union's boundary
//! touches itself at a single vertex (a fold turning around an input
//! vertex): each sheet there gets its own copy of the vertex, moved 1% of
//! the way to the centre of its ring, so that the sheets part.
//! Returns nothing (the caller repairs instead) when the crossings are too
//! many for this to pay (more than `max_crossing_pairs`), when a corner of
//! one crossing triangle lies exactly in the other's plane (a flat fold, a
//! vertex on a face: CGAL's autorefinement fails on those), when a cut does
//! not part the surface (it ends inside a patch) or the winding numbers of
//! the patches on its two sides do not differ by one, when no ray per patch
//! is decisive, or when the result is not itself a clean solid (check_solid,
//! after the rounding). Reports progress; throws Error(CANCELLED).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/mesh.h"
#include "core/progress.h"

namespace fabvdb::volume {

//! The most crossing pairs resolved for `triangle_count` triangles: a tenth
//! of the triangles, at least 1024. Cutting costs ~25 µs a pair and the rest
//! is one ray per patch, so resolving stays within about twice the crossing
//! test's time, far under a repair's (docs/design/geometry.md).
size_t max_crossing_pairs(size_t triangle_count);

std::optional<Mesh> resolve_crossings(const Mesh& mesh, const std::vector<std::pair<uint32_t, uint32_t>>& crossings,
                                      Progress& progress);

}  // namespace fabvdb::volume
