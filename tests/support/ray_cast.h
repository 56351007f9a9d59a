//! Independent geometric checks for tests (no code shared with the library):
//! lines cast through a triangle mesh (own Möller–Trumbore intersection over a
//! 2D bin grid perpendicular to the cast direction), point-in-solid by ray
//! parity, and the height-field test "each line parallel to d crosses the
//! solid at most twice" on jittered lines, so no line runs along an edge.
#pragma once

#include <cstddef>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::test {

class LineCaster {
public:
    //! `direction`: any non-zero vector; lines are cast parallel to it.
    LineCaster(const Mesh& mesh, const Vec3& direction);
    //! Parameters t (point + t·direction, direction normalised) where the whole
    //! line through `point` crosses a triangle, sorted.
    std::vector<double> crossings(const Vec3& point) const;
    //! Inside by parity of the crossings with t > 0.
    bool inside(const Vec3& point) const;

private:
    std::vector<double> crossings_once(const Vec3& point, bool& near_edge) const;
    const Mesh& mesh_;
    Vec3 u_, v_, w_;
    double u0_ = 0, v0_ = 0, cell_ = 1;
    int nu_ = 1, nv_ = 1;
    std::vector<std::vector<uint32_t>> bins_;
};

struct HeightFieldCheck {
    size_t lines = 0;           //!< lines cast through the solid's shadow
    size_t lines_over_two = 0;  //!< lines that crossed it more than twice
    size_t max_crossings = 0;
    size_t odd_lines = 0;       //!< lines with an odd count (a hole in the mesh)
};

//! Casts about samples_per_side² jittered lines parallel to `direction` over
//! the mesh's shadow.
HeightFieldCheck check_double_height_field(const Mesh& mesh, const Vec3& direction, int samples_per_side);

//! Each directed edge used once and its reverse once, and every vertex's
//! triangle fan a single cycle: closed, 2-manifold and consistently oriented.
bool closed_two_manifold(const Mesh& mesh);

//! CGAL's exact self-intersection test (Polygon_mesh_processing).
bool self_intersects(const Mesh& mesh);

//! The mesh as a binary STL file stores it: every coordinate rounded to float.
Mesh stored_as_float(Mesh mesh);

//! Triangles whose corners coincide or line up (cross product exactly zero).
size_t degenerate_triangle_count(const Mesh& mesh);

//! Volume of the set inside every mesh of `solids`, by ray parity on a
//! regular grid of `samples_per_side`³ points over `box_lo`..`box_hi`.
double sampled_common_volume(const std::vector<const Mesh*>& solids, const Vec3& box_lo, const Vec3& box_hi,
                             int samples_per_side);

}  // namespace fabvdb::test
