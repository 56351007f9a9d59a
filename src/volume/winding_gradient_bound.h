//! An upper bound on how fast the generalized winding number w of a triangle
//! soup (winding_number.h) can change over a box. Off the surface, ∇w is the
//! Biot–Savart field of the soup's boundary: edges that two consistently
//! oriented triangles share cancel, so only edges whose directed uses do not
//! sum to zero count, each |net uses| times, and
//!     |∇w(q)| <= Σ_e |m_e| · length_e / (4π · distance(q, e)²).
//! A closed, consistently oriented soup has no such edge: w is constant
//! between its sheets. Edges are matched by exact position, over the triangles
//! WindingNumber keeps (those of non-zero area): the bound reads the edge
//! table (edge_table.h) of the mesh welded by position (position_ids.h),
//! which the caller builds once for every check of the input. The edges sit in a tree whose
//! far nodes are bounded by their total length at their box's distance, so a
//! query costs about the log of the edge count where edges are far, and stops
//! once the bound reaches the caller's cap. Built once, queried concurrently.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"
#include "volume/edge_table.h"

namespace fabvdb::volume {

class WindingGradientBound {
public:
    //! `welded` is the mesh welded by position, `edges` its edge table.
    WindingGradientBound(const Mesh& welded, const EdgeTable& edges);

    //! An upper bound (1/mm) on |∇w| at every point of `box` off the surface;
    //! at least `cap` when the bound reaches it (the traversal stops there),
    //! infinite when a boundary edge touches the box.
    double operator()(const BoundingBox& box, double cap) const;

    //! Edges whose directed uses do not cancel.
    size_t boundary_edge_count() const { return edges_.size(); }

private:
    struct Edge {
        Vec3 a, b;
        double weight;  // |net uses| × length
    };
    struct Node {
        BoundingBox box;
        double weight;   // Σ of the edges' weights
        uint32_t first;  // leaf: first edge; inner: the right child (the left is the next node)
        uint32_t count;  // leaf: number of edges; inner: 0
    };
    uint32_t build(uint32_t first, uint32_t count);

    std::vector<Edge> edges_;
    std::vector<Node> nodes_;
};

}  // namespace fabvdb::volume
