//! Synthetic test shapes with known answers (closed, outward-oriented,
//! 2-manifold triangle meshes unless the name says otherwise): boxes,
//! icospheres and tori, with their exact volumes for the checks.
#pragma once

#include <array>
#include <vector>

#include "core/mesh.h"

namespace fabvdb::test {

//! Axis-aligned box from `lo` to `hi`: 8 vertices, 12 triangles.
Mesh make_box(const Vec3& lo, const Vec3& hi);
//! The same box without its top face (z = hi[2]): 8 vertices, 10 triangles.
Mesh make_open_box(const Vec3& lo, const Vec3& hi);
//! Sphere of `radius` at `center`: an icosahedron subdivided `levels` times,
//! projected on the sphere (20·4^levels triangles). Its volume is a little
//! under 4/3·π·r³: use mesh_volume() for the exact figure.
Mesh make_sphere(const Vec3& center, double radius, int levels);
//! Torus around the z axis: tube radius `minor` at distance `major`.
Mesh make_torus(const Vec3& center, double major, double minor, int segments_major, int segments_minor);
//! A torus about the origin standing up in the xz plane (its axis along y), so
//! lines along z cross it four times: a part that is no double height field.
Mesh make_standing_torus(double major, double minor, int segments_major, int segments_minor);
//! The same mesh with every triangle's orientation flipped.
Mesh flipped(Mesh mesh);
//! Two meshes as one (vertex indices of `b` shifted).
Mesh merged(const Mesh& a, const Mesh& b);
//! Loose triangles given by their corners: each its own three vertices.
Mesh loose_triangles(const std::vector<std::array<Vec3, 3>>& corners);
//! The same triangles, each on its own three vertices (nothing welded).
Mesh unwelded(const Mesh& mesh);
//! Signed volume by the divergence theorem (positive for outward closed meshes).
double mesh_volume(const Mesh& mesh);
//! Signed distance from `p` to the box [lo, hi] (negative inside), by its own formula.
double box_signed_distance(const Vec3& p, const Vec3& lo, const Vec3& hi);

}  // namespace fabvdb::test
