//! Whether a triangle mesh is a closed cycle: every edge between two points
//! (by position, so unwelded and split copies of a point count as one) is
//! used as often in one direction as in the other. Closed shells are, also
//! when they self-intersect, overlap, nest or meet at non-manifold edges;
//! a mesh with a hole or an inconsistently oriented piece is not. Its
//! generalized winding number is then an integer, constant on every
//! connected region off the surface. Degenerate triangles count like others.
//! Takes the edge table (edge_table.h) of the mesh welded by position
//! (position_ids.h); one pass over it.
#pragma once

#include "volume/edge_table.h"

namespace fabvdb::volume {

bool is_closed_cycle(const EdgeTable& welded_edges);

}  // namespace fabvdb::volume
