//! The edge table of a triangle mesh, on its vertex indices as stored (on a
//! mesh welded by position_ids.h, edges between positions): every edge with
//! the triangle sides that use it. From it come manifoldness, boundary edges
//! and loops, sharp edges, adjacency and whether directed uses cancel. Costs
//! 3 records of 16 bytes per triangle and one parallel sort of them (TBB); pure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

//! One side of a triangle along an edge: the edge is (lo, hi) with lo < hi, and
//! `forward` says whether the triangle runs from lo to hi.
struct EdgeUse {
    uint32_t lo;
    uint32_t hi;
    uint32_t triangle;
    bool forward;
};

//! Every edge of the mesh with the triangle sides that use it. The uses are
//! sorted by (lo, hi, triangle, forward); edge i owns uses[begin[i]] ..
//! uses[begin[i+1]-1]. A triangle with a repeated index has no side from a
//! vertex to itself; its two other sides both use the same edge.
struct EdgeTable {
    std::vector<EdgeUse> uses;
    std::vector<size_t> begin;  // size: edge count + 1
    size_t edge_count() const { return begin.size() - 1; }
    size_t use_count(size_t edge) const { return begin[edge + 1] - begin[edge]; }
};

EdgeTable build_edge_table(const Mesh& mesh);

}  // namespace fabvdb::volume
