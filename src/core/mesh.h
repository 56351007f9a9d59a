//! The triangle mesh every module passes around: vertex positions in
//! millimetres and triangles as three 0-based vertex indices. A plain value
//! type with no invariants beyond what `validate_mesh` checks; vertices that no
//! triangle uses are allowed (readers keep them, as a file stores them).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fabvdb {

using Vec3 = std::array<double, 3>;
using Triangle = std::array<uint32_t, 3>;

struct Mesh {
    std::vector<Vec3> vertices;
    std::vector<Triangle> triangles;
};

struct BoundingBox {
    Vec3 min{0, 0, 0};
    Vec3 max{0, 0, 0};
    double diagonal() const;
    //! Grows the box to hold `p`.
    void add(const Vec3& p);
};

//! Bounding box of the vertices that triangles use (all vertices if
//! `referenced_only` is false). Empty input gives a zero box.
BoundingBox bounding_box(const Mesh& mesh, bool referenced_only = true);

//! Squared Euclidean distance between two points.
double squared_distance(const Vec3& a, const Vec3& b);

//! Cross product of two edges of one triangle (b - a) x (c - a): normal to
//! it by the right-hand rule, twice its area long.
Vec3 triangle_normal(const Mesh& mesh, const Triangle& t);
//! Area of one triangle of the mesh.
double triangle_area(const Mesh& mesh, const Triangle& t);
//! Per vertex, the sum of its triangles' `triangle_normal`s (area-weighted,
//! not normalised; zero for a vertex no triangle uses).
std::vector<Vec3> area_weighted_vertex_normals(const Mesh& mesh);
//! Six times the signed volume of the tetrahedron (origin, a, b, c).
double six_signed_tetrahedron_volume(const Vec3& a, const Vec3& b, const Vec3& c);
//! Signed volume enclosed by the triangles (divergence theorem about the
//! origin): positive for closed outward shells, negative for inward ones,
//! meaningless for open ones.
double signed_volume(const Mesh& mesh);

//! Adds `from`'s vertices and triangles to `to`, its indices shifted past
//! `to`'s vertices.
void append(Mesh& to, const Mesh& from);

//! Throws Error(FABVDB_ERR_BAD_INPUT) naming `what` (usually the file) and the
//! defect when a coordinate is not finite or an index is out of range.
void validate_mesh(const Mesh& mesh, const std::string& what);

}  // namespace fabvdb
