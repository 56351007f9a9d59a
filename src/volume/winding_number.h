//! The generalized winding number of a triangle soup (Jacobson et al. 2013):
//! w(q) = Σ solid angle of each triangle seen from q / 4π, which is 1 inside
//! and 0 outside a closed outward-oriented surface, integer-valued across
//! overlapping shells, and varies smoothly across holes (w = 1/2 is the
//! natural surface that closes them). Evaluated hierarchically after Barill
//! et al. 2018: a bounding-volume tree over the triangles whose far nodes are
//! replaced by their dipole (the area-weighted normal at the area centroid),
//! and near leaves summed exactly (their solid angles as the argument of one
//! product of complex numbers, so a query takes one atan2). Built once (its
//! subtrees in parallel, TBB; the tree does not depend on the threads), then
//! queried concurrently from any number of threads (queries are const and
//! allocate nothing).
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

class WindingNumber {
public:
    //! Builds the tree over the mesh's triangles (zero-area ones are skipped;
    //! they contribute nothing). `accuracy` is Barill's β: a node is replaced
    //! by its dipole when q is farther than β × its radius from its centroid.
    explicit WindingNumber(const Mesh& mesh, double accuracy = 2.0);

    //! The winding number at q, from the tree.
    double operator()(const Vec3& q) const;
    //! The winding number at q by summing every triangle exactly (for checks).
    double exact(const Vec3& q) const;

private:
    struct Node {
        double center[3];       // area-weighted centroid of the node's triangles
        double area_normal[3];  // Σ of the triangles' area vectors (½ (b−a)×(c−a))
        double far_squared;     // (β × radius)²: beyond this distance the dipole is used
        uint32_t first;         // leaf: first triangle; inner: the right child (the left is the next node)
        uint32_t count;         // leaf: number of triangles; inner: 0 (two children)
    };
    //! Fills nodes_[index ..] with the subtree over order[first .. first + count)
    //! (disjoint subtrees in parallel); returns the index after its last node.
    uint32_t build(uint32_t first, uint32_t count, uint32_t index, const std::vector<double>& centroids,
                   std::vector<uint32_t>& order, double accuracy);

    std::vector<Node> nodes_;
    std::vector<double> corners_;  // 9 doubles per triangle, in tree order
};

}  // namespace fabvdb::volume
