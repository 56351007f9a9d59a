//! The generalized winding number of a triangle soup (Jacobson et al. 2013):
//! w(q) = Σ solid angle of each triangle seen from q / 4π, which is 1 inside
//! and 0 outside a closed outward-oriented surface, integer-valued across
//! overlapping shells, and varies smoothly across holes (w = 1/2 is the
//! natural surface that closes them). Evaluated hierarchically after Barill
//! et al. 2018: a bounding-volume tree over the triangles whose far nodes are
//! replaced by their expansion to second order (the area-weighted normal at
//! the area centroid and its first and second moments; error under 1e-2 at
//! β = 2, an eighth of the dipole's alone: winding_number_test), and near
//! leaves summed exactly (their solid angles as the argument of one product
//! of complex numbers, so a query takes one atan2). Where asked, triangles
//! much longer than the input's typical one (a soup of planks) are held as
//! pieces by longest-edge bisection, whose solid angles add up to theirs: a
//! query near one sums its near pieces, not every long triangle whose leaf
//! is wide. Built once (its subtrees in parallel, TBB;
//! the tree does not depend on the threads), then queried concurrently from
//! any number of threads (queries are const and allocate nothing). Costs 9
//! doubles per piece and 176 bytes per node.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::volume {

class WindingNumber {
public:
    static constexpr double default_accuracy = 2.0;
    //! Builds the tree over the mesh's triangles (zero-area ones are skipped;
    //! they contribute nothing). `accuracy` is Barill's β: a node is replaced
    //! by its expansion when q is farther than β × its radius from its
    //! centroid. `max_pieces`: over the triangle count, triangles longer than
    //! twice the median one are held as pieces, at most this many in all (for
    //! many queries near an open input's long triangles; each piece costs 9
    //! doubles and a share of a node).
    explicit WindingNumber(const Mesh& mesh, double accuracy = default_accuracy, size_t max_pieces = 0);

    //! The winding number at q, from the tree.
    double operator()(const Vec3& q) const;
    //! The winding number at q by summing every triangle exactly (for checks).
    double exact(const Vec3& q) const;

    //! The tree's far field over a box, for many queries in it: the nodes
    //! whose expansion holds at every point of the box and that lie more than
    //! box_far_reach half-diagonals from its centre, summed once at a
    //! 3 × 3 × 3 lattice over the box (interpolated per query, triquadratic:
    //! under 1e-3 of error more, winding_number_test), and the subtrees
    //! nearer than that, walked per query. One walk of the tree. None when
    //! the box is wide for the triangles around it (more subtrees near it
    //! than far: walking them would cost each query more than a plain walk).
    struct BoxField {
        Vec3 lo{0, 0, 0}, step{1, 1, 1};
        double lattice[27] = {};
        std::vector<uint32_t> near;  //!< roots of the subtrees walked per query
    };
    std::optional<BoxField> box_field(const BoundingBox& box) const;
    //! The winding number at q within the box `field` was made for.
    double operator()(const Vec3& q, const BoxField& field) const;

private:
    struct Node {
        double center[3];       // area-weighted centroid of the node's triangles
        double area_normal[3];  // Σ n_t, the triangles' area vectors (½ (b−a)×(c−a))
        double far_squared;     // (β × radius)²: beyond this distance the expansion is used
        uint32_t first;         // leaf: first triangle; inner: the right child (the left is the next node)
        uint32_t count;         // leaf: number of triangles; inner: 0 (two children)
        float first_moment[9];  // Σ n_t ⊗ (c_t − center), row i: n's component i
        float second_moment[18];  // Σ n_ti × the mean of (x − center)(x − center)ᵀ over t: per i, xx xy xz yy yz zz
    };
    //! Fills nodes_[index ..] with the subtree over order[first .. first + count)
    //! (disjoint subtrees in parallel); returns the index after its last node.
    uint32_t build(uint32_t first, uint32_t count, uint32_t index, const std::vector<double>& centroids,
                   std::vector<uint32_t>& order, double accuracy);

    //! A leaf's moments about its centre, from its triangles.
    void leaf_moments(uint32_t first, uint32_t count, const std::vector<double>& centroids,
                      const std::vector<uint32_t>& order, Node& node) const;
    //! Adds a child's moments, moved to the node's centre, to the node's.
    static void add_child_moments(const Node& child, Node& node);
    //! The far field (times 4π, as far_field) and the exact sum of the near
    //! triangles at q, over the subtrees at `roots`.
    double walk(const Vec3& q, const uint32_t* roots, size_t count) const;

    std::vector<Node> nodes_;
    std::vector<double> corners_;  // 9 doubles per triangle, in tree order
};

}  // namespace fabvdb::volume
