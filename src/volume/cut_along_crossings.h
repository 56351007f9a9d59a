//! A mesh cut along the intersection curves of its crossing triangles: the
//! crossing triangles (only them: every triangle a cut passes through
//! crosses another) are split by CGAL's autorefinement, the others kept as
//! they are. Each side of a cut keeps its own copies of the cut points, so a
//! closed oriented manifold stays one by its indices. The cut points are
//! rounded to doubles, and put in order of position (the cut points, each
//! piece from its least corner, the pieces), so that the order does not
//! depend on the autorefinement's, which changes from run to run. Their
//! rounding can: on some inputs a few cut points differ by an ulp between
//! runs (docs/design/geometry.md). Pure; costs ~25 µs a crossing pair.
#pragma once

#include <cstdint>
#include <optional>
#include <unordered_set>
#include <utility>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

struct CutSurface {
    Mesh mesh;               //!< the input's vertices, then the cut points
    size_t first_piece = 0;  //!< the untouched triangles come first, in input order, then the pieces
    std::unordered_set<uint64_t> cut_edges;  //!< edge_key(a, b) and (b, a) of every edge along a cut

    static uint64_t edge_key(uint32_t a, uint32_t b) { return uint64_t(a) << 32 | b; }
    //! Whether the edge between vertices a and b lies along a cut.
    bool along_cut(uint32_t a, uint32_t b) const { return cut_edges.count(edge_key(a, b)) > 0; }
};

//! `crossings`: the crossing pairs (crossing_pairs.h). Nothing when a corner
//! of one crossing triangle lies exactly in the other's plane (a flat fold,
//! a vertex on a face: CGAL 5.5's autorefinement crashes on such inputs,
//! corpus brucewick.obj and egret.ply), when the crossing triangles do not
//! make a manifold by their indices, or when the autorefinement fails or
//! moves an input vertex.
std::optional<CutSurface> cut_along_crossings(const Mesh& mesh,
                                              const std::vector<std::pair<uint32_t, uint32_t>>& crossings);

}  // namespace fabvdb::volume
